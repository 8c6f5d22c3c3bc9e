// display/render.h: whole frames, golden hashes, incremental redraw.
#include <cstdio>

#include "display/render.h"
#include "tests/alloc_count.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

TEST(render_look_pocketed) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  t::TestFrame f;
  t::make_frame(&f, 640, 480, PixelFormat::kXrgb8888);
  static Renderer<uint16_t> r;
  CHECK(t::init_renderer(&r, tg.g, &f));
  t::TestCutter cut;
  t::make_cutter(tg.g, t::ball_tool(8 * kNmPerMm), &cut);
  renderer_set_tool(&r, &cut.profile);
  const char* names[] = {"iso", "top", "front", "right"};
  for (int v = 0; v < 4; ++v) {
    renderer_set_camera(&r, renderer_fit(r, static_cast<ViewPreset>(v)));
    RenderResult res = render_full(&r, &tg.g, CutterPose{true, PointNm{44 * kNmPerMm, 15 * kNmPerMm, 15 * kNmPerMm}});
    char name[64];
    std::snprintf(name, sizeof name, "pocketed-%s", names[v]);
    t::dump_frame(f.fb, name);
    std::printf("%s: %llu triangles %llu pixels\n", name, (unsigned long long)res.stats.triangles,
                (unsigned long long)res.stats.pixels_written);
  }
}
