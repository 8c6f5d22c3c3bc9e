// core/engage/load_watch.h: chip and power limits, each at its line.
#include "core/engage/load_watch.h"

namespace dexmill {

const char* load_rule_name(LoadRule r) { return r == LoadRule::kChip ? "chip" : "power"; }

namespace {

void keep(LoadWatch* w, const EngageMove& m, LoadRule rule, int64_t value, int64_t limit) {
  ++w->total;
  if (w->nkept >= kLoadKept) return;
  LoadFinding& f = w->kept[w->nkept++];
  f.line = m.line;
  f.rule = rule;
  f.material = m.material;
  f.value = value;
  f.limit = limit;
}

}  // namespace

bool load_watch_check(LoadWatch* w, const EngageMove& m, int64_t max_chip_nm) {
  bool broke = false;
  if (max_chip_nm > 0 && m.chip.max_nm > max_chip_nm) {
    keep(w, m, LoadRule::kChip, m.chip.max_nm, max_chip_nm);
    broke = true;
  }
  if (w->spindle_power_mw > 0 && m.has_load && m.power_mw > w->spindle_power_mw) {
    keep(w, m, LoadRule::kPower, m.power_mw, w->spindle_power_mw);
    broke = true;
  }
  return broke;
}

}  // namespace dexmill
