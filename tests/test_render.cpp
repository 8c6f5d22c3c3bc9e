// display/render.h: whole frames, golden hashes, incremental redraw.
#include <cstdio>

#include "core/trig.h"
#include "display/render.h"
#include "tests/alloc_count.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {
constexpr int64_t mm = kNmPerMm;
}

TEST(render_look) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  t::TestFrame f;
  t::make_frame(&f, 640, 480, PixelFormat::kXrgb8888);
  static Renderer<uint16_t> r;
  CHECK(t::init_renderer(&r, tg.g, &f));
  t::TestCutter cuts[4];
  t::make_cutter(tg.g, t::ball_tool(8 * mm), &cuts[0]);
  t::make_cutter(tg.g, t::flat_tool(8 * mm), &cuts[1]);
  t::make_cutter(tg.g, t::bull_tool(8 * mm, 2 * mm), &cuts[2]);
  t::make_cutter(tg.g, t::vbit_tool(8 * mm, 60000), &cuts[3]);
  const char* tools[] = {"ball", "flat", "bull", "vbit"};
  for (int k = 0; k < 4; ++k) {
    renderer_set_tool(&r, &cuts[k].profile);
    Camera c = renderer_fit(r, ViewPreset::kFront);
    c.view_height_nm /= 3;
    c.target = PointNm{44 * mm, 15 * mm, 24 * mm};
    c.elevation_bam = static_cast<int32_t>(bam_from_mdeg(15000));
    renderer_set_camera(&r, c);
    render_full(&r, &tg.g, CutterPose{true, PointNm{44 * mm, 15 * mm, 21 * mm}});
    char name[64];
    std::snprintf(name, sizeof name, "tool-%s", tools[k]);
    t::dump_frame(f.fb, name);
  }
  Camera c = renderer_fit(r, ViewPreset::kIso);
  c.projection = Projection::kPerspective;
  camera_fit(&c, renderer_stock_box(r), 640, 480);
  c.distance_nm = c.distance_nm * 2 / 3;
  renderer_set_camera(&r, c);
  render_full(&r, &tg.g, CutterPose{true, PointNm{44 * mm, 15 * mm, 15 * mm}});
  t::dump_frame(f.fb, "persp");
  c = renderer_fit(r, ViewPreset::kIso);
  c.elevation_bam = -c.elevation_bam;
  renderer_set_camera(&r, c);
  render_full(&r, &tg.g, CutterPose{true, PointNm{44 * mm, 15 * mm, 15 * mm}});
  t::dump_frame(f.fb, "below");
  t::TestFrame f565;
  t::make_frame(&f565, 480, 272, PixelFormat::kRgb565);
  RenderOptions o;
  o.zformat = ZFormat::kZ16;
  static Renderer<uint16_t> r2;
  CHECK(t::init_renderer(&r2, tg.g, &f565, o));
  renderer_set_tool(&r2, &cuts[0].profile);
  renderer_set_camera(&r2, renderer_fit(r2, ViewPreset::kIso));
  render_full(&r2, &tg.g, CutterPose{true, PointNm{44 * mm, 15 * mm, 15 * mm}});
  t::dump_frame(f565.fb, "rgb565");
}
