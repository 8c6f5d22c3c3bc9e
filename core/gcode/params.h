// RS274/NGC parameters (as LinuxCNC 2.9 holds them): numbered
// #1..#5602 and named #<name> (names lower case, blanks dropped; a name
// beginning with '_' is global, others belong to the call level that set
// them). Fixed capacities, no heap: kParamsNamedMax names of at most
// kParamNameMax characters, running out is an error naming the limit.
//
// The interpreter's own values (the position #5420-#5428, the coordinate
// systems #5221..., the tool #5400, the predefined #<_x>, #<_metric>...) are
// read through `system`, never stored here; writing one of them is an
// error (LinuxCNC's persistent #5161-#5390 may be written by a program
// there; dexmill keeps them as the interpreter's state).
#ifndef DEXMILL_CORE_GCODE_PARAMS_H
#define DEXMILL_CORE_GCODE_PARAMS_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/error.h"
#include "core/gcode/gvalue.h"

namespace dexmill {

constexpr int32_t kParamsNumbered = 5602;
constexpr int32_t kParamsNamedMax = 200;
constexpr int32_t kParamNameMax = 31;

// The interpreter's values: true with *out set when it owns parameter n
// (name null) or the named one (n 0).
struct ParamSystem {
  bool (*read)(const void* ctx, int32_t n, const char* name, GValue* out) = nullptr;
  const void* ctx = nullptr;
};

struct ParamStore {
  int64_t numbered_e9[kParamsNumbered + 1];  // [0] unused; 0 until set
  struct Named {
    char name[kParamNameMax + 1];
    int64_t e9;
    uint8_t level;  // call level that set it (0 for globals)
  };
  Named named[kParamsNamedMax];
  int32_t nnamed;
  uint8_t level;     // the current call level (0: the main program)
  ParamSystem system;
};

// Every numbered parameter 0, no named one, level 0 (system kept).
void params_clear(ParamStore* p);

// Forgets the named locals of call level `level` (a subroutine returns).
void params_drop_level(ParamStore* p, uint8_t level);

// #n: kParamNumberRange outside 1..5602.
GcodeError param_get(const ParamStore& p, int64_t n, GValue* out);
GcodeError param_set(ParamStore* p, int64_t n, GValue v);
// #<name> (name as written; folded here). Reading an unset name is
// kParamUnknownName (LinuxCNC: "named parameter not defined"); *exists
// (when not null) says whether it is set instead of failing.
GcodeError param_get_named(const ParamStore& p, const char* name, size_t len, GValue* out, bool* exists);
GcodeError param_set_named(ParamStore* p, const char* name, size_t len, GValue v);

// The folded form of a name (lower case, no blanks) into out[kParamNameMax
// + 1]; false when it is empty or too long.
bool param_fold_name(const char* name, size_t len, char* out);

}  // namespace dexmill

#endif
