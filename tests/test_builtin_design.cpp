// core/design/builtin.h: the paper's four workpieces as built-in design
// parts. Every column filled inside [floor, stock top]; the table's API; a
// few structural facts per design that a broken drawing would lose. With
// DEXMILL_TEST_IMAGES=DIR each design is written as DIR/builtin-NAME.pgm
// (16-bit heights, white = the stock's top, row 0 = largest Y) to look at.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/design/builtin.h"
#include "core/design/builtin_font.h"
#include "core/design/builtin_shape.h"
#include "core/material/material_preset.h"
#include "display/overlay/font.h"
#include "platform/format/pgm.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = 1000000;

// A builtin's design grid at m = 16 bits, filled.
struct Filled {
  const BuiltinDesign* b = nullptr;
  std::vector<int32_t> top;
  DesignGrid d;

  explicit Filled(const char* name, int bits = 16) : b(builtin_design_find(name)) {
    if (!CHECK(b)) return;
    const GridGeometry geo = builtin_geometry(*b, bits);
    top.assign(static_cast<size_t>(geo.nx) * geo.ny, 0);
    CHECK(ok(design_init(&d, geo, top.data(), top.size())));
    CHECK(ok(builtin_design_fill(*b, &d)));
  }
  int32_t at(int32_t i, int32_t j) const { return top[d.index(i, j)]; }
  // The top over machine (x, y) in mm (the nearest dexel's).
  int32_t at_mm(double x_mm, double y_mm) const {
    const double p = static_cast<double>(b->pitch_nm) / kMm;
    return at(static_cast<int32_t>(x_mm / p + 0.5), static_cast<int32_t>(y_mm / p + 0.5));
  }
  int32_t lsb_of(int64_t z_nm) const { return static_cast<int32_t>((z_nm + d.geo.lsb_nm / 2) / d.geo.lsb_nm); }
};

void dump_pgm(const Filled& f) {
  const char* dir = std::getenv("DEXMILL_TEST_IMAGES");
  if (!dir || !*dir) return;
  const int32_t nx = f.d.geo.nx, ny = f.d.geo.ny;
  const int64_t full = f.lsb_of(f.b->stock_height_nm);
  std::vector<uint16_t> s(static_cast<size_t>(nx) * ny);
  for (int32_t row = 0; row < ny; ++row)
    for (int32_t i = 0; i < nx; ++i)
      s[static_cast<size_t>(row) * nx + i] = static_cast<uint16_t>(int64_t{f.at(i, ny - 1 - row)} * 65535 / full);
  char path[1024], err[256];
  std::snprintf(path, sizeof path, "%s/builtin-%s.pgm", dir, f.b->name);
  CHECK(write_pgm16(path, nx, ny, s.data(), err, sizeof err));
}

}  // namespace

TEST(builtin_table) {
  CHECK_EQ(builtin_design_count(), 4);
  const char* names[] = {"panel", "smiley", "freeform", "tsuba"};
  for (int32_t k = 0; k < 4; ++k) {
    const BuiltinDesign& b = builtin_design_at(k);
    CHECK(std::strcmp(b.name, names[k]) == 0);
    CHECK_EQ(builtin_design_find(names[k]), &b);
    CHECK(b.about && std::strlen(b.about) > 10);
    CHECK(b.ball_dexels > 0);
    CHECK(b.floor_nm >= 2 * kMm);  // the part stands on a floor of the block
    CHECK_LT(b.floor_nm, b.stock_height_nm);
    StockComposition c;
    CHECK(material_preset(b.material, BoxNm{{0, 0, 0}, {b.nx * b.pitch_nm, b.ny * b.pitch_nm, b.stock_height_nm}}, &c));
    for (int bits : {8, 16, 32}) CHECK(ok(grid_check_geometry(builtin_geometry(b, bits))));
  }
  CHECK(builtin_design_find("smile") == nullptr);
  CHECK(builtin_design_find("panels") == nullptr);
  CHECK(builtin_design_find("") == nullptr);
  CHECK(builtin_design_find(nullptr) == nullptr);
  CHECK_EQ(&builtin_design_at(-1), &builtin_design_at(0));
  CHECK_EQ(&builtin_design_at(4), &builtin_design_at(0));
}

