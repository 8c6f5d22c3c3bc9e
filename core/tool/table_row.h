// One line of a LinuxCNC tool table (`dexmill run --tools FILE`; the format
// is platform/format/tool_table.h's): its words read into a tool, or the
// reason it is refused with the column, and the messages both say, for the
// host's reader (platform/format/tool_table.cpp) and the embedding API
// (display/api/dexmill.h dm_tool_table_parse) alike. No heap, no stdio.
#ifndef DEXMILL_CORE_TOOL_TABLE_ROW_H
#define DEXMILL_CORE_TOOL_TABLE_ROW_H

#include <stddef.h>
#include <stdint.h>

#include "core/tool/spec.h"
#include "core/tool/tool.h"

namespace dexmill {

// The longest length offset a row may give (the interpreter's coordinate
// bound, core/interp/interp.h kGcodeMaxCoordNm: 10 m).
constexpr int64_t kToolRowMaxOffsetNm = 10000000000;

enum class ToolRowError : uint8_t {
  kOk = 0,
  kUnknownWord,   // a letter that is not a table word
  kNeedsNumber,   // a word without its number
  kBadNumber,     // T not a whole number 0 .. 1e9
  kBadPocket,     // P the same
  kBadDiameter,   // D neither 0 nor 0.001 .. 1000 mm
  kBadOffset,     // Z beyond +-10 m
  kNoNumber,      // D without T
  kNoDiameter,    // T without D
  kDuplicate,     // a T defined before
  kBadShape,      // a shape word in the comment that does not parse
  kCornerRadius,  // a bull nose's corner radius over D/2
  kOutOfRange,    // the tool fails tool_check
};

struct ToolRow {
  bool empty = true;  // a blank line, or one with only a comment: no tool
  int32_t number = 0;
  int32_t pocket = 0;
  Tool tool;
  int64_t length_offset_nm = 0;  // Z, for G43
  bool flat_guess = false;       // the comment names a shape it does not give: simulated flat (a warning)
  uint32_t t_col = 1;            // the T word's column
};

// Why a row is refused, and what its message quotes.
struct ToolRowFault {
  ToolRowError error = ToolRowError::kOk;
  uint32_t col = 1;           // 1-based
  char word = 0;              // kUnknownWord: the letter as written; kNeedsNumber: upper case
  int32_t number = 0;         // the row's T
  const char* shape = nullptr;  // kBadShape: the word (in the line's text) and why
  size_t shape_n = 0;
  ToolSpecError spec = ToolSpecError::kOk;
  uint32_t other_line = 0;    // kDuplicate: the line of the first definition
};

// The line an earlier row defined T `number` on (0: none), asked of the caller.
typedef uint32_t (*ToolRowDefined)(const void* ctx, int32_t number);

// Reads line s[0, n) (without its line end); lengths in inch when `inch`;
// `defined` (with ctx) says which T came before. kOk: *out is the row
// (empty for no tool); else *why says what and where.
ToolRowError tool_table_row(const char* s, size_t n, bool inch, ToolRowDefined defined, const void* ctx, ToolRow* out,
                            ToolRowFault* why);

// The fault's message, without the place ("unknown word 'k' in the tool
// table (...)"), NUL terminated in buf[0, n); the length written.
size_t tool_row_message(const ToolRowFault& f, char* buf, size_t n);
// The warning of a flat_guess row, without the place ("T3 is simulated as
// a flat end mill; ...").
size_t tool_row_warning(const ToolRow& row, char* buf, size_t n);

}  // namespace dexmill

#endif
