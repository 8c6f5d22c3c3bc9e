// The memory of o-word control flow: LinuxCNC 2.9's offset table,
// call stack and skipping state, in fixed capacities (caller memory, like
// ParamStore; InterpOptions::control). About 11 KB.
//
// LinuxCNC's model, kept here: a label's first statement is recorded with
// its line's position (sub, do, while, repeat, if); loops and calls go back
// by seeking to that position and reading the line again; false conditions,
// breaks and definitions are passed over by reading on without executing
// ("skipping") until a statement with the same label. Labels of sub, endsub,
// call and return are global; the others belong to the subroutine they are
// in (LinuxCNC names them "sub#label").
#ifndef DEXMILL_CORE_INTERP_OWORD_STORE_H
#define DEXMILL_CORE_INTERP_OWORD_STORE_H

#include <stdint.h>

#include "core/gcode/gvalue.h"
#include "core/gcode/oword.h"
#include "core/gcode/source.h"

namespace dexmill {

// Labels a program may record (LinuxCNC: unlimited; the corpus's most is 14).
constexpr int32_t kOwordLabelsMax = 128;
// Call levels, the main program's included: calls nest 9 deep
// (LinuxCNC's INTERP_SUB_ROUTINE_LEVELS).
constexpr int32_t kOwordLevels = 10;
// Blocks a program may run once it has looped or called (--max-blocks).
constexpr uint64_t kDefaultMaxBlocks = 10000000;

// Scopes of a label (OwordLabel::scope): a global (sub, endsub, call,
// return), one of the main program, or >= 0: the sub whose label it is.
constexpr int16_t kOwordGlobal = -1;
constexpr int16_t kOwordMain = -2;

struct OwordLabel {
  char name[kOwordNameMax + 1];
  int16_t scope;
  OwordOp op;           // the statement that recorded it
  SourcePos at;         // its line
  int64_t repeat_left;  // a repeat's passes still to run; -1 when none is counting
};

struct OwordFrame {
  int16_t sub;            // the label of the sub running (-1 until a forward call finds it)
  bool fanuc;             // called by M98 (returns by M99; #1..#30 are not the caller's own)
  SourcePos back;         // where its call returns: the line after the call
  int64_t saved_e9[kOwordArgsMax];  // the caller's #1..#30
};

struct OwordStore {
  OwordLabel labels[kOwordLabelsMax];
  int32_t nlabels;
  OwordFrame frames[kOwordLevels];  // frames[k] holds what level k returns to (k >= 1)
  uint8_t level;                    // the call level (0: the main program)
  int64_t m98_left[kOwordLevels];   // an M98 L loop at this level: calls still to make (-1: none)
  // Skipping: to the next statement with this label (-1: none), or, for a
  // call of a sub not yet met, to its `sub` line (skip_sub[0] != 0).
  int16_t skip_label;
  char skip_sub[kOwordNameMax + 1];
  uint32_t skip_from_line;          // the statement that began the skip
  int16_t defining;                 // the sub whose definition is passed over, -1
  // LinuxCNC's flags (one each, not per statement, as in LinuxCNC).
  bool executed_if, doing_break, doing_continue;
  GValue return_value;              // #<_value>
  bool value_returned;              // #<_value_returned>
  uint64_t blocks;                  // lines run
  bool looped;                      // a loop or call went back: the block limit applies
  uint32_t loop_line;               // the loop or call that last went back
};

// The start-of-program state (no label, level 0, not skipping).
void oword_store_clear(OwordStore* c);

}  // namespace dexmill

#endif
