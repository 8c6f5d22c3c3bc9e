// Colours per vertex (paper §2.7.1, display/colour/material_colours.h textured):
// the lit ramp against shade_ramp, side faces split so that a layer's
// boundary shows sharp on a wall (figure 11) and without cracks, uncut tops
// tinted apart from cut ones.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "display/colour/material_colours.h"
#include "display/surface/render.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

// Two-layer block: black over yellow at 10 mm.
const StockComposition& two_layer() {
  static StockComposition c;
  composition_clear(&c);
  Material m;
  m.texture.kind = TextureKind::kLayers;
  m.texture.layers.boundary_z_nm[0] = 10 * mm;
  uint8_t k = 0;
  CHECK(ok(composition_add_material(&c, m, &k)));
  composition_set_default(&c, k);
  return c;
}

struct Scene {
  t::TestGrid<uint16_t> tg;
  t::TestFrame f;
  std::vector<uint8_t> cls;
  std::vector<uint32_t> luts, mem;
  MaterialColours<uint16_t> mc;
  Renderer<uint16_t> r;

  // A 40 x 30 mm block 20 mm high, a pocket cut into its middle, seen from
  // the front and a little above, drawn plain or textured.
  void draw(bool textured, uint32_t uncut_top = 0) {
    t::make_block(&tg, 40, 30, mm, 20 * mm);
    t::TestCutter flat;
    t::make_cutter(tg.g, t::flat_tool(6 * mm), &flat);
    CutStats st;
    for (int64_t y = 10 * mm; y <= 20 * mm; y += 2 * mm)
      stamp_line(&tg.g, flat.c, PointNm{12 * mm, y, 14 * mm}, PointNm{28 * mm, y, 14 * mm}, &st);
    t::make_frame(&f, 200, 150, PixelFormat::kXrgb8888);
    CHECK(t::init_renderer(&r, tg.g, &f));
    Camera cam = renderer_fit(r, ViewPreset::kFront);
    renderer_set_camera(&r, cam);
    if (textured) {
      cls.assign(size_t(tg.g.nx) * tg.g.ny, 0);
      luts.assign(size_t(kMaxColourClasses) * kShadeLevels, 0);
      mem.assign(material_texture_bytes(tg.g) / 4 + 1, 0);
      material_colours_init(&mc, tg.g, two_layer(), cls.data(), luts.data());
      material_colours_texture(&mc, mem.data(), uncut_top);
      renderer_set_colours(&r, &mc.colours);
    }
    render_full(&r, &tg.g, CutterPose{});
  }
  uint32_t at(int32_t x, int32_t y) const { return frame_pixel(f.fb, x, y); }
};

bool yellowish(uint32_t p) {
  const Rgb c = pixel_unpack(PixelFormat::kXrgb8888, p);
  return c.r > 60 && c.g > 45 && c.b < c.r / 2;
}
bool blackish(uint32_t p) {
  const Rgb c = pixel_unpack(PixelFormat::kXrgb8888, p);
  return c.r < 60 && c.g < 60 && c.b < 60;
}

}  // namespace

TEST(lit_ramp_matches_shade_ramp) {
  // The ramp per vertex colour is the ramp per class within one step.
  for (int32_t base : {1, 100, 180, 230, 255}) {
    LitRamp lit;
    lit_ramp(base, &lit);
    for (uint32_t rgb : {0x000000u, 0xFFFFFFu, 0xE8C018u, 0x2448A8u, 0x7F8081u}) {
      uint32_t lut[256];
      shade_ramp(PixelFormat::kXrgb8888, Rgb{uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb)}, base, lut);
      for (int32_t s = 0; s < 256; ++s) {
        const uint32_t a = lit_rgb(lit, rgb, s), b = lut[s] & 0xFFFFFF;
        for (int k = 0; k < 24; k += 8) CHECK_LE(std::abs(int((a >> k) & 0xFF) - int((b >> k) & 0xFF)), 1);
      }
    }
  }
}

