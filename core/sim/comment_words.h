// The words of a stock comment, read as LinuxCNC's preview reads its
// (WORKPIECE,...) comments and as TNC posts write BLK FORM: letters in any
// case, values within the interpreter's range (core/sim/workpiece_comment.h,
// core/sim/blk_form_comment.h).
#ifndef DEXMILL_CORE_SIM_COMMENT_WORDS_H
#define DEXMILL_CORE_SIM_COMMENT_WORDS_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

constexpr int64_t kCommentMaxNm = 10LL * 1000 * 1000000;  // 10 m, the interpreter's range

inline char comment_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// Whether s[at, n) starts with word (upper case), case-insensitively.
inline bool comment_starts(const char* s, size_t n, size_t at, const char* word) {
  for (size_t k = 0; word[k]; ++k)
    if (at + k >= n || comment_upper(s[at + k]) != word[k]) return false;
  return true;
}

}  // namespace dexmill

#endif
