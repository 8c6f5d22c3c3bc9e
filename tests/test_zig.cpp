// core/cam/zig.h against a double-precision oracle: the chord between
// positions stays above the exact requirement (sampled 24 times a dexel:
// no gouge from the path, to the profile's nm rounding), for balls, flat
// and bull-nose tools on a rough design with steps and spikes; positions
// are tight where nothing raises them; the ladders; the allowance.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <vector>

#include "core/cam/zig.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

// The exact lower surface of the tool r from its axis (r <= R), in nm.
double exact_h(const ToolProfile& p, double r) {
  const double R = double(p.radius_nm);
  switch (p.kind) {
    case ToolKind::kBall: return R - std::sqrt(std::max(0.0, R * R - r * r));
    case ToolKind::kFlat: return 0;
    case ToolKind::kBullNose: {
      const double rc = double(p.corner_nm), flat = R - rc;
      if (r <= flat) return 0;
      const double d = r - flat;
      return rc - std::sqrt(std::max(0.0, rc * rc - d * d));
    }
    default: return 0;
  }
}

struct Design {
  GridGeometry geo{};
  std::vector<int32_t> tops;
  DesignGrid d;
};

// A rough design: a smooth bump field plus random steps and spikes, some
// columns without design.
void make_design(Design* x, int32_t nx, int32_t ny, int64_t pitch_nm, t::Rng* rng) {
  x->geo = GridGeometry{nx, ny, 0, 0, pitch_nm, 0, 500};
  x->tops.assign(size_t(nx) * ny, 0);
  CHECK(ok(design_init(&x->d, x->geo, x->tops.data(), x->tops.size())));
  for (int32_t j = 0; j < ny; ++j)
    for (int32_t i = 0; i < nx; ++i) {
      double z = 10000 + 3000 * std::sin(i * 0.31) * std::cos(j * 0.17);
      if (rng->range(0, 40) == 0) z += double(rng->range(-4000, 6000));
      if ((i / 7 + j / 5) % 4 == 0) z += 1500;
      x->tops[x->d.index(i, j)] = rng->range(0, 60) == 0 ? kNoDesign : int32_t(z);
    }
}

// The exact requirement (nm above z0) with the tip at (tu, v) in pitches
// along the stripe; -inf when no design under the tool.
double exact_need(const Design& x, const ToolProfile& p, bool along_y, double tu, int32_t v) {
  const double pitch = double(x.geo.pitch_nm), R = double(p.radius_nm);
  const int32_t nu = along_y ? x.geo.ny : x.geo.nx, nv = along_y ? x.geo.nx : x.geo.ny;
  double need = -1e300;
  for (int32_t b = -30; b <= 30; ++b)
    for (int32_t a = int32_t(std::floor(tu)) - 30; a <= int32_t(std::floor(tu)) + 30; ++a) {
      if (a < 0 || a >= nu || v + b < 0 || v + b >= nv) continue;
      const double r = std::hypot((a - tu) * pitch, b * pitch);
      if (r > R) continue;
      const int32_t top = x.tops[along_y ? x.d.index(v + b, a) : x.d.index(a, v + b)];
      if (top == kNoDesign) continue;
      need = std::max(need, double(top) * double(x.geo.lsb_nm) - exact_h(p, r));
    }
  return need;
}


}  // namespace

TEST(zig_positions_against_double_oracle) {
  t::Rng rng(23);
  const Tool tools[] = {t::ball_tool(3 * mm), t::ball_tool(6 * mm), t::flat_tool(2 * mm), t::bull_tool(4 * mm, mm)};
  double worst_low = 0, worst_high = 0, worst_dip = 0;
  int checked = 0;
  for (int rep = 0; rep < 8; ++rep) {
    const double dip_before = worst_dip;
    worst_dip = 0;
    Design x;
    make_design(&x, 32, 24, rep % 2 ? 250000 : 400000, &rng);
    const Tool& tool = tools[rep % 4];
    const ToolProfile p = tool_profile(tool);
    std::vector<int32_t> words(zig_tool_words(p, x.geo));
    ZigTool zt;
    CHECK(ok(zig_tool_build(p, x.geo, words.data(), words.size(), &zt)));
    ZigOptions o;
    o.along_y = rep % 3 == 2;
    o.step_dex = 1 + rep % 3;
    o.stepover_dex = 1 + rep % 2;
    std::vector<int64_t> scratch(zig_stripe_scratch(x.d, zt, o)), z(size_t(zig_positions(x.d, o)));
    const double lsb = double(x.geo.lsb_nm);
    for (int32_t s = 0; s < zig_stripe_count(x.d, o); ++s) {
      CHECK(ok(zig_stripe(x.d, zt, o, s, 0, scratch.data(), scratch.size(), z.data())));
      const int32_t v = zig_stripe_row(x.d, o, s);
      for (int32_t k = 0; k < zig_positions(x.d, o); ++k) {
        const int32_t u = zig_position_u(x.d, o, k);
        const double need = std::max(exact_need(x, p, o.along_y, u, v), 0.0);
        const double got = double(z[size_t(k)]) * lsb;
        // Never below the requirement (floored heights: within the
        // profile's own 1 nm rounding).
        worst_low = std::max(worst_low, need - got);
        CHECK_GE(got, need - 2);
        // The chord to the next position, 24 checks a dexel.
        if (k + 1 < zig_positions(x.d, o)) {
          const int32_t u1 = zig_position_u(x.d, o, k + 1);
          const double g1 = double(z[size_t(k) + 1]) * lsb;
          for (int q = 1; q < 24 * (u1 - u); ++q) {
            const double f = q / (24.0 * (u1 - u));
            const double chord = got + (g1 - got) * f;
            const double need_q = std::max(exact_need(x, p, o.along_y, u + f * (u1 - u), v), 0.0);
            worst_dip = std::max(worst_dip, need_q - chord);
            ++checked;
          }
        }
        if (k > 0 && k + 1 < zig_positions(x.d, o)) worst_high = std::max(worst_high, got - need);
      }
    }
    worst_dip = std::max(worst_dip, dip_before);
  }
  // No dip at all but the profile's own rounding.
  CHECK_LE(worst_dip, 3.0);
  std::printf("zig: %d chord checks; worst below requirement %.1f nm, worst chord dip %.1f nm, worst raise %.0f nm\n",
              checked, worst_low, worst_dip, worst_high);
}

