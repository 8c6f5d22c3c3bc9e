// A run's verdict (`dexmill run --sheet`'s top line, the report's key
// `verdict`): the count of its findings by kind, from the report's totals
// (platform/report/run_report.h); it passes when there is none and the run
// was not stopped.
#ifndef DEXMILL_PLATFORM_REPORT_VERDICT_H
#define DEXMILL_PLATFORM_REPORT_VERDICT_H

#include <cstdint>
#include <string>

#include "platform/report/run_report.h"

namespace dexmill {

struct Verdict {
  uint64_t errors = 0;      // input errors
  uint64_t gouges = 0;      // assessment.gouges_total: lines that gouged the design
  uint64_t collisions = 0;  // collisions_total: the safety checks' findings
  uint64_t travel = 0;      // machine.travel_total: moves beyond the machine's travel
  uint64_t rules = 0;       // material_violations_total: the material's process rules broken
  uint64_t load = 0;        // load.total: --check load's findings
  bool stopped = false;     // --stop-at, or a bad block: the cut did not run to the end
  bool pass() const { return !errors && !gouges && !collisions && !travel && !rules && !load && !stopped; }
};

Verdict report_verdict(const RunReport& r);

// "PASS", or the counts that are not 0, e.g. "3 gouges · 1 collision ·
// 2 travel · 5 rule findings · 1 load" (and "stopped at line N").
std::string verdict_text(const Verdict& v, const RunReport& r);

}  // namespace dexmill

#endif
