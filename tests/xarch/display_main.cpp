// Cross-target check of the display: frame hashes of full frames and of
// incremental updates, printed so that its builds for every CPU and compiler
// can be required to print the same output. Build it with
// tests/scene_util.cpp and every .cpp of core/ and display/, for each target
// the way tools/scripts/xcheck.sh builds the golden program, run each build
// and compare the outputs.
//
// (Not part of `make test`: the Makefile builds tests/*.cpp only.)
#include <cstdio>

#include "core/math/trig.h"
#include "display/surface/render.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;
Renderer<uint16_t> g_renderer;

struct Case {
  const char* name;
  ViewPreset view;
  Projection projection;
  PixelFormat format;
  ZFormat zformat;
  int32_t elevation_mdeg;  // 0: the preset's
};

// Prints the hash of the first full frame, of the frame after 12 cuts
// drawn incrementally, and whether that equals a full redraw.
void run(const Case& c) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  t::TestCutter tool;
  t::make_cutter(tg.g, t::ball_tool(8 * mm), &tool);
  RenderOptions opt;
  opt.zformat = c.zformat;
  t::TestFrame f;
  t::make_frame(&f, 160, 120, c.format);
  Renderer<uint16_t>& r = g_renderer;
  if (!t::init_renderer(&r, tg.g, &f, opt)) return;
  Camera cam = renderer_fit(r, c.view);
  cam.projection = c.projection;
  if (c.elevation_mdeg) cam.elevation_bam = static_cast<int32_t>(bam_from_mdeg(c.elevation_mdeg));
  camera_fit(&cam, renderer_stock_box(r), 160, 120);
  renderer_set_tool(&r, &tool.profile);
  renderer_set_camera(&r, cam);
  CutterPose pose{true, PointNm{44 * mm, 15 * mm, 21 * mm}};
  render_full(&r, &tg.g, pose);
  const uint64_t first = frame_hash(f.fb);
  CutStats st;
  for (int k = 0; k < 12; ++k) {
    const PointNm a{(5 + 4 * k) * mm, (5 + 2 * k) * mm, (14 - k) * mm};
    pose.tip = PointNm{a.x_nm + 6 * mm, a.y_nm + 3 * mm, a.z_nm - 2 * mm};
    stamp_line(&tg.g, tool.c, a, pose.tip, &st);
    render_update(&r, &tg.g, pose);
  }
  const uint64_t incremental = frame_hash(f.fb);
  render_full(&r, &tg.g, pose);
  const uint64_t full = frame_hash(f.fb);
  std::printf("%s first %016llx after-cuts %016llx %s\n", c.name, static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(incremental), incremental == full ? "equals-full" : "DIFFERS-FROM-FULL");
}

}  // namespace

int main() {
  const Case cases[] = {
      {"iso", ViewPreset::kIso, Projection::kOrthographic, PixelFormat::kXrgb8888, ZFormat::kZ32, 0},
      {"top-565", ViewPreset::kTop, Projection::kOrthographic, PixelFormat::kRgb565, ZFormat::kZ16, 0},
      {"persp", ViewPreset::kIso, Projection::kPerspective, PixelFormat::kXrgb8888, ZFormat::kZ16, 0},
      {"below", ViewPreset::kFront, Projection::kOrthographic, PixelFormat::kRgb565, ZFormat::kZ32, -30000},
  };
  for (const Case& c : cases) run(c);
  return 0;
}