TEST(builtin_paper_sizes) {
  // Table 2's resolutions and ball sizes in dexels; the paper's materials.
  const BuiltinDesign& panel = *builtin_design_find("panel");
  const BuiltinDesign& smiley = *builtin_design_find("smiley");
  const BuiltinDesign& freeform = *builtin_design_find("freeform");
  CHECK_EQ(panel.nx, 80); CHECK_EQ(panel.ny, 40); CHECK_EQ(panel.ball_dexels, 9);
  CHECK_EQ(smiley.nx, 128); CHECK_EQ(smiley.ny, 128); CHECK_EQ(smiley.ball_dexels, 12);
  CHECK_EQ(freeform.nx, 256); CHECK_EQ(freeform.ny, 256); CHECK_EQ(freeform.ball_dexels, 6);
  CHECK(std::strcmp(smiley.material, "two-layer") == 0);
  CHECK(std::strcmp(freeform.material, "marble") == 0);
  CHECK(std::strcmp(builtin_design_find("tsuba")->material, "bronze") == 0);
  // The LSB leaves a quarter of the stock's height of headroom.
  const GridGeometry g = builtin_geometry(panel, 16);
  CHECK_EQ(g.x0_nm, 0); CHECK_EQ(g.y0_nm, 0); CHECK_EQ(g.z0_nm, 0);
  CHECK_EQ(g.lsb_nm, lsb_for_range(panel.stock_height_nm * 5 / 4, 16));
}

TEST(builtin_fill_every_column_in_range) {
  for (int32_t k = 0; k < builtin_design_count(); ++k) {
    for (int bits : {8, 16, 32}) {
      Filled f(builtin_design_at(k).name, bits);
      const int32_t lo = f.lsb_of(f.b->floor_nm), hi = f.lsb_of(f.b->stock_height_nm);
      int32_t mn = INT32_MAX, mx = INT32_MIN;
      for (int32_t t : f.top) mn = t < mn ? t : mn, mx = t > mx ? t : mx;
      CHECK_GE(mn, lo);
      CHECK_LE(mx, hi);
      CHECK_LT(mx, hi);  // everything is milled: no column keeps the block's top
      CHECK_LT(mn, mx);
      if (bits == 16) dump_pgm(f);
      // Column by column gives the same tops as the fill.
      for (int32_t j = 0; j < f.d.geo.ny; j += 7)
        for (int32_t i = 0; i < f.d.geo.nx; i += 5) CHECK_EQ(builtin_top_lsb(*f.b, f.d.geo, i, j), f.at(i, j));
    }
  }
}

TEST(builtin_fill_rejects_other_geometry) {
  const BuiltinDesign& b = *builtin_design_find("panel");
  GridGeometry g = builtin_geometry(b, 16);
  std::vector<int32_t> mem(static_cast<size_t>(g.nx + 1) * g.ny);
  DesignGrid d;
  const GridGeometry good = g;
  g.nx += 1;
  CHECK(ok(design_init(&d, g, mem.data(), mem.size())));
  CHECK_EQ(builtin_design_fill(b, &d), Status::kBadArgument);
  g = good;
  g.pitch_nm += 1;
  CHECK(ok(design_init(&d, g, mem.data(), mem.size())));
  CHECK_EQ(builtin_design_fill(b, &d), Status::kBadArgument);
  g = good;
  g.x0_nm = -g.pitch_nm;
  CHECK(ok(design_init(&d, g, mem.data(), mem.size())));
  CHECK_EQ(builtin_design_fill(b, &d), Status::kBadArgument);
  // Another z0 and LSB are fine: the tops follow them.
  g = good;
  g.z0_nm = -kMm;
  g.lsb_nm = 1000;
  CHECK(ok(design_init(&d, g, mem.data(), mem.size())));
  CHECK(ok(builtin_design_fill(b, &d)));
  CHECK_EQ(d.top_lsb[0], 10000);  // the rim, 9 mm up: 10 mm above z0 in um
}

