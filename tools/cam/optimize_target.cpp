// tools/cam/optimize_target.h: the --target option's forms.
#include "tools/cam/optimize_target.h"

#include <cstring>

#include "core/math/fixed.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_values.h"

namespace dexmill {
namespace cli {

int parse_target(const char* v, OptimizeTarget* t) {
  const char* eq = std::strchr(v, '=');
  const std::string kind(v, eq ? static_cast<size_t>(eq - v) : std::strlen(v));
  const char* value = eq ? eq + 1 : nullptr;
  EngageTarget& g = t->target;
  int64_t x = 0;
  auto bad = [v]() {
    return fail(kExitUsage, "--target takes chip-load[=MM], power=W or mrr=MM3/MIN (or power W, mrr MM3/MIN), not '%s'", v);
  };
  if (kind == "chip-load") {
    g.kind = EngageTargetKind::kChip;
    if (value && (!parse_scaled(value, kNmPerMm, &x) || x <= 0 || x > 100 * kNmPerMm)) return bad();
    g.chip_nm = value ? x : 0;
    t->text = value ? std::string("chip-load ") + value + " mm" : "chip-load (each material's max_chip)";
  } else if (kind == "power" && value) {
    if (!parse_scaled(value, 1000, &x) || x <= 0 || x > (int64_t{1} << 50)) return bad();
    g.kind = EngageTargetKind::kPower;
    g.power_mw = x;
    t->text = std::string("power ") + value + " W";
  } else if (kind == "mrr" && value) {
    // mm^3/min to um^3/min: 10^9.
    if (!parse_scaled(value, 1000000000, &x) || x <= 0) return bad();
    g.kind = EngageTargetKind::kMrr;
    g.mrr_um3_per_min = x;
    t->text = std::string("mrr ") + value + " mm3/min";
  } else {
    return bad();
  }
  t->given = true;
  return kExitOk;
}

std::vector<std::string> join_target_words(int argc, char** argv) {
  std::vector<std::string> out;
  for (int k = 0; k < argc; ++k) {
    const bool two = k + 2 < argc && !std::strcmp(argv[k], "--target") &&
                     (!std::strcmp(argv[k + 1], "power") || !std::strcmp(argv[k + 1], "mrr"));
    if (two) {
      out.push_back(argv[k]);
      out.push_back(std::string(argv[k + 1]) + "=" + argv[k + 2]);
      k += 2;
    } else {
      out.push_back(argv[k]);
    }
  }
  return out;
}

}  // namespace cli
}  // namespace dexmill
