// Repeated warnings folded; see warning_fold.h.
#include "platform/input/warning_fold.h"

namespace dexmill {

std::string folded_warning_text(const FoldedWarning& w) {
  std::string s = w.file + ":" + std::to_string(w.line) + ":" + std::to_string(w.column) + ": warning: " + w.message;
  if (w.count > 1) {
    s += " (" + std::to_string(w.count) + " times, ";
    s += w.last_line == w.line ? "all on line " + std::to_string(w.line)
                               : "lines " + std::to_string(w.line) + " to " + std::to_string(w.last_line);
    s += ")";
  }
  return s;
}

bool WarningList::add(const std::string& file, uint32_t line, uint32_t column, const std::string& message) {
  std::string key = file;
  key.push_back('\0');
  key += message;
  const auto it = index_.find(key);
  if (it != index_.end()) {
    FoldedWarning& w = entries_[it->second];
    ++w.count;
    w.last_line = line;
    return true;
  }
  if (full()) return false;
  index_.emplace(std::move(key), entries_.size());
  entries_.push_back(FoldedWarning{file, message, line, column, line, 1});
  return true;
}

void WarningList::clear() {
  entries_.clear();
  index_.clear();
}

void WarningFold::add(const std::string& file, uint32_t line, uint32_t column, const std::string& message) {
  if (held_.add(file, line, column, message)) return;
  flush();
  (void)held_.add(file, line, column, message);
}

void WarningFold::flush() {
  for (const FoldedWarning& w : held_.entries()) std::fprintf(out_, "%s\n", folded_warning_text(w).c_str());
  held_.clear();
}

}  // namespace dexmill
