#include "tools/run_safety.h"

#include <cstdio>

namespace dexmill {
namespace cli {

void safety_start(RunSafety* s, const DexelGrid<height_t>& g, bool rapid, bool spindle, bool below, bool has_table,
                  int64_t table_nm) {
  s->shadow.assign(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny), 0);
  safety_watch_init(&s->watch, g, s->shadow.data(), s->shadow.size());
  s->watch.check_rapid = rapid;
  s->watch.check_spindle = spindle;
  s->watch.check_below = below;
  s->watch.bottom_nm = g.z0_nm;
  s->watch.check_table = has_table;
  s->watch.table_nm = table_nm;
}

void safety_mark_new(RunSafety* s) {
  for (; s->marked < s->watch.nevents; ++s->marked) s->marks.push_back(s->watch.events[s->marked].at);
}

void safety_print(const RunSafety& s, const std::string& file, const DexelGrid<height_t>& g) {
  for (size_t k = 0; k < s.watch.nevents; ++k) {
    const SafetyEvent& e = s.watch.events[k];
    std::fprintf(stderr, "%s:%u:1: warning: %s\n", file.c_str(), e.line, safety_event_text(e, g.lsb_nm, g.pitch_nm).c_str());
  }
  if (s.watch.total > s.watch.nevents)
    std::fprintf(stderr, "%s: warning: %llu more safety findings not listed\n", file.c_str(),
                 static_cast<unsigned long long>(s.watch.total - s.watch.nevents));
}

void safety_to_report(const RunSafety& s, RunReport* rep) {
  rep->have_collisions = true;
  rep->collisions.assign(s.watch.events, s.watch.events + s.watch.nevents);
  rep->collisions_total = s.watch.total;
  rep->rapid_removed_lsb = s.watch.rapid_removed_lsb;
}

}  // namespace cli
}  // namespace dexmill
