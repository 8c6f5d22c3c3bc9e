// A program in memory; see source.h.
#include "core/gcode/source.h"

namespace dexmill {

bool MemorySource::next(const char** text, size_t* len, uint32_t* line) {
  if (pos_ >= n_) return false;
  size_t e = pos_;
  while (e < n_ && s_[e] != '\n') ++e;
  start_ = pos_;
  *text = s_ + pos_;
  *len = e - pos_;
  *line = ++line_;
  pos_ = e < n_ ? e + 1 : e;
  return true;
}

bool MemorySource::seek(const SourcePos& p) {
  if (p.file != 0 || p.offset > n_ || p.line == 0) return false;
  pos_ = static_cast<size_t>(p.offset);
  line_ = p.line - 1;
  return true;
}

}  // namespace dexmill
