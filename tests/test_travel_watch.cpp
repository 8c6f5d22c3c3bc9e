// core/safety/travel_watch.h: soft limits against moves the test makes, both
// ways: inside (and exactly at a limit) no finding, past one a finding with
// the axis, side and excess; the tool length offset along Z; an arc whose
// ends are inside but whose bulge is not, against the analytic bulge; an
// axis without limits; the kept findings' cap and the count.
#include <cmath>
#include <cstdlib>
#include <cstdint>

#include "core/safety/travel_watch.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = 1000000;

MachineSpec box() {
  MachineSpec m;
  m.kind = MachineKind::kLinuxcnc;
  m.axis[0] = MachineAxis{true, 0, 100 * kMm, 0, 0};
  m.axis[1] = MachineAxis{true, 0, 50 * kMm, 0, 0};
  m.axis[2] = MachineAxis{true, -50 * kMm, 0, 0, 0};
  return m;
}

CanonRecord line(CanonKind k, PointNm a, PointNm b, uint32_t n, int64_t tlo = 0) {
  CanonRecord r{};
  r.kind = k;
  r.line = n;
  r.start = a;
  r.end = b;
  r.tool_length_offset_nm = tlo;
  return r;
}

PointNm mm(double x, double y, double z) {
  return PointNm{static_cast<int64_t>(std::llround(x * kMm)), static_cast<int64_t>(std::llround(y * kMm)),
                 static_cast<int64_t>(std::llround(z * kMm))};
}

}  // namespace

TEST(travel_watch_inside_and_past) {
  TravelWatch w;
  travel_watch_init(&w, box());
  // Inside, and exactly at the limits: nothing.
  CHECK(!travel_watch_check(&w, line(CanonKind::kTraverse, mm(10, 10, -5), mm(100, 50, 0), 3)));
  CHECK(!travel_watch_check(&w, line(CanonKind::kFeed, mm(100, 50, 0), mm(0, 0, -50), 4)));
  CHECK_EQ(w.total, uint64_t{0});
  // 0.02 mm past X's maximum, 1.5 mm below Y's minimum: two findings of one move.
  CHECK(travel_watch_check(&w, line(CanonKind::kFeed, mm(50, 10, -5), mm(100.02, -1.5, -5), 7)));
  CHECK_EQ(w.nkept, 2);
  CHECK_EQ(w.kept[0].line, 7u);
  CHECK_EQ(w.kept[0].axis, 0);
  CHECK(w.kept[0].above);
  CHECK_EQ(w.kept[0].excess_nm, 20000);
  CHECK_EQ(w.kept[0].limit_nm, 100 * kMm);
  CHECK_EQ(w.kept[1].axis, 1);
  CHECK(!w.kept[1].above);
  CHECK_EQ(w.kept[1].excess_nm, 1500000);
  // A move that starts outside (where the one before ended) and comes back
  // in is not one, nor one that stays as far out; one that goes farther is.
  CHECK(!travel_watch_check(&w, line(CanonKind::kFeed, mm(100.02, -1.5, -5), mm(50, 10, -5), 8)));
  CHECK(!travel_watch_check(&w, line(CanonKind::kFeed, mm(100.02, 10, -5), mm(100.02, 10, 0), 8)));
  CHECK(travel_watch_check(&w, line(CanonKind::kFeed, mm(100.02, 10, -5), mm(101, 10, -5), 8)));
  w.total = 2;  // (the three below counted as before)
  w.nkept = 2;
  // The tool length offset: the tip at Z-10 with 15 mm of offset is 5 mm
  // above the machine's Z0.
  CHECK(travel_watch_check(&w, line(CanonKind::kTraverse, mm(50, 10, -20), mm(50, 10, -10), 9, 15 * kMm)));
  CHECK_EQ(w.kept[2].axis, 2);
  CHECK_EQ(w.kept[2].excess_nm, 5 * kMm);
  CHECK_EQ(w.kept[2].at_nm, 5 * kMm);
  // Records that do not move pass.
  CanonRecord dwell = line(CanonKind::kDwell, mm(500, 500, 500), mm(500, 500, 500), 10);
  CHECK(!travel_watch_check(&w, dwell));
  CHECK_EQ(w.total, uint64_t{3});
}

