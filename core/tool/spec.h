// Tool specifications as text, the `--tool` syntax (tools/README.md):
//
//   ball:D   flat:D   bull:D:R   vbit:D:ANGLE      then any of, after commas:
//     len=L         flute length: above it the shank must not touch material
//     stick=S       stick-out: the tip to the holder's face
//     shank=D       the shank's diameter (default: the cutting diameter)
//     holder=DxH[,DxH...]   the holder above the stick-out, bottom piece
//                   first: a cylinder of diameter D and height H, or a cone
//                   D1-D2xH from D1 at its bottom to D2 at its top; at most
//                   kHolderSegmentsMax pieces
//     nocentre      (or nocenter) the tool cannot plunge straight down
//     flutes=N      its cutting edges (1 to kToolFlutesMax), for the chip
//                   per tooth (core/engage/engage.h); 2 when not given
//
// Lengths in millimetres, ANGLE (the V-bit's included angle) in degrees;
// decimals as G-code writes them (read exactly, core/math/decimal.h).
// Parsing is integer-only and uses no heap, so a controller's panel can take
// the same text.
//
// Without stick=, the stick-out (Tool::length_nm, the top of the shaft above
// the tip) is max(L, the profile's full height, 2 D, 30 mm), long enough that
// the shaft, not the end of the model, meets any material the holder would.
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
  kBadOption = 4,      // something after ',' that is not an option above
  kOutOfRange = 5,     // outside the ranges of core/tool/tool.h (tool_check): e.g. R > D/2, angle under 1 degree
  kBadHolder = 6,      // a holder piece that is not DxH or D1-D2xH, or too many
};

// Message for an error; never null.
const char* tool_spec_message(ToolSpecError e);

// Parses s[0, n). On success *out is a tool that passes tool_check.
ToolSpecError tool_spec_parse(const char* s, size_t n, Tool* out);

// A tool whose fields are set (the shape, the sizes, the options above)
// made whole as a spec makes it: range checks, the stick-out rule, then
// tool_check. kOk or kOutOfRange (t then undefined).
ToolSpecError tool_spec_complete(Tool* t);

// The stick-out: stick_out_nm when given, else the rule above, for a tool
// whose other fields are set.
int64_t tool_default_length_nm(const Tool& t);

// Room for any tool's canonical text with its NUL.
constexpr size_t kToolSpecTextMax = 192;

// Writes the canonical text of a tool ("ball:6", "bull:10:1.5,len=25",
// "flat:6,len=20,stick=35,holder=20x10,30-40x15"),
// NUL-terminated and truncated to n - 1 bytes. Returns the length written.
size_t tool_spec_format(const Tool& t, char* buf, size_t n);

}  // namespace dexmill

#endif
