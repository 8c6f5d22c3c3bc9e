// display/surface/shade.h's key and fill lights: every face the camera sees of the
// plain workpiece is at least about 25 % grey, from every side.
#include <cstdint>
#include <cstdio>

#include "core/cut/stamp.h"
#include "core/math/trig.h"
#include "display/surface/render.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int32_t kW = 240, kH = 180;
// 25 % grey: the mean of the three channels.
constexpr int32_t kDarkest = 64;

struct Darkest {
  int32_t value = 256;  // the darkest stock pixel's mean channel
  int32_t x = -1, y = -1;
  int32_t view = -1;
  int64_t stock_pixels = 0;
};

// A round pocket cut with a ball, 24 mm across: its wall faces every
// direction.
void make_round_pocket(t::TestGrid<uint16_t>* tg) {
  const int64_t mm = kNmPerMm;
  t::make_block(tg, 100, 80, mm / 2, 12 * mm);
  t::TestCutter ball;
  t::make_cutter(tg->g, t::ball_tool(6 * mm), &ball);
  CutStats st;
  PointNm prev{37 * mm, 20 * mm, 4 * mm};
  for (int32_t k = 1; k <= 96; ++k) {
    const SinCosQ30 cs = sincos_bam(bam_from_mdeg(k * 3750));
    const PointNm p{25 * mm + ((9 * mm * cs.cos_q30) >> 30), 20 * mm + ((9 * mm * cs.sin_q30) >> 30), 4 * mm};
    stamp_line(&tg->g, ball.c, prev, p, &st);
    prev = p;
  }
}

// The pocketed block (walls facing every way, holes, a ball channel, a V
// groove, 45 degree walls) or the round pocket, from all round at several
// heights and from below; the background white and no table or tool, so
// that every other pixel is the stock's.
Darkest darkest_stock_pixel(bool old_light, int scene) {
  t::TestGrid<uint16_t> tg;
  if (scene == 0) t::make_pocketed(&tg);
  else make_round_pocket(&tg);
  RenderOptions opt;
  opt.gradient = false;
  opt.table = false;
  opt.background_top = Rgb{255, 255, 255};
  if (old_light) {  // before the fill: a key light, less ambient
    opt.ambient_q14 = 3000;
    opt.key_q14 = 13384;
    opt.fill_q14 = 0;
  }
  t::TestFrame f;
  t::make_frame(&f, kW, kH, PixelFormat::kXrgb8888);
  static Renderer<uint16_t> r;
  Darkest d;
  if (!t::init_renderer(&r, tg.g, &f, opt)) return d;
  const uint32_t bg = pixel_pack(PixelFormat::kXrgb8888, opt.background_top);
  const int32_t elevations_mdeg[] = {10000, 35264, 60000, -30000};
  int view = 0;
  for (int32_t el : elevations_mdeg) {
    for (int32_t az = 0; az < 360000; az += 30000, ++view) {
      Camera cam = renderer_fit(r, ViewPreset::kIso);
      cam.azimuth_bam = bam_from_mdeg(az + 7000);
      cam.elevation_bam = static_cast<int32_t>(bam_from_mdeg(el));
      camera_fit(&cam, renderer_stock_box(r), kW, kH);
      renderer_set_camera(&r, cam);
      render_full(&r, &tg.g, CutterPose{});
      for (int32_t y = 0; y < kH; ++y) {
        const uint32_t* row = f.pixels.data() + static_cast<size_t>(y) * kW;
        for (int32_t x = 0; x < kW; ++x) {
          if (row[x] == bg) continue;
          const Rgb c = pixel_unpack(PixelFormat::kXrgb8888, row[x]);
          const int32_t mean = (c.r + c.g + c.b) / 3;
          ++d.stock_pixels;
          if (mean < d.value) d = Darkest{mean, x, y, view, d.stock_pixels};
        }
      }
    }
  }
  return d;
}

}  // namespace

TEST(render_light_no_visible_face_darker_than_quarter_grey) {
  for (int scene = 0; scene < 2; ++scene) {
    const Darkest d = darkest_stock_pixel(false, scene);
    std::printf("light: scene %d: darkest stock pixel %d (view %d, at %d,%d) over %lld pixels\n", scene, d.value,
                d.view, d.x, d.y, static_cast<long long>(d.stock_pixels));
    CHECK_GT(d.stock_pixels, 48 * kW * kH / 20);  // the stock fills the frames
    CHECK_GE(d.value, kDarkest);
  }
}

TEST(render_light_check_catches_a_key_light_alone) {
  // The check is not blind: with the light as it was before the fill came
  // (ambient 0.18 and the key), faces turned away from the key fall to the
  // ambient, about 18 % of their colour.
  const Darkest d = darkest_stock_pixel(true, 0);
  std::printf("light: with the old light, darkest stock pixel %d (view %d)\n", d.value, d.view);
  CHECK_LT(d.value, kDarkest);
}
