#include "tools/run/run_safety.h"

#include <cstdio>

#include "platform/report/report_json.h"

namespace dexmill {
namespace cli {

SimChecks safety_checks(const SafetyChoice& c) {
  SimChecks s;
  s.rapid = c.rapid;
  s.spindle = c.spindle;
  s.below = c.below;
  s.shank = c.shank;
  s.holder = c.holder;
  s.plunge = c.plunge;
  s.has_table = c.has_table;
  s.table_nm = c.table_nm;
  s.fixtures = c.fixtures.data();
  s.nfixtures = static_cast<int>(c.fixtures.size());
  return s;
}

void safety_print(const SafetyWatch& w, const std::string& file, const DexelGrid<height_t>& g) {
  for (size_t k = 0; k < w.nevents; ++k) {
    const SafetyEvent& e = w.events[k];
    std::fprintf(stderr, "%s:%u:1: warning: %s\n", file.c_str(), e.line, safety_event_text(e, g.lsb_nm, g.pitch_nm).c_str());
  }
  if (w.total > w.nevents)
    std::fprintf(stderr, "%s: warning: %llu more safety findings not listed\n", file.c_str(),
                 static_cast<unsigned long long>(w.total - w.nevents));
}

void safety_to_report(const SafetyWatch& w, RunReport* rep) {
  rep->have_collisions = true;
  rep->collisions.assign(w.events, w.events + w.nevents);
  rep->collisions_total = w.total;
  rep->rapid_removed_lsb = w.rapid_removed_lsb;
}

}  // namespace cli
}  // namespace dexmill
