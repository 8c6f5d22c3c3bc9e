#include "tools/run_safety.h"

#include <cstdio>

namespace dexmill {
namespace cli {

bool safety_start(RunSafety* s, const DexelGrid<height_t>& g, const SafetyChoice& c, std::string* why) {
  s->shadow.assign(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny), 0);
  s->tiles.assign(safety_tile_words(g), 0);
  safety_watch_init(&s->watch, g, s->shadow.data(), s->shadow.size(), s->tiles.data(), s->tiles.size());
  SafetyWatch& w = s->watch;
  w.check_rapid = c.rapid;
  w.check_spindle = c.spindle;
  w.check_below = c.below;
  w.check_shank = c.shank;
  w.check_holder = c.holder;
  w.check_plunge = c.plunge;
  w.bottom_nm = g.z0_nm;
  w.check_table = c.has_table;
  w.table_nm = c.table_nm;
  s->boxes = c.fixtures;
  if (s->boxes.empty()) return true;
  DexelGrid<uint32_t>& f = s->fixture_grid;
  if (!fixture_grid_size(g, s->boxes.data(), static_cast<int>(s->boxes.size()), &f)) {
    *why = "the fixtures hold no dexel column of the stock's lattice, or span more than 65535 of them";
    return false;
  }
  const size_t n = static_cast<size_t>(f.nx) * static_cast<size_t>(f.ny);
  if (n > (size_t{1} << 26)) {
    *why = "the fixtures span more than 64 M dexel columns at this pitch; use a coarser --pitch";
    return false;
  }
  s->fixture_top.assign(n, 0);
  s->fixture_bottom.assign(n, 0);
  f.top = s->fixture_top.data();
  f.bottom = s->fixture_bottom.data();
  fixture_grid_fill(&f, s->boxes.data(), static_cast<int>(s->boxes.size()));
  w.fixtures = &f;
  w.fixture_boxes = s->boxes.data();
  w.nfixture_boxes = static_cast<int>(s->boxes.size());
  return true;
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
