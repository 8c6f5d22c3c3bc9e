// Load limits as findings (`dexmill run --check load`): a move whose
// thickest chip is over its material's largest chip per tooth
// (MaterialProcess::max_chip_nm), or whose power is over the spindle's
// (`--spindle-power W`), at its line. The first kLoadKept findings are
// kept, every one counted. Integer only, no heap: the panel's too.
#ifndef DEXMILL_CORE_ENGAGE_LOAD_WATCH_H
#define DEXMILL_CORE_ENGAGE_LOAD_WATCH_H

#include <stdint.h>

#include "core/engage/engage_meter.h"

namespace dexmill {

enum class LoadRule : uint8_t { kChip = 0, kPower = 1 };
const char* load_rule_name(LoadRule r);  // "chip", "power"

struct LoadFinding {
  uint32_t line = 0;
  LoadRule rule = LoadRule::kChip;
  uint8_t material = 0;  // kChip: whose limit
  int64_t value = 0;     // kChip: nm; kPower: mW
  int64_t limit = 0;
};

constexpr int32_t kLoadKept = 100;

struct LoadWatch {
  int64_t spindle_power_mw = 0;  // 0: no power limit
  uint64_t total = 0;
  int32_t nkept = 0;
  LoadFinding kept[kLoadKept];
};

// Checks m against its material's chip limit (max_chip_nm, 0: none) and
// the spindle's power; true when it broke either.
bool load_watch_check(LoadWatch* w, const EngageMove& m, int64_t max_chip_nm);

}  // namespace dexmill

#endif