TEST(builtin_font_is_the_display_font) {
  for (const char* c = "DEXMIL"; *c; ++c)
    for (int32_t row = 0; row < kGlyphRows; ++row)
      for (int32_t col = 0; col < kGlyphCols; ++col) {
        const char s[2] = {*c, 0};
        CHECK_EQ(text_ink(s, col, row), ((font_glyph(*c)[row] >> (4 - col)) & 1) != 0);
      }
  CHECK_EQ(text_cols("DEXMILL"), 41);
  CHECK(!text_ink("I", 5, 0));
  CHECK(!text_ink("I", 2, 7));
  CHECK(!text_ink("I", -1, 0));
}

namespace {

// The design's height over (x, y) in mm, nm (the function itself, so that
// features narrower than a dexel are probed where they are).
int64_t height_at(const BuiltinDesign& b, double x_mm, double y_mm) {
  return b.height_nm(static_cast<int64_t>(x_mm * kMm + (x_mm < 0 ? -0.5 : 0.5)),
                     static_cast<int64_t>(y_mm * kMm + (y_mm < 0 ? -0.5 : 0.5)));
}

}  // namespace

TEST(builtin_panel_structure) {
  Filled f("panel");
  const BuiltinDesign& b = *f.b;
  const int64_t rim = height_at(b, 0.2, 0.2), face = height_at(b, 3, 10);
  const int64_t ring = height_at(b, 10 + 5.4, 11.75), dial = height_at(b, 10, 11.75 - 2.5);
  const int64_t ring2 = height_at(b, 29.5 - 5.4, 11.75), dial2 = height_at(b, 29.5, 11.75 - 2.5);
  CHECK_GT(rim, ring);
  CHECK_GT(ring, face);
  CHECK_GT(face, dial);
  CHECK_EQ(ring2, ring);
  CHECK_EQ(dial2, dial);
  CHECK_EQ(dial, b.floor_nm);
  // The rim runs all round; the face inside it.
  for (double x = 0; x < 39.5; x += 0.5) { CHECK_EQ(height_at(b, x, 0), rim); CHECK_EQ(height_at(b, x, 19.5), rim); }
  for (double y = 0; y < 19.5; y += 0.5) { CHECK_EQ(height_at(b, 0, y), rim); CHECK_EQ(height_at(b, 39.5, y), rim); }
  // The needles stand on the dials, narrower than the 4.5 mm ball: the left
  // one points up-left (150 degrees), the right one up-right (55).
  CHECK_GT(height_at(b, 10 - 2.6, 11.75 + 1.5), dial);
  CHECK_EQ(height_at(b, 10 + 2.6, 11.75 + 1.5), dial);
  CHECK_GT(height_at(b, 29.5 + 1.72, 11.75 + 2.46), dial2);
  // A button's dome is above the face.
  CHECK_GT(height_at(b, 19.75, 11.75), face);
  // "DEXMILL" engraved: exactly its inked font pixels are below the face
  // in the lettering's box (dexels 19..59 x 4..10).
  int32_t engraved = 0, inked = 0;
  for (int32_t j = 4; j <= 10; ++j)
    for (int32_t i = 19; i <= 59; ++i) {
      const bool ink = text_ink("DEXMILL", i - 19, 10 - j);
      inked += ink;
      engraved += f.at(i, j) < f.lsb_of(face);
      CHECK_EQ(f.at(i, j) < f.lsb_of(face), ink);
    }
  CHECK_EQ(engraved, inked);
  CHECK_GT(inked, 60);
}

