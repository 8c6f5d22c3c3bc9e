// Tool specifications as text, the `--tool` syntax of ../shared/CLI.md:
//
//   ball:D   flat:D   bull:D:R   vbit:D:ANGLE      each optionally ,len=L
//
// D (diameter), R (corner radius) and L (flute length) in millimetres,
// ANGLE (the V-bit's included angle) in degrees; decimals as G-code writes
// them (read exactly, core/math/decimal.h). Parsing is integer-only and uses no
// heap, so a controller's panel can take the same text.
//
// The tool's stick-out (Tool::length_nm, the top of the shaft above the tip)
// is not part of the text: it is max(L, the profile's full height, 2 D,
// 30 mm), long enough that the shaft, not the end of the model, meets any
// material the holder would.
#ifndef DEXMILL_CORE_TOOL_SPEC_H
#define DEXMILL_CORE_TOOL_SPEC_H

#include <stddef.h>
#include <stdint.h>

#include "core/tool/tool.h"

namespace dexmill {

enum class ToolSpecError : uint8_t {
  kOk = 0,
  kUnknownShape = 1,   // not ball, flat, bull or vbit
  kBadNumber = 2,      // a field is not a decimal number
  kFieldCount = 3,     // too few or too many ':' fields for the shape
  kBadOption = 4,      // something after ',' other than len=L
  kOutOfRange = 5,     // fails tool_check (e.g. R > D/2, angle >= 180)
};

// Message for an error; never null.
const char* tool_spec_message(ToolSpecError e);

// Parses s[0, n). On success *out is a tool that passes tool_check.
ToolSpecError tool_spec_parse(const char* s, size_t n, Tool* out);

// The stick-out rule above, for a tool whose other fields are set.
int64_t tool_default_length_nm(const Tool& t);

// Writes the canonical text of a tool ("ball:6", "bull:10:1.5,len=25"),
// NUL-terminated and truncated to n - 1 bytes. Returns the length written.
size_t tool_spec_format(const Tool& t, char* buf, size_t n);

}  // namespace dexmill

#endif
