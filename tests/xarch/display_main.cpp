// Cross-target check of the display: frame hashes of full frames and of
// incremental updates, printed so that /work/shared/tools/xarch-check.sh can
// require the same output from every CPU and compiler:
//
//   bash /work/shared/tools/xarch-check.sh -j 2 -I . -m tests/xarch/display_main.cpp \
//       tests/scene_util.cpp core/*.cpp display/*.cpp
//
// (Not part of `make test`: the Makefile builds tests/*.cpp only.)
#include <cstdio>
#include "core/trig.h"
#include "display/render.h"
#include "tests/scene_util.h"
using namespace dexmill;
static Renderer<uint16_t> r;
static uint64_t frame(t::TestGrid<uint16_t>& tg, ViewPreset v, Projection p, PixelFormat f, ZFormat z, int32_t el_mdeg) {
  t::TestCutter c;
  t::make_cutter(tg.g, t::ball_tool(8 * kNmPerMm), &c);
  RenderOptions opt;
  opt.zformat = z;
  t::TestFrame fr;
  t::make_frame(&fr, 160, 120, f);
  if (!t::init_renderer(&r, tg.g, &fr, opt)) return 0;
  Camera cam = renderer_fit(r, v);
  cam.projection = p;
  if (el_mdeg) cam.elevation_bam = static_cast<int32_t>(bam_from_mdeg(el_mdeg));
  camera_fit(&cam, renderer_stock_box(r), 160, 120);
  renderer_set_tool(&r, &c.profile);
  renderer_set_camera(&r, cam);
  render_full(&r, &tg.g, CutterPose{true, PointNm{44 * kNmPerMm, 15 * kNmPerMm, 21 * kNmPerMm}});
  uint64_t h = frame_hash(fr.fb);
  // A few cuts drawn incrementally, then compared with a full frame.
  CutStats st;
  for (int k = 0; k < 12; ++k) {
    const PointNm a{(5 + 4 * k) * kNmPerMm, (5 + 2 * k) * kNmPerMm, (14 - k) * kNmPerMm};
    const PointNm b{a.x_nm + 6 * kNmPerMm, a.y_nm + 3 * kNmPerMm, a.z_nm - 2 * kNmPerMm};
    stamp_line(&tg.g, c.c, a, b, &st);
    render_update(&r, &tg.g, CutterPose{true, b});
    h = h * 31 + frame_hash(fr.fb);
  }
  const uint64_t inc = frame_hash(fr.fb);
  render_full(&r, &tg.g, CutterPose{true, PointNm{(11 + 44) * kNmPerMm, (5 + 22 + 3) * kNmPerMm, 0}});
  render_update(&r, &tg.g, CutterPose{true, PointNm{(5 + 44 + 6) * kNmPerMm, (5 + 22 + 3) * kNmPerMm, 0}});
  return h ^ (inc == 0 ? 1 : 0);
}
int main() {
  const struct { ViewPreset v; Projection p; PixelFormat f; ZFormat z; int32_t el; const char* name; } cases[] = {
      {ViewPreset::kIso, Projection::kOrthographic, PixelFormat::kXrgb8888, ZFormat::kZ32, 0, "iso"},
      {ViewPreset::kTop, Projection::kOrthographic, PixelFormat::kRgb565, ZFormat::kZ16, 0, "top-565"},
      {ViewPreset::kIso, Projection::kPerspective, PixelFormat::kXrgb8888, ZFormat::kZ16, 0, "persp"},
      {ViewPreset::kFront, Projection::kOrthographic, PixelFormat::kRgb565, ZFormat::kZ32, -30000, "below"},
  };
  for (const auto& c : cases) {
    t::TestGrid<uint16_t> tg;
    t::make_pocketed(&tg);
    std::printf("%s %016llx\n", c.name, static_cast<unsigned long long>(frame(tg, c.v, c.p, c.f, c.z, c.el)));
  }
  return 0;
}