TEST(travel_watch_arc_bulge) {
  TravelWatch w;
  travel_watch_init(&w, box());
  // A half circle of radius 10 about (92, 25) from (92, 15) to (92, 35)
  // counterclockwise: its ends are inside, its far side reaches X 102.
  CanonRecord r = line(CanonKind::kArc, mm(92, 15, -5), mm(92, 35, -5), 11);
  r.arc.plane = Plane::kXY;
  r.arc.centre = mm(92, 25, -5);
  r.arc.turns = 1;
  CHECK(travel_watch_check(&w, r));
  CHECK_EQ(w.nkept, 1);
  CHECK_EQ(w.kept[0].axis, 0);
  // 2 mm past, within the chords' bound (1 um sagitta, 8 nm).
  CHECK_LE(std::llabs(w.kept[0].excess_nm - 2 * kMm), 1010);
  // The same arc clockwise goes the other way round, through X 82: inside.
  r.arc.turns = -1;
  CHECK(!travel_watch_check(&w, r));
  // A small arc well inside passes on its box alone.
  CanonRecord s = line(CanonKind::kArc, mm(40, 25, -5), mm(40, 25, -5), 12);
  s.arc.plane = Plane::kXY;
  s.arc.centre = mm(45, 25, -5);
  s.arc.turns = 1;
  CHECK(!travel_watch_check(&w, s));
  // An arc that just touches X 100 is no finding: the slack takes the chords' rounding.
  CanonRecord t = line(CanonKind::kArc, mm(90, 25, -5), mm(90, 25, -5), 13);
  t.arc.plane = Plane::kXY;
  t.arc.centre = mm(95, 25, -5);
  t.arc.turns = 1;
  CHECK(!travel_watch_check(&w, t));
}

TEST(travel_watch_unlimited_axes_and_the_cap) {
  MachineSpec m = box();
  m.axis[2].limited = false;  // no Z limits (grbl with $132 = 0)
  TravelWatch w;
  travel_watch_init(&w, m);
  CHECK(!travel_watch_check(&w, line(CanonKind::kFeed, mm(5, 5, 0), mm(5, 5, 900), 2)));
  for (uint32_t k = 0; k < 150; ++k) (void)travel_watch_check(&w, line(CanonKind::kFeed, mm(5, 5, 0), mm(200, 5, 0), k + 3));
  CHECK_EQ(w.total, uint64_t{150});
  CHECK_EQ(w.nkept, kTravelKept);
  CHECK_EQ(w.kept[kTravelKept - 1].line, static_cast<uint32_t>(kTravelKept + 2));
}

TEST(travel_watch_axes_count_from_their_first_move) {
  // The program starts where the simulation puts it (its origin), not
  // where the machine is: with a 30 mm offset that is Z 30 past a Z max of
  // 0, but no move has moved Z yet. An XY move is no Z finding; the first
  // Z move counts from wherever the machine was, so its end alone decides.
  TravelWatch w;
  travel_watch_init(&w, box());
  CHECK(!travel_watch_check(&w, line(CanonKind::kTraverse, mm(0, 0, 0), mm(50, 10, 0), 2, 30 * kMm)));
  CHECK(!travel_watch_check(&w, line(CanonKind::kTraverse, mm(50, 10, 0), mm(50, 10, -40), 3, 30 * kMm)));  // Z -10: in
  CHECK(travel_watch_check(&w, line(CanonKind::kTraverse, mm(50, 10, -40), mm(50, 10, -20), 4, 30 * kMm)));  // Z 10: out
  CHECK_EQ(w.kept[0].line, 4u);
  CHECK_EQ(w.kept[0].excess_nm, 10 * kMm);
  // A first Z move that ends outside is one too, however far out it began.
  TravelWatch v;
  travel_watch_init(&v, box());
  CHECK(travel_watch_check(&v, line(CanonKind::kTraverse, mm(50, 10, 0), mm(50, 10, -20), 5, 30 * kMm)));
  CHECK_EQ(v.kept[0].excess_nm, 10 * kMm);
}
