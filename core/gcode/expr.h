// RS274/NGC values computed as LinuxCNC 2.9 reads them (issue 21): a real
// value is a number, a parameter (#5, ##1, #<name>), a [bracketed
// expression] or a unary function (ABS ACOS ASIN ATAN[y]/[x] COS EXISTS
// EXP FIX FUP LN ROUND SIN SQRT TAN, degrees as LinuxCNC), optionally
// signed. Binary operators with LinuxCNC's precedence and left-to-right
// evaluation at equal precedence (core/gcode/gvalue.h). Blanks are allowed
// anywhere; words are case-insensitive. Nesting deeper than kExprDepthMax
// is an error, never a stack overflow.
#ifndef DEXMILL_CORE_GCODE_EXPR_H
#define DEXMILL_CORE_GCODE_EXPR_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/error.h"
#include "core/gcode/gvalue.h"
#include "core/gcode/params.h"

namespace dexmill {

constexpr int kExprDepthMax = 16;

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
