// The verdict of a run; see verdict.h.
#include "platform/report/verdict.h"

namespace dexmill {

Verdict report_verdict(const RunReport& r) {
  Verdict v;
  v.errors = r.errors.size();
  if (r.have_assessment) v.gouges = r.assessment.gouges_total;
  if (r.have_collisions) v.collisions = r.collisions_total;
  if (r.have_machine) v.travel = r.machine.travel_total;
  if (r.have_materials) v.rules = r.material_violations_total;
  if (r.have_load) v.load = r.load.total;
  v.stopped = !r.stopped_reason.empty();
  return v;
}

std::string verdict_text(const Verdict& v, const RunReport& r) {
  if (v.pass()) return "PASS";
  std::string o;
  auto add = [&o](uint64_t n, const char* one, const char* many) {
    if (!n) return;
    o += std::string(o.empty() ? "" : " \xc2\xb7 ") + std::to_string(n) + " " + (n == 1 ? one : many);
  };
  add(v.errors, "error", "errors");
  add(v.gouges, "gouge", "gouges");
  add(v.collisions, "collision", "collisions");
  add(v.travel, "travel finding", "travel findings");
  add(v.rules, "rule finding", "rule findings");
  add(v.load, "load finding", "load findings");
  if (v.stopped)
    o += std::string(o.empty() ? "" : " \xc2\xb7 ") + "stopped (" + r.stopped_reason + ") at line " +
         std::to_string(r.stopped_line);
  return o;
}

}  // namespace dexmill
