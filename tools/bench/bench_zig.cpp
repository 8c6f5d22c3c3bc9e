// `dexmill bench zig-1k` (paper §3's loop): the zig-milling path generator
// (core/cam/zig.h) on a 1024 x 1024 design, a smooth relief 2 to 10 mm deep
// at 0.1 mm, with the paper's free-form cutter (a 6-dexel ball) and a
// 3 mm ball: positions per second, every stripe and position (the paper's
// stepover and step of one dexel). Each position checks kZigPhases
// intervals of the tool's footprint on its way to the next.
#include <cmath>
#include <vector>

#include "core/cam/zig.h"
#include "core/tool/tool.h"
#include "tools/bench/bench.h"

namespace dexmill {
namespace {

void run_zig(const char* name) {
  constexpr int32_t kN = 1024;
  const GridGeometry geo{kN, kN, 0, 0, 100000, 0, 500};
  std::vector<int32_t> tops(static_cast<size_t>(kN) * kN);
  DesignGrid d;
  design_init(&d, geo, tops.data(), tops.size());
  for (int32_t j = 0; j < kN; ++j)
    for (int32_t i = 0; i < kN; ++i) {
      const double u = i / double(kN), v = j / double(kN);
      const double depth_mm = 6.0 + 2.5 * std::sin(9.42 * u) * std::cos(6.28 * v) + 1.5 * std::cos(15.7 * (u + v));
      tops[d.index(i, j)] = static_cast<int32_t>((20.0 - depth_mm) * 1e6 / 500);
    }
  const int64_t diameters_nm[] = {600000, 3000000};  // 6 dexels; 30 dexels
  for (int64_t dia : diameters_nm) {
    Tool tool;
    tool.kind = ToolKind::kBall;
    tool.diameter_nm = dia;
    tool.length_nm = 40 * kNmPerMm;
    const ToolProfile p = tool_profile(tool);
    std::vector<int32_t> words(zig_tool_words(p, geo));
    ZigTool t;
    zig_tool_build(p, geo, words.data(), words.size(), &t);
    const ZigOptions o;
    std::vector<int64_t> scratch(zig_stripe_scratch(d, t, o)), z(static_cast<size_t>(zig_positions(d, o)));
    // Every stripe once: the positions of a whole 1024^2 program.
    const int32_t stripes = bench::single_run() ? 64 : zig_stripe_count(d, o);
    const double t0 = bench::now_s();
    int64_t sum = 0;
    for (int32_t s = 0; s < stripes; ++s) {
      zig_stripe(d, t, o, s, 0, scratch.data(), scratch.size(), z.data());
      sum += z[z.size() / 2];
    }
    const double sec = bench::now_s() - t0;
    const double positions = double(stripes) * double(z.size());
    bench::result(name, "design=%dx%d pitch_mm=0.1 tool=ball:%.1f reach_dex=%d positions=%.0f positions_per_s=%.0f checksum=%lld seconds=%.3f",
                  kN, kN, double(dia) * 1e-6, t.reach_dex, positions, positions / sec, static_cast<long long>(sum), sec);
  }
}

}  // namespace
}  // namespace dexmill

BENCH(zig_1k, "zig-1k", dexmill::run_zig);
