// display/shade.h's key and fill lights: every face the camera sees of the
// plain workpiece is at least about 25 % grey, from every side.
#include <cstdint>
#include <cstdio>

#include "core/math/trig.h"
#include "display/render.h"
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

// The pocketed block (walls facing every way, holes, a ball channel, a V
// groove, 45 degree walls) from presets and from all round at several
// heights, and from below; the background white and no table or tool, so
// that every other pixel is the stock's.
Darkest darkest_stock_pixel(bool old_light) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
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
  const Darkest d = darkest_stock_pixel(false);
  std::printf("light: darkest stock pixel %d (view %d, at %d,%d) over %lld pixels\n", d.value, d.view, d.x, d.y,
              static_cast<long long>(d.stock_pixels));
  CHECK_GT(d.stock_pixels, 48 * kW * kH / 20);  // the stock fills the frames
  CHECK_GE(d.value, kDarkest);
}

TEST(render_light_check_catches_a_key_light_alone) {
  // The check is not blind: with the light as it was before the fill came
  // (ambient 0.18 and the key), faces turned away from the key fall to the
  // ambient, about 18 % of their colour.
  const Darkest d = darkest_stock_pixel(true);
  std::printf("light: with the key alone, darkest stock pixel %d (view %d)\n", d.value, d.view);
  CHECK_LT(d.value, kDarkest);
}
