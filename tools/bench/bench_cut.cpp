// Cutting benchmarks: the paper's Table 2 jobs and the scale-up jobs, in
// both modes, with the lower bound of the same dexel visits.
//
// bound_ratio = seconds of the real cut / seconds of a pass that applies only
// min() of a precomputed constant to the same dexels in the same order (the
// spans the real cut logged), both timed in this run.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/assess/gouge_watch.h"
#include "core/safety/material_limits.h"
#include "core/safety/safety.h"
#include "core/material/material_preset.h"
#include "core/config.h"
#include "core/cut/stamp.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "tools/bench/bench.h"
#include "tools/bench/bench_job.h"
#include "tools/bench/workloads.h"

namespace dexmill {
namespace {

// Table 2, "cutting only", seconds on the paper's 200 MHz Pentium Pro.
double paper_cut_seconds(const char* name) {
  if (!std::strcmp(name, "paper-w1")) return 3 * 60 + 30;
  if (!std::strcmp(name, "paper-w2")) return 9 * 60 + 42;
  if (!std::strcmp(name, "paper-w3")) return 34 * 60 + 16;
  return 0;
}

// The path as one polyline, as core/cut/mill.h cuts a program: stamping leaves
// out each joint's repeated instance, sweeping chains the moves.
void cut(Job* j, bool sweep, CutStats* st) {
  const std::vector<PointNm>& path = j->w.path;
  if (!sweep) {
    for (size_t k = 1; k < path.size(); ++k) stamp_line(&j->g, j->cutter, path[k - 1], path[k], st, k == 1);
    return;
  }
  sweep_moves(j, 1, path.size(), st);
}

// One mode: its logged run (counts, and the spans for the lower bound) and
// its fastest timed cut and bound.
struct ModeRun {
  std::vector<DexelSpan> spans;
  SpanLog log;
  CutStats counted;
  double cut_s = 1e300, bound_s = 1e300;
};

// Seconds of the lower bound: min() of a constant over n logged spans, on
// the grid as it is.
double time_bound_spans(Job* j, const DexelSpan* spans, size_t n) {
  const height_t c = static_cast<height_t>(grid_height_of_z(j->g, j->w.stock_top_nm - kNmPerMm));
  const double t0 = bench::now_s();
  for (size_t k = 0; k < n; ++k) {
    const DexelSpan& sp = spans[k];
    height_t* row = j->top.data() + j->g.index(0, sp.j);
    for (int32_t i = sp.i0; i <= sp.i1; ++i) row[i] = row[i] < c ? row[i] : c;
  }
  return bench::now_s() - t0;
}

double time_bound(Job* j, const ModeRun& m) {
  reset(j);
  return time_bound_spans(j, m.spans.data(), m.log.count);
}

double time_cut(Job* j, bool sweep) {
  reset(j);
  CutStats st;
  const double t0 = bench::now_s();
  cut(j, sweep, &st);
  return bench::now_s() - t0;
}

void run_phases(const char* name, Job* j);

void run(const char* name) {
  Job j;
  if (!setup(name, name, &j)) return;
  const bool big = j.w.geo.nx > 2000;
  ModeRun m[2];
  for (int mode = 0; mode < 2; ++mode) {
    m[mode].spans.resize(big ? 1 : 1 << 22);
    m[mode].log.spans = m[mode].spans.data();
    m[mode].log.capacity = m[mode].spans.size();
    m[mode].counted.log = &m[mode].log;
    reset(&j);
    cut(&j, mode == 1, &m[mode].counted);
  }
  // Each round times both modes and both bounds, one after the other, and
  // every figure is the fastest of its rounds: the ratios then compare runs
  // made under the same load of the shared machine. Each cut is timed right
  // after an untimed one of the same mode, as when one mode is repeated:
  // without it the mode that ran second in a round starts with the other's
  // state in the caches and branch predictors, which costs stamping about
  // 1.7x and sweeping 1.4x on paper-w3 (and would flatter the sweep).
  const bool repeat = !big && !bench::single_run();
  // best_time_s drives the rounds (0.6 s, at most 50); each round keeps its
  // four figures in m, so its own return value is not needed.
  bench::best_time_s([&] {
    for (int mode = 0; mode < 2; ++mode) {
      if (repeat) time_cut(&j, mode == 1);
      m[mode].cut_s = std::min(m[mode].cut_s, time_cut(&j, mode == 1));
      if (!m[mode].log.dropped) m[mode].bound_s = std::min(m[mode].bound_s, time_bound(&j, m[mode]));
    }
    return 0.0;
  }, repeat ? 0.6 : 0.0);
  for (int mode = 0; mode < 2; ++mode) {
    const bool sweep = mode == 1;
    const double cut_s = m[mode].cut_s;
    const CutStats& counted = m[mode].counted;
    char bound[96] = "bound_ratio=n/a";
    if (!m[mode].log.dropped && m[mode].bound_s > 0)
      std::snprintf(bound, sizeof bound, "bound_seconds=%.6f bound_ratio=%.2f", m[mode].bound_s, cut_s / m[mode].bound_s);
    char paper[96] = "";
    if (j.w.paper_instances)
      std::snprintf(paper, sizeof paper, " paper_instances=%lld paper_seconds=%.0f speedup_vs_paper=%.0f",
                    static_cast<long long>(j.w.paper_instances), paper_cut_seconds(name), paper_cut_seconds(name) / cut_s);
    bench::result(name, "mode=%s grid=%dx%d tool=ball:%g moves=%zu instances=%llu dexel_updates=%llu seconds=%.6f "
                  "ns_per_update=%.3f %s%s",
                  sweep ? "sweep" : "stamp", j.w.geo.nx, j.w.geo.ny, j.w.tool.diameter_nm / 1e6, j.w.path.size() - 1,
                  static_cast<unsigned long long>(counted.instances),
                  static_cast<unsigned long long>(counted.dexel_updates), cut_s,
                  1e9 * cut_s / static_cast<double>(counted.dexel_updates ? counted.dexel_updates : 1), bound, paper);
  }
  if (j.w.pocket_start && !big) run_phases(name, &j);
}

// A phase's timed cut through a call of its own (not inlined), so that
// callgrind counts each alone: `valgrind --tool=callgrind build/dexmill
// bench --once scale-1k`, then `callgrind_annotate --inclusive=yes` on this
// file: the inclusive costs of the two calls in timed_phase(int, ...), the
// first the relief's, the second the pocket's (the compiler may fold the
// two instances into one name).
template <int Phase>
__attribute__((noinline)) void timed_phase(Job* j, size_t from, size_t to, CutStats* st) {
  sweep_moves(j, from, to, st);
}
void timed_phase(int ph, Job* j, size_t from, size_t to, CutStats* st) {
  if (ph == 0) timed_phase<0>(j, from, to, st);
  else timed_phase<1>(j, from, to, st);
}

// The sweep's two phases of a scale job timed apart, each against its own
// bound: the relief finish (short moves along x) and the spiral pocket
// (moves in every direction), which starts from the grid the relief left
// (cut untimed before its rounds). Where bound_ratio's time goes.
void run_phases(const char* name, Job* j) {
  const std::vector<PointNm>& path = j->w.path;
  const size_t at[3] = {1, j->w.pocket_start + 1, path.size()};
  const char* const phase[2] = {"relief", "pocket"};
  std::vector<DexelSpan> spans(1 << 22);
  for (int ph = 0; ph < 2; ++ph) {
    reset(j);
    CutStats before;
    sweep_moves(j, at[0], at[ph], &before);
    const std::vector<height_t> start_top = j->top, start_bottom = j->bottom;
    auto restore = [&] {
      j->top = start_top;
      j->bottom = start_bottom;
    };
    SpanLog log;
    log.spans = spans.data();
    log.capacity = spans.size();
    CutStats counted;
    counted.log = &log;
    sweep_moves(j, at[ph], at[ph + 1], &counted);
    if (log.dropped) continue;
    double cut_s = 1e300, bound_s = 1e300;
    bench::best_time_s([&] {
      restore();
      CutStats st;
      const double t0 = bench::now_s();
      timed_phase(ph, j, at[ph], at[ph + 1], &st);
      cut_s = std::min(cut_s, bench::now_s() - t0);
      restore();
      bound_s = std::min(bound_s, time_bound_spans(j, spans.data(), log.count));
      return 0.0;
    }, bench::single_run() ? 0.0 : 0.6);
    bench::result(name, "mode=sweep phase=%s moves=%zu dexel_updates=%llu spans=%zu floor_skips=%llu seconds=%.6f "
                  "bound_seconds=%.6f bound_ratio=%.2f",
                  phase[ph], at[ph + 1] - at[ph], static_cast<unsigned long long>(counted.dexel_updates), log.count,
                  static_cast<unsigned long long>(counted.floor_skips), cut_s, bound_s, cut_s / bound_s);
  }
}

// The sweep of a workload with a watch called over each move's changed
// columns (as the run's cut sink does), against the same sweep without, in
// the same rounds: the watch's cost as a ratio. watch(k, changed) runs
// after move k (k = path size: the last end cap).
template <class Watch, class Start>
void watch_ratio(const char* name, const char* workload, Job* j, Start start, Watch watch, uint64_t* found) {
  const auto timed = [&](bool watched) {
    reset(j);
    start();
    CutStats st;
    SweepChain chain;
    const std::vector<PointNm>& path = j->w.path;
    const double t0 = bench::now_s();
    for (size_t k = 1; k < path.size(); ++k) {
      sweep_chain_line(&j->g, j->sweep_tool, path[k - 1], path[k], &st, &chain);
      if (watched) {
        watch(k, j->g.dirty);
        j->g.dirty = GridRect::none();
      }
    }
    sweep_chain_end(&j->g, j->sweep_tool, &st, &chain);
    if (watched) watch(path.size(), j->g.dirty);
    return bench::now_s() - t0;
  };
  double plain = 1e300, watched = 1e300;
  bench::best_time_s([&] {
    plain = std::min(plain, timed(false));
    watched = std::min(watched, timed(true));
    return 0.0;
  }, bench::single_run() ? 0.0 : 0.6);
  bench::result(name, "workload=%s grid=%dx%d moves=%zu seconds=%.6f plain_seconds=%.6f watch_ratio=%.3f found=%llu",
                workload, j->w.geo.nx, j->w.geo.ny, j->w.path.size() - 1, watched, plain, watched / plain,
                static_cast<unsigned long long>(*found));
}

// assess-*: what the gouge watch of `dexmill run --design` costs. The
// design is a plane 0.1 mm under the path's lowest point, so nothing gouges
// and every changed column is compared (the usual case).
void run_assess(const char* name) {
  const char* workload = !std::strcmp(name, "assess-w3") ? "paper-w3" : "scale-1k";
  Job j;
  if (!setup(name, workload, &j)) return;
  const size_t n = static_cast<size_t>(j.w.geo.nx) * j.w.geo.ny;
  std::vector<int32_t> tops(n);
  std::vector<uint8_t> seen(gouge_watch_seen_bytes(j.w.geo.nx, j.w.geo.ny));
  DesignGrid d;
  int64_t zmin = j.w.path[0].z_nm;
  for (const PointNm& p : j.w.path) zmin = std::min(zmin, p.z_nm);
  if (!ok(design_init(&d, j.w.geo, tops.data(), n))) return;
  std::fill(tops.begin(), tops.end(), static_cast<int32_t>(grid_height_of_z(j.g, zmin - kNmPerMm / 10)));
  GougeWatch watch;
  AssessOptions opt;
  opt.region = GridRect{1, 1, j.w.geo.nx - 1, j.w.geo.ny - 1};  // not the ring of holes
  watch_ratio(
      name, workload, &j, [&] { (void)gouge_watch_init(&watch, &d, opt, seen.data(), seen.size()); },
      [&](size_t k, GridRect changed) {
        const PointNm& at = j.w.path[k < j.w.path.size() ? k : j.w.path.size() - 1];
        gouge_watch_check(&watch, j.g, changed, static_cast<uint32_t>(k), at, nullptr);
      },
      &watch.total);
}

// safety-*: what `dexmill run --check all` costs: each move a feed with the
// spindle on (every removal is compared with the shadow, none is a
// finding), below-stock checks on every move. safety-body-1k adds the
// shank, holder and plunge checks of a tool whose flutes (20 mm) and holder
// (a 40 mm cylinder at a 30 mm stick-out) clear the stock, as a sound
// program's do; safety-deep-1k gives it 3 mm flutes and a 6 mm stick-out,
// so that the shank and holder meet material on most moves (the work a
// finding costs, not the usual case).
void run_safety(const char* name) {
  const char* workload = !std::strcmp(name, "safety-w3") ? "paper-w3" : "scale-1k";
  const bool body = !std::strcmp(name, "safety-body-1k") || !std::strcmp(name, "safety-deep-1k");
  const bool deep = !std::strcmp(name, "safety-deep-1k");
  Job j;
  if (!setup(name, workload, &j)) return;
  std::vector<uint32_t> shadow(static_cast<size_t>(j.w.geo.nx) * j.w.geo.ny);
  std::vector<uint32_t> tiles(safety_tile_words(j.g));
  SafetyWatch watch;
  Tool t = j.w.tool;
  if (deep) t.flute_length_nm = 3 * kNmPerMm;
  t.length_nm = deep ? 6 * kNmPerMm : 30 * kNmPerMm;
  t.holder_segments = 1;
  t.holder[0] = HolderSegment{40 * kNmPerMm, 40 * kNmPerMm, 20 * kNmPerMm};
  ToolBody tb;
  tool_body_build(t, &tb);
  watch_ratio(
      name, workload, &j,
      [&] {
        (void)safety_watch_init(&watch, j.g, shadow.data(), shadow.size(), tiles.data(), tiles.size());
        watch.bottom_nm = j.g.z0_nm;
        watch.check_shank = watch.check_holder = watch.check_plunge = body;
      },
      [&](size_t k, GridRect changed) {
        const std::vector<PointNm>& path = j.w.path;
        CanonRecord r{};
        r.kind = k < path.size() ? CanonKind::kFeed : CanonKind::kDwell;
        r.line = static_cast<uint32_t>(k);
        r.start = path[k < path.size() ? k - 1 : path.size() - 1];
        r.end = path[k < path.size() ? k : path.size() - 1];
        SafetyMove m{r.line, false, true};
        m.plunge = safety_is_plunge(r);
        m.end = r.end;
        m.body = body ? &tb : nullptr;
        safety_watch_record(&watch, j.g, changed, r, m, nullptr);
      },
      &watch.total);
}

// process-1k: what `dexmill run --material wood-on-aluminium` costs: every
// column a move lowers looked up through the two layers (each move a feed
// within every limit, so nothing is a violation).
void run_process(const char* name) {
  Job j;
  if (!setup(name, "scale-1k", &j)) return;
  std::vector<uint32_t> shadow(static_cast<size_t>(j.w.geo.nx) * j.w.geo.ny);
  const BoxNm stock{PointNm{0, 0, 0}, PointNm{j.w.geo.nx * j.w.geo.pitch_nm, j.w.geo.ny * j.w.geo.pitch_nm, j.w.stock_top_nm}};
  static StockComposition comp;
  (void)material_preset("wood-on-aluminium", stock, &comp);
  ProcessWatch watch;
  watch_ratio(
      name, "scale-1k", &j, [&] { (void)process_watch_init(&watch, j.g, &comp, shadow.data(), shadow.size()); },
      [&](size_t k, GridRect changed) {
        ProcessState s;
        s.line = static_cast<uint32_t>(k);
        s.feed_move = true;
        s.feed_nm_per_min = 1000 * kNmPerMm;
        s.spindle_rpm = 12000;
        s.spindle_on = true;
        process_watch_record(&watch, j.g, changed, s, nullptr);
      },
      &watch.total);
}

}  // namespace
}  // namespace dexmill

BENCH(process_1k, "process-1k", dexmill::run_process);
BENCH(assess_w3, "assess-w3", dexmill::run_assess);
BENCH(assess_1k, "assess-1k", dexmill::run_assess);
BENCH(safety_w3, "safety-w3", dexmill::run_safety);
BENCH(safety_1k, "safety-1k", dexmill::run_safety);
BENCH(safety_body_1k, "safety-body-1k", dexmill::run_safety);
BENCH(safety_deep_1k, "safety-deep-1k", dexmill::run_safety);
BENCH(paper_w1, "paper-w1", dexmill::run);
BENCH(paper_w2, "paper-w2", dexmill::run);
BENCH(paper_w3, "paper-w3", dexmill::run);
BENCH(scale_1k, "scale-1k", dexmill::run);
BENCH(scale_4k, "scale-4k", dexmill::run);
