// RS274/NGC values computed as LinuxCNC 2.9 reads them: a real
// value is a number, a parameter (#5, ##1, #<name>), a [bracketed
// expression] or a unary function (ABS ACOS ASIN ATAN[y]/[x] COS EXISTS
// EXP FIX FUP LN ROUND SIN SQRT TAN, degrees as LinuxCNC), optionally
// signed. Binary operators with LinuxCNC's precedence and left-to-right
// evaluation at equal precedence (core/gcode/gvalue.h). Blanks are allowed
// anywhere; words are case-insensitive.
//
// Nesting: as deep as a line holds, as LinuxCNC (its rs274 has no limit but
// its line: it ran 123 nested brackets, the most its 252-byte command
// holds, and 240 chained '#'). A level is a bracket (a function's too), a
// '#' before a value, or a sign before a computed value; each reads at
// least one byte, so a line of kGcodeMaxLine bytes (core/gcode/block.h)
// never reaches kExprDepthMax, which guards callers with longer text
// (kExprTooDeep where the level past it opens, never a deeper recursion).
//
// Stack: the reader recurses once a level, its frames kept small (names
// and numbers read outside the recursion, a bracket's operators in
// kExprPendingMax slots), and a bracket opens only with a ']' left for it
// in the text (an unclosed run of '[' is refused before it recurses). On
// x86-64 (g++ -O2 -fstack-usage) a bracket level takes 304 bytes (value 80
// + bracket_body 224), a '#' or a sign 80, a function 400 for its 5 bytes
// or more: a line of 256 bytes nests at most 128 brackets, 39 KB; on a
// Cortex-M4 (arm-none-eabi-g++ -Os) a bracket level takes 224 bytes (value
// 56 + bracketed 168), 28 KB for the deepest line.
#ifndef DEXMILL_CORE_GCODE_EXPR_H
#define DEXMILL_CORE_GCODE_EXPR_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/gcode/gvalue.h"
#include "core/gcode/params.h"

namespace dexmill {

constexpr int kExprDepthMax = 256;
static_assert(kExprDepthMax >= static_cast<int>(kGcodeMaxLine), "every nesting a line holds");
// Operators waiting in one bracket: one per precedence level (gvalue.h).
constexpr int kExprPendingMax = 5;

// The real value starting at s[*pos] (blanks first skipped); *pos moves
// past it. Errors fill d->code, d->col and d->word.
GcodeError expr_read_value(const char* s, size_t n, size_t* pos, const ParamStore& p, GValue* out, GcodeDiag* d);

// True when a real value that is not a plain number starts at s[pos] (after
// blanks): '[', '#', a function name, or a sign before one of those.
bool expr_starts_computed(const char* s, size_t n, size_t pos);

// The target of an assignment, `#n` or `#<name>` at s[*pos] == '#'; the
// number of ##k is computed with the values before the line.
struct ParamRef {
  bool named;
  int64_t number;
  char name[kParamNameMax + 1];  // folded
};
GcodeError expr_read_param_ref(const char* s, size_t n, size_t* pos, const ParamStore& p, ParamRef* out, GcodeDiag* d);

}  // namespace dexmill

#endif
