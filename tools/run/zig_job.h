// `dexmill zig`'s job, shared with `dexmill run --demo` (the paper's loop,
// tools/README.md): a
// zig-milling program for the design a job (JobOptions) names (a file, or a
// built-in part of core/design/builtin.h) on the grid `run` would use for
// its stock, pitch or grid and tool.
#ifndef DEXMILL_TOOLS_RUN_ZIG_JOB_H
#define DEXMILL_TOOLS_RUN_ZIG_JOB_H

#include <string>

#include "core/design/builtin.h"
#include "tools/run/run_options.h"
#include "tools/run/run_stock.h"
#include "tools/cam/zig_program.h"

namespace dexmill {
namespace cli {

struct ZigJob {
  ZigProgramOptions prog;
  int64_t stepover_nm = 0, step_nm = 0;  // 0: one pitch
  int64_t safe_z_nm = 0;
  bool have_safe = false;                // else the stock's top + 5 mm
};

// Sets o up for built-in part b: its block as the stock (unless o gives a
// --stock box: the part stays at its place, X and Y from 0, its top at Z0),
// its pitch (unless o gives --pitch or --grid), its ball (unless
// tool_given), its material (unless o gives one), and b as the design.
// kExitOk, or kExitUsage (printed) for a --stock STL blank, which the zig
// path cannot start from.
int builtin_setup(const BuiltinDesign& b, bool tool_given, JobOptions* o);

// Feeds and spindle speed within every limit of o's material preset (paper
// §2.6: the process rules then pass): the lowest max feed (at most the
// feed already set), a third of it to plunge, a speed inside every range.
// Nothing for a material file or none.
void zig_fit_to_material(const JobOptions& o, ZigProgramOptions* p);

// The program for o's design, stock, grid and tool into *text; the grid
// used into *plan. Returns an exit status (the message printed).
int zig_generate(const JobOptions& o, ZigJob* z, std::string* text, ZigProgramStats* st, GridPlan* plan);

// "dexmill zig: grid ..., N stripes, N positions, N moves, T s" on stderr.
void zig_print_stats(const GridPlan& plan, const ZigProgramStats& st);

}  // namespace cli
}  // namespace dexmill

#endif
