// The process rules (core/safety/material_limits.h) on cuts the test makes: a feed
// over a material's limit on exactly one record gives one violation of
// that material on that line; the spindle outside a range, coolant in wood;
// nothing for a cut within the limits or through the other material; the
// volume each material lost against the geometry (a slot through two
// layers: the layer boundary splits each column exactly).
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/safety/material_limits.h"
#include "core/cut/sweep.h"
#include "core/math/fixed.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;
using t::flat_tool;
using t::make_block;
using t::TestGrid;

namespace {

const int64_t mm = kNmPerMm;

// Wood (coolant forbidden, 3000 mm/min) from Z10 up over aluminium
// (1200 mm/min, spindle 8000..24000) below, on a 20 mm block.
StockComposition sandwich() {
  StockComposition c;
  composition_clear(&c);
  Material alu, wood;
  (void)material_set_name(&alu, "alu");
  alu.process.max_feed_nm_per_min = 1200 * mm;
  alu.process.spindle_min_rpm = 8000;
  alu.process.spindle_max_rpm = 24000;
  (void)material_set_name(&wood, "wood");
  wood.process.max_feed_nm_per_min = 3000 * mm;
  wood.process.coolant_allowed = false;
  uint8_t ia = 0, iw = 0;
  (void)composition_add_material(&c, alu, &ia);
  (void)composition_add_material(&c, wood, &iw);
  (void)composition_add_layer(&c, -1000 * mm, 10 * mm, ia);
  (void)composition_add_layer(&c, 10 * mm, 1000 * mm, iw);
  return c;
}

struct Rig {
  TestGrid<uint16_t> tg;
  StockComposition comp = sandwich();
  std::vector<uint32_t> shadow;
  ProcessWatch w;
  SweepTool st;
  Rig() {
    make_block(&tg, 81, 41, 500000, 20 * mm);  // 40 x 20 mm at 0.5 mm
    shadow.resize(tg.top.size());
    (void)process_watch_init(&w, tg.g, &comp, shadow.data(), shadow.size());
    (void)sweep_tool_prepare(tool_profile(flat_tool(4 * mm)), tg.g.lsb_nm, &st);
  }
  // One straight feed at depth z with state s.
  void cut(double x0, double x1, double y, double z, const ProcessState& s) {
    CutStats stats;
    tg.g.dirty = GridRect::none();
    sweep_line(&tg.g, st, PointNm{int64_t(x0 * mm), int64_t(y * mm), int64_t(z * mm)},
               PointNm{int64_t(x1 * mm), int64_t(y * mm), int64_t(z * mm)}, &stats, true);
    process_watch_record(&w, tg.g, tg.g.dirty, s, nullptr);
  }
};

ProcessState feed(uint32_t line, int64_t f_mm_min, int32_t rpm = 12000, uint8_t coolant = 0) {
  ProcessState s;
  s.line = line;
  s.feed_move = true;
  s.feed_nm_per_min = f_mm_min * mm;
  s.spindle_rpm = rpm;
  s.spindle_on = true;
  s.coolant = coolant;
  s.time_us = 1000000;
  return s;
}

}  // namespace

TEST(process_feed_over_a_limit_on_its_line_only) {
  Rig r;
  r.cut(-5, 45, 5, 15, feed(3, 2000));   // wood only, within its 3000
  r.cut(-5, 45, 10, 5, feed(4, 1000));   // through both, within both
  r.cut(-5, 45, 15, 5, feed(5, 2000));   // through both: over alu's 1200
  CHECK_EQ(r.w.total, 1u);
  CHECK_EQ(r.w.nkept, 1u);
  CHECK_EQ(r.w.kept[0].line, 5u);
  CHECK_EQ(r.w.kept[0].rule, ProcessRule::kFeed);
  CHECK(!std::strcmp(r.comp.materials[r.w.kept[0].material].name, "alu"));
  CHECK_EQ(r.w.tally[0].violations, 1u);
  CHECK_EQ(r.w.tally[1].violations, 0u);
  // The same feed in air or in wood only is no violation.
  Rig q;
  q.cut(-5, 45, 5, 15, feed(7, 2900));
  q.cut(-5, 45, 5, 25, feed(8, 9000));
  CHECK_EQ(q.w.total, 0u);
}

TEST(process_spindle_and_coolant) {
  Rig r;
  r.cut(-5, 45, 5, 5, feed(3, 1000, 30000));            // alu over 24000 rpm (and wood has no range)
  r.cut(-5, 45, 15, 15, feed(4, 1000, 12000, 2));       // flood in wood
  r.cut(-5, 45, 10, 5, feed(5, 1000, 12000, 0));        // fine
  CHECK_EQ(r.w.total, 2u);
  CHECK_EQ(r.w.kept[0].rule, ProcessRule::kSpindle);
  CHECK_EQ(r.w.kept[0].line, 3u);
  CHECK_EQ(r.w.kept[0].value, 30000);
  CHECK_EQ(r.w.kept[1].rule, ProcessRule::kCoolant);
  CHECK_EQ(r.w.kept[1].line, 4u);
  CHECK(!std::strcmp(r.comp.materials[r.w.kept[1].material].name, "wood"));
}

TEST(process_volume_by_material) {
  Rig r;
  // A 4 mm slot 15 mm deep (Z5) through the 40 mm block: 10 mm of wood and
  // 5 mm of aluminium in every column it empties.
  r.cut(-5, 45, 10, 5, feed(3, 1000));
  uint64_t cols = 0;
  for (size_t k = 0; k < r.tg.top.size(); ++k)  // the slot's floor (the block's rim is a ring of holes)
    cols += r.tg.top[k] > 0 && r.tg.g.z0_nm + int64_t(r.tg.top[k]) * r.tg.g.lsb_nm < 6 * mm;
  const uint64_t wood = r.w.tally[1].removed_nm_columns, alu = r.w.tally[0].removed_nm_columns;
  CHECK_GT(cols, 0u);
  CHECK_EQ(wood, cols * 10 * static_cast<uint64_t>(mm));
  CHECK_EQ(alu, cols * 5 * static_cast<uint64_t>(mm));
  CHECK_EQ(r.w.tally[0].cut_time_us, 1000000);
  CHECK_EQ(r.w.tally[1].cut_time_us, 1000000);
}

// `dexmill optimize`'s input: per line, the lowest limit among what its feed
// moves removed, whether or not the feed was over it; air, rapids and
// untracked lines stay kNoFeedLimit.
TEST(process_line_feed_limits) {
  Rig r;
  std::vector<int64_t> lim(8, 0);
  process_watch_track_lines(&r.w, lim.data(), 7);  // lines 0..6; line 7 untracked
  CHECK_EQ(lim[7], 0);
  r.cut(-5, 45, 5, 15, feed(2, 2000));   // wood only
  r.cut(-5, 45, 10, 5, feed(3, 1000));   // both layers, within both: alu's limit all the same
  r.cut(-5, 45, 15, 25, feed(4, 9000));  // air
  ProcessState rapid = feed(5, 9000);
  rapid.feed_move = false;
  r.cut(-5, 45, 30, 5, rapid);           // a rapid through both: no feed limit
  r.cut(-5, 45, 35, 5, feed(7, 500));    // past the tracked lines
  CHECK_EQ(lim[1], kNoFeedLimit);
  CHECK_EQ(lim[2], 3000 * mm);
  CHECK_EQ(lim[3], 1200 * mm);
  CHECK_EQ(lim[4], kNoFeedLimit);
  CHECK_EQ(lim[5], kNoFeedLimit);
  CHECK_EQ(lim[7], 0);
}
