// O-word lines (LinuxCNC 2.9's control flow, read as its read_o
// reads them). A line whose first word (after blanks, a block-delete '/'
// and an N word) is O holds one control statement and nothing else but
// comments:
//
//   O<label> sub | endsub [value] | return [value] | call [arg]...
//            | do | while [cond] | endwhile | repeat [count] | endrepeat
//            | if [cond] | elseif [cond] | else | endif | break | continue
//   O<digits> alone: a Fanuc-style program number (nothing to do), or the
//            start of a subprogram M98 P<digits> calls, which M99 ends
//
// A label is a number (`o100`, also computed: `o[#1]`, `o#2`) or a name
// (`o<name>`, folded like parameter names: lower case, blanks dropped).
// Reading is in two steps, because LinuxCNC evaluates a statement's
// expressions only when it is not skipping past it: oword_read_head reads
// the label and the statement; oword_read_rest the values after it.
#ifndef DEXMILL_CORE_GCODE_OWORD_H
#define DEXMILL_CORE_GCODE_OWORD_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/error.h"
#include "core/gcode/gvalue.h"
#include "core/gcode/params.h"

namespace dexmill {

// Longest label name (as LinuxCNC reads it, folded), like parameter names.
constexpr int kOwordNameMax = kParamNameMax;
// Arguments of a call: #1..#30 (LinuxCNC's INTERP_SUB_PARAMS).
constexpr int kOwordArgsMax = 30;

enum class OwordOp : uint8_t {
  kNone = 0,  // not an o-word line
  kProgramNumber,
  kSub,
  kEndsub,
  kCall,
  kReturn,
  kDo,
  kWhile,
  kEndwhile,
  kRepeat,
  kEndrepeat,
  kIf,
  kElseif,
  kElse,
  kEndif,
  kBreak,
  kContinue,
  kM98,  // M98 P<n> [L<count>]: a Fanuc-style call of program O<n>
  kM99,  // M99: its return (in the main program: LinuxCNC starts it again)
};

struct OwordHead {
  OwordOp op;
  char name[kOwordNameMax + 1];  // the label, folded ("100", "flowsnake"); M98: P; M99: none
  uint16_t col;                  // 1-based column of the O (or the M)
  uint16_t rest;                 // 0-based offset just after the statement word
  int64_t m98_count;             // M98: L, the number of calls (1 without L)
};

// True when the line is an o-word line (its first word is O, or M98 or
// M99: LinuxCNC reads Fanuc-style calls as o-words); cheap, reads no value:
// what the interpreter asks of every line it skips.
bool oword_line(const char* s, size_t n);
// The same, told at the first byte for the lines that start with a G or
// an X word (most of them): what the interpreter asks of every line.
inline bool oword_line_fast(const char* s, size_t n) {
  if (n == 0) return false;
  switch (s[0]) {
    case 'O': case 'o': case 'M': case 'm': case 'N': case 'n': case '/': case ' ': case '\t': case '\r':
      return oword_line(s, n);
    default:
      return false;
  }
}

// The label and the statement of an o-word line. A computed label reads
// parameters (p). Errors: a bad label, an unknown statement.
[[nodiscard]] GcodeError oword_read_head(const char* s, size_t n, const ParamStore& p, OwordHead* h, GcodeDiag* d);

// What follows the statement: the bracketed values (a condition, a count, a
// return value: at most one; a call: up to kOwordArgsMax), then only
// comments. *count gets how many values were read; values[] has room for
// kOwordArgsMax. A condition, a repeat count and an elseif need exactly
// one (LinuxCNC: "Left bracket missing after 'while'").
[[nodiscard]] GcodeError oword_read_rest(const char* s, size_t n, const OwordHead& h, const ParamStore& p,
                                         GValue* values, int* count, GcodeDiag* d);

// "while", "endsub": the statement's word, for messages.
const char* oword_op_name(OwordOp op);

}  // namespace dexmill

#endif