TEST(zig_position_is_tight_where_nothing_raises_it) {
  // On a flat design a position is exactly the top (a ball touches it with
  // its tip), and a single spike raises every position whose tool covers
  // it to the spike's top less the ball's height there, floored to LSB.
  Design x;
  x.geo = GridGeometry{32, 20, 0, 0, 500000, 0, 500};
  x.tops.assign(32 * 20, 20000);
  CHECK(ok(design_init(&x.d, x.geo, x.tops.data(), x.tops.size())));
  for (int32_t& t : x.tops) t = 20000;
  x.tops[x.d.index(16, 10)] = 26000;  // a spike 3 mm high
  const ToolProfile p = tool_profile(t::ball_tool(4 * mm));
  std::vector<int32_t> words(zig_tool_words(p, x.geo));
  ZigTool zt;
  CHECK(ok(zig_tool_build(p, x.geo, words.data(), words.size(), &zt)));
  // What an interval asks at its ends (LSB): exact but for the convexity
  // bound (2 h'' (pitch / 16)^2: 2 LSB here) and flooring.
  auto need = [&](bool along_y, int32_t u, int32_t v, int32_t k, bool right) {
    int64_t l, r;
    zig_interval_need(x.d, zt, along_y, u, v, k, &l, &r);
    return right ? r : l;
  };
  CHECK_GE(need(false, 2, 2, 0, false), 20000);
  CHECK_LE(need(false, 2, 2, 0, false), 20003);
  CHECK_GE(need(false, 16, 10, 0, false), 26000);
  CHECK_LE(need(false, 16, 10, 0, false), 26003);
  // One pitch (0.5 mm) off: h = 2 - sqrt(4 - 0.25) mm = 63 508 nm = 127.0 LSB.
  const double h = 2e6 - std::sqrt(4e12 - 0.25e12);
  for (bool along_y : {false, true}) {
    const int64_t got = along_y ? need(true, 10, 15, 0, false) : need(false, 15, 10, 0, false);
    CHECK_GE(got, 26000 - int64_t(std::floor(h / 500)));
    CHECK_LE(got, 26000 - int64_t(std::floor(h / 500)) + 3);
  }
  // Half a pitch past 15 (the end of interval 7 of 16): 0.25 mm off.
  const double h2 = 2e6 - std::sqrt(4e12 - 0.0625e12);
  CHECK_GE(need(false, 15, 10, 7, true), 26000 - int64_t(std::floor(h2 / 500)));
  CHECK_LE(need(false, 15, 10, 7, true), 26000 - int64_t(std::floor(h2 / 500)) + 3);
  // Beyond the radius nothing but the floor.
  CHECK_LE(need(false, 16, 5, 0, false), 20003);
  // The allowance lifts every position by its LSB, rounded up.
  ZigOptions o;
  o.allowance_nm = 300000 + 1;
  std::vector<int64_t> scratch(zig_stripe_scratch(x.d, zt, o)), z(size_t(zig_positions(x.d, o)));
  CHECK(ok(zig_stripe(x.d, zt, o, 2, 0, scratch.data(), scratch.size(), z.data())));
  CHECK_GE(z[0], 20000 + 601);
  CHECK_LE(z[0], 20000 + 601 + 3);
  // Ladders: 32 dexels at step 3 give 0, 3, ..., 30 and 31.
  o.step_dex = 3;
  CHECK_EQ(zig_positions(x.d, o), 12);
  CHECK_EQ(zig_position_u(x.d, o, 11), 31);
  CHECK_EQ(zig_position_u(x.d, o, 10), 30);
  o.stepover_dex = 4;
  CHECK_EQ(zig_stripe_count(x.d, o), 6);  // rows 0, 4, ..., 16, 19
  CHECK_EQ(zig_stripe_row(x.d, o, 5), 19);
  // Too little memory.
  CHECK(zig_tool_build(p, x.geo, words.data(), words.size() - 1, &zt) == Status::kBufferTooSmall);
  CHECK(zig_stripe(x.d, zt, o, 0, 0, scratch.data(), 1, z.data()) == Status::kBufferTooSmall);
}
