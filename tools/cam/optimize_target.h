// `dexmill optimize --target`: feeds set by the measured load
// (core/engage/engage_target.h), raised in light cuts and lowered in heavy
// ones. The option's forms: `--target chip-load` (each material's
// max_chip), `--target chip-load=MM`, `--target power=W` or `--target
// power W`, `--target mrr=MM3/MIN` or `--target mrr MM3/MIN`; with
// `--min-feed MM/MIN` (10 unless given) and `--max-feed MM/MIN` (the
// machine's; without it, the material's max_feed).
#ifndef DEXMILL_TOOLS_CAM_OPTIMIZE_TARGET_H
#define DEXMILL_TOOLS_CAM_OPTIMIZE_TARGET_H

#include <string>
#include <vector>

#include "core/engage/engage_target.h"

namespace dexmill {
namespace cli {

struct OptimizeTarget {
  bool given = false;
  EngageTarget target;
  std::string text;  // as the summary says it: "chip-load 0.05 mm", "power 1500 W"
};

// The target from the option's value; kExitUsage (said) when it is none.
int parse_target(const char* v, OptimizeTarget* t);
// The command line with `--target power W` and `--target mrr Q` joined
// into one word each (`power=W`): the option parser takes one value an option.
std::vector<std::string> join_target_words(int argc, char** argv);

}  // namespace cli
}  // namespace dexmill

#endif
