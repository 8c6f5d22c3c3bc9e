// The marks of a run over its pictures; see run_marks.h.
#include "display/api/run_marks.h"

namespace dexmill {

PointNm gouge_mark_point(const GougeEvent& e, const DexelGrid<height_t>& g) {
  return PointNm{g.x0_nm + e.i * g.pitch_nm, g.y0_nm + e.j * g.pitch_nm, g.z0_nm + e.design_lsb * g.lsb_nm};
}

namespace {

void take_gouges(RunMarks* m, const GougeWatch& w, const DexelGrid<height_t>& g) {
  m->ngouges = 0;
  for (size_t k = 0; k < w.nevents && k < kGougeEventsMax; ++k) m->gouges[m->ngouges++] = gouge_mark_point(w.events[k], g);
}

void take_safety(RunMarks* m, const SafetyWatch& w) {
  for (; m->nsafety < w.nevents && m->nsafety < kSafetyEventsMax; ++m->nsafety) m->safety[m->nsafety] = w.events[m->nsafety].at;
}

}  // namespace

void run_marks_record(RunMarks* m, const Simulation& s) {
  if (const GougeWatch* w = s.gouges()) {
    if (s.gouge_finds() != m->gouge_finds) take_gouges(m, *w, s.grid());
    m->gouge_finds = s.gouge_finds();
  }
  if (const SafetyWatch* w = s.safety()) take_safety(m, *w);
}

void run_marks_after_cut(RunMarks* m, const Simulation& s, bool stopped_at_input_error) {
  run_marks_record(m, s);  // what the finish found
  const SafetyWatch* safety = s.safety();
  m->error = stopped_at_input_error;
  if (m->error) m->error_at = s.mill().position();  // the bad block's place
  m->stop = s.stop_reason() == SimStop::kCollision && safety && safety->nevents > 0;
  if (m->stop) m->stop_at = safety->events[safety->nevents - 1].at;  // the finding it stopped at
}

int32_t run_marks_lists(RunMarks* m, const Simulation& s) {
  int32_t n = 0;
  if (s.gouges()) m->lists[n++] = ViewMarks{m->gouges, m->ngouges, kGougeMarkColour};
  if (s.safety()) m->lists[n++] = ViewMarks{m->safety, m->nsafety, kSafetyMarkColour};
  if (m->error) m->lists[n++] = ViewMarks{&m->error_at, 1, kInputErrorMarkColour};
  if (m->stop) m->lists[n++] = ViewMarks{&m->stop_at, 1, kStopMarkColour};
  return n;
}

}  // namespace dexmill