TEST(builtin_smiley_cuts_through_the_black) {
  Filled f("smiley");
  const BuiltinDesign& b = *f.b;
  // The two-layer preset's boundary (black above, yellow below): half the
  // block's height (paper eq. 4).
  StockComposition c;
  CHECK(material_preset(b.material, BoxNm{{0, 0, 0}, {64 * kMm, 64 * kMm, b.stock_height_nm}}, &c));
  const int64_t boundary = c.materials[0].texture.layers.boundary_z_nm[0];
  CHECK_EQ(boundary, b.stock_height_nm / 2);
  const double cx = 31.75, cy = 31.75;
  CHECK_LT(height_at(b, cx - 9.5, cy + 8.5), boundary);  // the eyes
  CHECK_LT(height_at(b, cx + 9.5, cy + 8.5), boundary);
  CHECK_LT(height_at(b, cx, cy + 3 - 15.5), boundary);   // the mouth's lowest point
  CHECK_LT(height_at(b, cx - 12, cy - 5), boundary);     // and along it
  CHECK_LT(height_at(b, cx + 12, cy - 5), boundary);
  CHECK_GT(height_at(b, cx, cy), boundary);              // the face between them stays black
  CHECK_GT(height_at(b, 1, 1), boundary);                // and the ground round it
  CHECK_GT(height_at(b, cx, cy + 24), height_at(b, 1, 1));  // the face is raised
  // Only eyes and mouth show yellow: every column below the boundary is at
  // the cut floor, and they cover about the eyes' and mouth's area
  // (2 x pi 4.5 x 6.5 + 9 x 15.5 x 130 deg + pi 4.5^2 = 564 mm^2).
  int32_t yellow = 0;
  for (int32_t t : f.top)
    if (static_cast<int64_t>(t) * f.d.geo.lsb_nm < boundary) {
      ++yellow;
      CHECK_EQ(t, f.lsb_of(b.floor_nm));
    }
  CHECK_NEAR(yellow * 0.25, 564.0, 25.0);
  // The eyebrows are grooves in the black, narrower than the 6 mm ball.
  const int64_t brow = height_at(b, cx - 9.5, cy + 8.5 + 10);
  CHECK_LT(brow, height_at(b, cx - 9.5, cy + 8.5 + 11.5));
  CHECK_GT(brow, boundary);
}

TEST(builtin_freeform_is_smooth) {
  Filled f("freeform");
  const GridGeometry& g = f.d.geo;
  // Slope under 1 (45 degrees) between neighbours, and second differences
  // within the documented curvature bound, 0.15/mm, plus 2 LSB of rounding:
  // a 1.5 mm ball radius is far inside every concave radius (6.5 mm).
  const double pitch_mm = static_cast<double>(g.pitch_nm) / kMm, lsb_mm = static_cast<double>(g.lsb_nm) / kMm;
  const double curv_lsb = 0.15 * pitch_mm * pitch_mm / lsb_mm + 2;
  int64_t max_step = 0;
  double max_curv = 0;
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) {
      if (i + 1 < g.nx) max_step = std::max<int64_t>(max_step, std::llabs(f.at(i + 1, j) - f.at(i, j)));
      if (j + 1 < g.ny) max_step = std::max<int64_t>(max_step, std::llabs(f.at(i, j + 1) - f.at(i, j)));
      if (i > 0 && i + 1 < g.nx) max_curv = std::max<double>(max_curv, std::abs(f.at(i + 1, j) - 2 * f.at(i, j) + f.at(i - 1, j)));
      if (j > 0 && j + 1 < g.ny) max_curv = std::max<double>(max_curv, std::abs(f.at(i, j + 1) - 2 * f.at(i, j) + f.at(i, j - 1)));
    }
  CHECK_LT(max_step * g.lsb_nm, g.pitch_nm);
  CHECK_LE(max_curv, curv_lsb);
  int32_t mn = INT32_MAX, mx = INT32_MIN;
  for (int32_t t : f.top) mn = std::min(mn, t), mx = std::max(mx, t);
  CHECK_GT((mx - mn) * g.lsb_nm, 12 * kMm);  // hills, not a plate
}

