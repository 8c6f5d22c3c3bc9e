// `dexmill bench paper-table` (tools/README.md, Benchmarks): every row of the paper's Table 2
// for its three workpieces (paper-w1..3: the paper's resolutions, ball
// cutters and instance counts, zig milling along x-parallel stripes with the
// lifted return simulated), each beside the paper's figure (200 MHz Pentium
// Pro, OpenGL in software) as a ratio, all in one run:
//   cut_s      cutting only: every instance stamped (the paper's instances
//              of motion), no display
//   full_ms    complete surface extraction: one full 640x480 frame of the
//              milled part (fastest of repeated frames)
//   update_ms  local update of the surface: the redraw after one instance,
//              the cutter drawn where it now stands (median over every
//              instance of the job, half of them the lifted return's)
//   sim_s      the whole simulation with display: every instance stamped and
//              the frame updated after each one (the paper drew about 10
//              frames a second; drawing every instance is the heavier case)
#include <algorithm>
#include <vector>

#include "core/cut/stamp.h"
#include "display/surface/render.h"
#include "tools/bench/bench.h"
#include "tools/bench/bench_job.h"

namespace dexmill {
namespace {

struct PaperRow {
  const char* job;
  double cut_s, full_s, update_s, sim_s;  // Table 2
};
const PaperRow kPaper[] = {
    {"paper-w1", 3 * 60 + 30, 20, 0.100, 10 * 60 + 40},
    {"paper-w2", 9 * 60 + 42, 80, 0.120, 33 * 60 + 4},
    {"paper-w3", 34 * 60 + 16, 150, 0.080, 87 * 60 + 7},
};

// The job's instances one at a time (each stamp_line piece is at most one
// pitch long: one instance, as stamp_line spaces them), calling after(tip)
// after each.
template <class F>
uint64_t each_instance(Job* j, F after) {
  const std::vector<PointNm>& path = j->w.path;
  const int64_t p = j->g.pitch_nm;
  CutStats st;
  uint64_t n = 0;
  for (size_t k = 1; k < path.size(); ++k) {
    const PointNm a = path[k - 1], b = path[k];
    const int64_t steps = std::max<int64_t>({(std::abs(b.x_nm - a.x_nm) + p - 1) / p, (std::abs(b.y_nm - a.y_nm) + p - 1) / p, 1});
    PointNm prev = a;
    if (k == 1) {
      stamp_line(&j->g, j->cutter, a, a, &st);
      after(a);
      ++n;
    }
    for (int64_t s = 1; s <= steps; ++s) {
      const PointNm q{a.x_nm + (b.x_nm - a.x_nm) * s / steps, a.y_nm + (b.y_nm - a.y_nm) * s / steps,
                      a.z_nm + (b.z_nm - a.z_nm) * s / steps};
      stamp_line(&j->g, j->cutter, prev, q, &st, false);
      after(q);
      ++n;
      prev = q;
    }
  }
  return n;
}

void run_table(const char* name) {
  for (const PaperRow& row : kPaper) {
    Job j;
    if (!setup(name, row.job, &j)) return;
    // Cutting only.
    reset(&j);
    double t0 = bench::now_s();
    const uint64_t instances = each_instance(&j, [](const PointNm&) {});
    const double cut_s = bench::now_s() - t0;
    // The display: a renderer over the milled part.
    std::vector<uint32_t> pixels(640 * 480);
    const FrameView fb{pixels.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
    RenderOptions opt;
    const size_t need = renderer_scratch_bytes(j.g, 640, 480, opt.zformat);
    std::vector<uint64_t> scratch((need + 7) / 8);
    static Renderer<height_t> r;
    renderer_init(&r, j.g, fb, opt, scratch.data(), need);
    const ToolProfile prof = tool_profile(j.w.tool);
    renderer_set_tool(&r, &prof);
    renderer_set_camera(&r, renderer_fit(r, ViewPreset::kIso));
    const CutterPose pose{true, j.w.path.back()};
    const double full_s = bench::best_time_s(
        [&] {
          const double a = bench::now_s();
          render_full(&r, &j.g, pose);
          return bench::now_s() - a;
        },
        0.3, 50);
    // The whole simulation with display, timing each update on its own.
    reset(&j);
    render_full(&r, &j.g, CutterPose{true, j.w.path.front()});
    std::vector<double> updates;
    updates.reserve(static_cast<size_t>(instances));
    t0 = bench::now_s();
    each_instance(&j, [&](const PointNm& tip) {
      const double a = bench::now_s();
      render_update(&r, &j.g, CutterPose{true, tip});
      updates.push_back(bench::now_s() - a);
    });
    const double sim_s = bench::now_s() - t0;
    std::sort(updates.begin(), updates.end());
    const double update_s = updates[updates.size() / 2];
    bench::result(name,
                  "job=%s grid=%dx%d instances=%llu paper_instances=%lld cut_s=%.4f vs_paper=%.0f full_ms=%.2f vs_paper=%.0f "
                  "update_ms=%.4f vs_paper=%.0f sim_s=%.3f vs_paper=%.0f seconds=%.6f",
                  row.job, j.g.nx, j.g.ny, static_cast<unsigned long long>(instances),
                  static_cast<long long>(j.w.paper_instances), cut_s, row.cut_s / cut_s, full_s * 1e3, row.full_s / full_s,
                  update_s * 1e3, row.update_s / update_s, sim_s, row.sim_s / sim_s, sim_s);
  }
}

}  // namespace
}  // namespace dexmill

BENCH(paper_table, "paper-table", dexmill::run_table);