TEST(layer_boundary_is_sharp_on_the_front_wall) {
  // Seen from the front, the block's front wall runs from z 0 (yellow) to
  // 20 mm (black); down the middle column the colour changes once, from one
  // pixel to the next: the wall was split at the boundary, each side drawn
  // in its own colour. Unsplit, the wall's two vertices (black top, yellow
  // bottom) would blend into a ramp of brown rows.
  static Scene s;
  s.draw(true);
  // The wall's rows: where the depth buffer holds the workpiece (the
  // table lies below the stock, seen edge-on from the front).
  std::vector<Rgb> rows;
  for (int32_t y = 0; y < 150; ++y) {
    const uint32_t z = reinterpret_cast<const uint32_t*>(s.r.target.z + y * s.r.target.z_stride)[100];
    if (z != 0xFFFFFFFFu) rows.push_back(pixel_unpack(PixelFormat::kXrgb8888, s.at(100, y)));
  }
  CHECK_GT(rows.size(), size_t(40));
  if (rows.size() <= 40) return;
  const Rgb top = rows[2], foot = rows[rows.size() - 3];
  auto near = [](Rgb a, Rgb b) {
    return std::abs(int(a.r) - int(b.r)) <= 4 && std::abs(int(a.g) - int(b.g)) <= 4 && std::abs(int(a.b) - int(b.b)) <= 4;
  };
  CHECK(blackish(pixel_pack(PixelFormat::kXrgb8888, top)));
  CHECK(yellowish(pixel_pack(PixelFormat::kXrgb8888, foot)));
  // Every row one of the two: no blend between them.
  int blended = 0, changes = 0;
  for (size_t y = 2; y + 2 < rows.size(); ++y) {
    blended += !near(rows[y], top) && !near(rows[y], foot);
    changes += near(rows[y], top) != near(rows[y - 1], top);
  }
  CHECK_EQ(blended, 0);
  CHECK_EQ(changes, 1);
  t::dump_frame(s.f.fb, "texture-front");
}

TEST(split_walls_leave_no_crack) {
  // The same scene plain and textured: the split side faces cover the same
  // pixels (background where the plain frame has background), up to pixel
  // centres within 1/16 pixel of a wall's outline (split vertices are
  // rounded to q4), and no pinhole: no background pixel whose four
  // neighbours are all workpiece.
  static Scene plain, tex;
  plain.draw(false);
  tex.draw(true);
  int differ = 0, covered = 0, pinholes = 0;
  auto is_bg = [](const Scene& s, int32_t x, int32_t y) { return s.r.target.z && reinterpret_cast<const uint32_t*>(s.r.target.z + y * s.r.target.z_stride)[x] == 0xFFFFFFFFu; };
  for (int32_t y = 1; y < 149; ++y)
    for (int32_t x = 1; x < 199; ++x) {
      const bool a = is_bg(plain, x, y), b = is_bg(tex, x, y);
      covered += !a;
      differ += a != b;
      if (b && !is_bg(tex, x - 1, y) && !is_bg(tex, x + 1, y) && !is_bg(tex, x, y - 1) && !is_bg(tex, x, y + 1)) ++pinholes;
    }
  CHECK_GT(covered, 5000);
  CHECK_LE(differ, covered / 500);
  CHECK_EQ(pinholes, 0);
}

TEST(uncut_tops_are_tinted_apart) {
  // With the stock's top given, the tops the cut never lowered take the
  // tint, the pocket's floor (black too, 6 mm down) does not: seen from
  // above, the uncut rim is lighter with the tint than without, the floor
  // the same. (Compared pixel for pixel: the rim's normals tilt towards the
  // walls either side, which the light shows even on black.)
  static Scene s;
  s.draw(true, 0);
  s.tg.g.dirty = GridRect::none();
  Camera top = renderer_fit(s.r, ViewPreset::kTop);
  renderer_set_camera(&s.r, top);
  render_full(&s.r, &s.tg.g, CutterPose{});
  const Rgb rim0 = pixel_unpack(PixelFormat::kXrgb8888, s.at(100, 15));
  const Rgb floor0 = pixel_unpack(PixelFormat::kXrgb8888, s.at(100, 75));
  static Scene u;
  u.draw(true, uint32_t(s.tg.g.top[s.tg.g.index(2, 2)]));
  renderer_set_camera(&u.r, top);
  render_full(&u.r, &u.tg.g, CutterPose{});
  const Rgb rim = pixel_unpack(PixelFormat::kXrgb8888, u.at(100, 15));
  const Rgb floor = pixel_unpack(PixelFormat::kXrgb8888, u.at(100, 75));
  CHECK_GT(int(rim.r), int(rim0.r) + 30);
  CHECK_LE(std::abs(int(floor.r) - int(floor0.r)), 2);
  CHECK(material_uncut_tint(0x000000) == 0x4B4B4Bu);
  t::dump_frame(u.f.fb, "texture-uncut-top");
}