TEST(builtin_tsuba_structure) {
  Filled f("tsuba");
  const BuiltinDesign& b = *f.b;
  const double c = 38.2;
  const int64_t plate = height_at(b, c + 10.6, c + 10.6);
  CHECK_EQ(height_at(b, c, c), b.floor_nm);             // the nakago-ana is a recess to the floor
  CHECK_EQ(height_at(b, c, c - 6), b.floor_nm);         // down to its narrow foot
  CHECK_EQ(height_at(b, c, c + 7.2), b.floor_nm);       // and its round top
  CHECK_GT(height_at(b, c + 2.0, c - 6), b.floor_nm);   // narrower at the foot
  CHECK_EQ(height_at(b, c - 11.5, c), b.floor_nm);      // kozuka-hitsu
  CHECK_EQ(height_at(b, c + 11.5, c), b.floor_nm);      // kogai-hitsu
  CHECK_EQ(height_at(b, c + 10, c), plate);             // its tongue
  CHECK_GT(height_at(b, c, c + 10), plate);             // the seppa-dai, raised
  CHECK_GT(height_at(b, c, c + 34.25), plate);          // the rim
  CHECK_GT(height_at(b, c, c + 34.25), height_at(b, c + 20.6, c + 20.6));  // above the petals
  CHECK_EQ(height_at(b, 0, 0), b.floor_nm);             // the block's corners
  CHECK_EQ(height_at(b, c + 37, c), b.floor_nm);        // beyond the plate
  // A petal on the 22.5-degree axis: domed, its vein lower than its flanks.
  const double ca = 0.92387953, sa = 0.38268343;
  const int64_t vein = height_at(b, c + 25 * ca, c + 25 * sa);
  const int64_t flank = height_at(b, c + 25 * ca - 1.0 * sa, c + 25 * sa + 1.0 * ca);
  CHECK_GT(flank, plate);
  CHECK_LT(vein, flank);
  CHECK_GT(vein, plate);
  // Eight petals alike: the rotations by 90 degrees give the same heights
  // (the other diagonals are mirror images through the off-centre slot,
  // not tested).
  CHECK_EQ(height_at(b, c - 25 * sa, c + 25 * ca), vein);
  // A bead between two petals (on the 45-degree line).
  CHECK_GT(height_at(b, c + 29 * 0.70710678, c + 29 * 0.70710678), plate);
}

