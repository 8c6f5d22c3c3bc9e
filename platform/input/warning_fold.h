// Repeated warnings folded into one line: a program missing one spindle
// speed (or one feed) draws the same warning on every line after it, and 64
// identical lines hide everything else. A warning is held until something
// else has to be printed; each held message (by file and text) is printed
// once, in the order it first came, and when it came more than once with
// how often and its last line:
//   FILE:LINE:COL: warning: MESSAGE (64 times, lines 51 to 120)
// An error printed in between ends the fold (flush() first), so that what
// is printed keeps the program's order; repeats after it begin a new one.
// At most kHeld distinct messages are held (beyond, they are printed and a
// new fold begins): the memory stays bounded whatever the program.
#ifndef DEXMILL_PLATFORM_INPUT_WARNING_FOLD_H
#define DEXMILL_PLATFORM_INPUT_WARNING_FOLD_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

namespace dexmill {

// One folded warning: where it first came, how often, its last line.
struct FoldedWarning {
  std::string file, message;
  uint32_t line = 0, column = 0;
  uint32_t last_line = 0;
  uint64_t count = 0;
};

// "FILE:LINE:COL: warning: MESSAGE", with " (N times, lines A to B)" (or
// " (N times, all on line A)") when it came more than once.
std::string folded_warning_text(const FoldedWarning& w);

// A list of folded warnings: add() counts a repeat into the entry of its
// file and message, else appends one (while there are fewer than `most`).
class WarningList {
 public:
  explicit WarningList(std::size_t most) : most_(most) {}
  // False when the warning is new and the list is full (it is not kept).
  bool add(const std::string& file, uint32_t line, uint32_t column, const std::string& message);
  const std::vector<FoldedWarning>& entries() const { return entries_; }
  bool full() const { return entries_.size() >= most_; }
  void clear();

 private:
  std::size_t most_;
  std::vector<FoldedWarning> entries_;
  std::unordered_map<std::string, std::size_t> index_;  // file NUL message -> entries_
};

class WarningFold {
 public:
  static constexpr std::size_t kHeld = 256;
  explicit WarningFold(std::FILE* out = stderr) : out_(out) {}
  WarningFold(const WarningFold&) = delete;
  WarningFold& operator=(const WarningFold&) = delete;
  ~WarningFold() { flush(); }
  void add(const std::string& file, uint32_t line, uint32_t column, const std::string& message);
  // Prints what is held and forgets it.
  void flush();

 private:
  std::FILE* out_;
  WarningList held_{kHeld};
};

}  // namespace dexmill

#endif