// The shape kit against a double oracle, within each function's stated
// bound (core/design/builtin_shape.h), over the sizes the designs use
// (up to 128 mm) and beyond.
TEST(builtin_shape_kit_bounds) {
  t::Rng rng(23);
  const double q30 = 1073741824.0, pi = 3.14159265358979323846;
  for (int n = 0; n < 20000; ++n) {
    const int64_t span = rng.range(0, 1) ? 200 * kMm : 2 * kMm;
    const int64_t ax = rng.range(1000, span), ay = rng.range(1000, span);
    const int64_t dx = rng.range(-2 * span, 2 * span), dy = rng.range(-2 * span, 2 * span);
    const double e = std::pow(double(dx) / ax, 2) + std::pow(double(dy) / ay, 2);
    if (e < 3.99) CHECK_NEAR(ellipse_q30(dx, dy, ax, ay), e * q30, 1.0);
    else CHECK_GE(ellipse_q30(dx, dy, ax, ay), static_cast<int64_t>(3.98 * q30));
    const int64_t u = rng.range(-1000, kQ30One + 1000);
    const double v = 1.0 - std::max(0.0, u / q30);
    CHECK_NEAR(bump_q30(u), u >= kQ30One ? 0.0 : v * v * v * q30, 2.0);
    const int64_t h = rng.range(-(int64_t{1} << 31) + 1, (int64_t{1} << 31) - 1), f = rng.range(-4 * kQ30One, 4 * kQ30One);
    CHECK_NEAR(scale_nm(h, f), double(h) * f / q30, 0.5);
    const int64_t r = rng.range(1, span), sd = rng.range(-2 * r, 2 * r);
    CHECK_NEAR(round_profile_nm(sd, r), std::llabs(sd) < r ? std::sqrt(double(r) * r - double(sd) * sd) : 0.0, 0.5);
    // Segments, including degenerate and very short ones.
    const int64_t x0 = rng.range(-span, span), y0 = rng.range(-span, span);
    const int64_t x1 = rng.range(0, 3) ? rng.range(-span, span) : x0 + rng.range(-2, 2), y1 = rng.range(-span, span);
    const int64_t px = rng.range(-span, span), py = rng.range(-span, span);
    const double bx = double(x1 - x0), by = double(y1 - y0), len2 = bx * bx + by * by;
    double tt = len2 > 0 ? ((px - x0) * bx + (py - y0) * by) / len2 : 0;
    tt = std::min(1.0, std::max(0.0, tt));
    CHECK_NEAR(segment_distance_nm(px, py, x0, y0, x1, y1), std::hypot(px - (x0 + tt * bx), py - (y0 + tt * by)), 1.0);
    // Phases and sines.
    const int64_t period = rng.range(1000, span), x = rng.range(-100 * span, 100 * span);
    double ph = std::fmod(double(x), double(period));
    if (ph < 0) ph += period;
    const double bam = ph / period * 4294967296.0;
    const uint32_t got = phase_bam(x, period);
    const double dbam = std::remainder(double(got) - bam, 4294967296.0);
    CHECK_LE(std::abs(dbam), 0.5 + 1e-6);
    const int64_t amp = rng.range(-span, span);
    CHECK_NEAR(sine_nm(amp, got), amp * std::sin(double(got) / 4294967296.0 * 2 * pi), 0.5 + 2e-9 * std::abs(double(amp)));
    // Arcs: the distance to the arc's points, by dense sampling's closed form.
    const int64_t ar = rng.range(1000, span / 2);
    const uint32_t a0 = static_cast<uint32_t>(rng.next()), a1 = static_cast<uint32_t>(rng.next());
    const int64_t qx = rng.range(-span / 2, span / 2), qy = rng.range(-span / 2, span / 2);
    const double th0 = a0 / 4294967296.0 * 2 * pi, sweep = static_cast<uint32_t>(a1 - a0) / 4294967296.0 * 2 * pi;
    double th = std::atan2(double(qy), double(qx)) - th0;
    th = std::fmod(th + 4 * pi, 2 * pi);
    double want;
    if (th <= sweep) want = std::abs(std::hypot(double(qx), double(qy)) - ar);
    else want = std::min(std::hypot(qx - ar * std::cos(th0), qy - ar * std::sin(th0)),
                         std::hypot(qx - ar * std::cos(th0 + sweep), qy - ar * std::sin(th0 + sweep)));
    CHECK_NEAR(arc_distance_nm(qx, qy, ar, a0, a1), want, 2.0 + 4e-9 * ar);
  }
  // Rounded rectangles: corners cut on the radius, edges kept.
  CHECK(in_rounded_rect(0, 5, 0, 0, 10, 10, 3));
  CHECK(!in_rounded_rect(0, 0, 0, 0, 10, 10, 3));
  CHECK(in_rounded_rect(1, 1, 0, 0, 10, 10, 2));   // (1,1) is sqrt(2) from the corner centre (2,2)
  CHECK(!in_rounded_rect(1, 0, 0, 0, 10, 10, 3));  // 2^2 + 3^2 = 13 > 3^2 from the corner centre (3,3)
  CHECK(!in_rounded_rect(11, 5, 0, 0, 10, 10, 3));
}
