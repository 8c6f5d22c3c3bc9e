// core/tool/tool.h and core/tool/cutter.h: each cutter shape's dexel set against a
// double-precision ray-cast oracle, every dexel within 1 LSB (the stated
// bound is 0.5 LSB + 1 nm).
#include <cmath>
#include <vector>

#include "core/math/fixed.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

double oracle_profile_nm(const Tool& t, double r) {
  const double R = static_cast<double>(t.diameter_nm / 2);
  switch (t.kind) {
    case ToolKind::kFlat: return 0;
    case ToolKind::kBall: return R - std::sqrt(std::max(0.0, R * R - r * r));
    case ToolKind::kBullNose: {
      const double rc = static_cast<double>(t.corner_radius_nm), f = R - rc;
      if (r <= f) return 0;
      return rc - std::sqrt(std::max(0.0, rc * rc - (r - f) * (r - f)));
    }
    case ToolKind::kVBit: {
      const double half = t.tip_angle_mdeg / 1000.0 / 2.0 * 3.14159265358979323846 / 180.0;
      return r / std::tan(half);
    }
  }
  return 0;
}

Tool make(ToolKind k, int64_t d_nm, int64_t rc_nm = 0, int32_t mdeg = 0) {
  Tool t;
  t.kind = k;
  t.diameter_nm = d_nm;
  t.corner_radius_nm = rc_nm;
  t.tip_angle_mdeg = mdeg;
  t.length_nm = 50 * kNmPerMm;
  t.flute_length_nm = 20 * kNmPerMm;
  return t;
}

void check_against_oracle(const Tool& t, int64_t pitch_nm, int64_t lsb_nm) {
  CHECK_EQ(tool_check(t), Status::kOk);
  ToolProfile p = tool_profile(t);
  std::vector<int32_t> words(cutter_storage_words(cutter_reach_dex(p, pitch_nm)));
  CutterDexels c;
  if (!CHECK_EQ(cutter_build(p, pitch_nm, lsb_nm, words.data(), words.size(), &c), Status::kOk)) return;
  const int64_t R = t.diameter_nm / 2;
  CHECK_EQ(c.reach_dex, static_cast<int32_t>(R / pitch_nm));
  const int32_t k = c.reach_dex;
  int hits = 0;
  for (int32_t dj = -k; dj <= k; ++dj) {
    for (int32_t di = -k; di <= k; ++di) {
      const int64_t x = di * pitch_nm, y = dj * pitch_nm;
      const bool hit = x * x + y * y <= R * R;  // exact integer test
      const int32_t col = di + k, row = dj + k;
      const bool in_span = col >= c.row_lo[row] && col <= c.row_hi[row];
      if (!CHECK_EQ(in_span, hit)) return;
      if (!hit) continue;
      ++hits;
      const double r = std::sqrt(static_cast<double>(x) * x + static_cast<double>(y) * y);
      const double want = oracle_profile_nm(t, r) / lsb_nm;
      const size_t idx = static_cast<size_t>(row) * c.side + col;
      if (!CHECK_NEAR(static_cast<double>(c.bottom_lsb[idx]), want, 1.0)) return;
      CHECK_NEAR(static_cast<double>(c.bottom_lsb[idx]), want, 0.5 + 1.0 / lsb_nm + 1e-9);
      CHECK_EQ(c.top_lsb[idx], static_cast<int32_t>((t.length_nm + lsb_nm / 2) / lsb_nm));
    }
  }
  CHECK_GT(hits, 0);
}

}  // namespace

TEST(cutter_ball_against_oracle) {
  for (int64_t lsb : {1, 37, 1000, 100000}) {
    check_against_oracle(make(ToolKind::kBall, 6 * kNmPerMm), 500000, lsb);
    check_against_oracle(make(ToolKind::kBall, 6 * kNmPerMm), 100000, lsb);
    check_against_oracle(make(ToolKind::kBall, 3175000), 123457, lsb);  // 1/8 inch, odd pitch
  }
  // The paper's cutters: 9, 12 and 6 dexels across.
  check_against_oracle(make(ToolKind::kBall, 9 * kNmPerMm), kNmPerMm, 1000);
  check_against_oracle(make(ToolKind::kBall, 12 * kNmPerMm), kNmPerMm, 1000);
  check_against_oracle(make(ToolKind::kBall, 6 * kNmPerMm), kNmPerMm, 1000);
}

TEST(cutter_flat_against_oracle) {
  check_against_oracle(make(ToolKind::kFlat, 6 * kNmPerMm), 250000, 1000);
  check_against_oracle(make(ToolKind::kFlat, 1 * kNmPerMm), 10000, 7);
}

TEST(cutter_bullnose_against_oracle) {
  for (int64_t lsb : {1, 1000, 20000}) {
    check_against_oracle(make(ToolKind::kBullNose, 10 * kNmPerMm, 2 * kNmPerMm), 250000, lsb);
    check_against_oracle(make(ToolKind::kBullNose, 10 * kNmPerMm, 5 * kNmPerMm), 99991, lsb);  // rc = R: a ball
    check_against_oracle(make(ToolKind::kBullNose, 6350000, 793750), 50000, lsb);
  }
}

TEST(cutter_vbit_against_oracle) {
  for (int32_t mdeg : {60000, 90000, 30000, 120000, 10000, 179000}) {
    check_against_oracle(make(ToolKind::kVBit, 6 * kNmPerMm, 0, mdeg), 200000, 1000);
    check_against_oracle(make(ToolKind::kVBit, 6 * kNmPerMm, 0, mdeg), 77777, 10);
  }
}

TEST(tool_check_limits) {
  CHECK_EQ(tool_check(make(ToolKind::kBall, 0)), Status::kBadArgument);
  CHECK_EQ(tool_check(make(ToolKind::kBall, 2000 * kNmPerMm)), Status::kBadArgument);
  CHECK_EQ(tool_check(make(ToolKind::kBullNose, 6 * kNmPerMm, 0)), Status::kBadArgument);
  CHECK_EQ(tool_check(make(ToolKind::kBullNose, 6 * kNmPerMm, 4 * kNmPerMm)), Status::kBadArgument);
  CHECK_EQ(tool_check(make(ToolKind::kVBit, 6 * kNmPerMm, 0, 0)), Status::kBadArgument);
  CHECK_EQ(tool_check(make(ToolKind::kVBit, 6 * kNmPerMm, 0, 180000)), Status::kBadArgument);
  Tool shortv = make(ToolKind::kVBit, 20 * kNmPerMm, 0, 10000);  // cone 114 mm tall, tool 50 mm long
  CHECK_EQ(tool_check(shortv), Status::kBadArgument);
  Tool neg = make(ToolKind::kFlat, 6 * kNmPerMm);
  neg.flute_length_nm = -1;
  CHECK_EQ(tool_check(neg), Status::kBadArgument);
}

TEST(cutter_build_limits) {
  ToolProfile p = tool_profile(make(ToolKind::kBall, 6 * kNmPerMm));
  int32_t words[16];
  CutterDexels c;
  CHECK_EQ(cutter_build(p, kNmPerMm, 1000, words, 16, &c), Status::kBufferTooSmall);
  CHECK_EQ(cutter_build(p, 1, 1000, words, 16, &c), Status::kToolTooLarge);
  CHECK_EQ(cutter_build(p, 0, 1000, words, 16, &c), Status::kBadArgument);
  ToolProfile tiny = tool_profile(make(ToolKind::kFlat, kNmPerUm));
  CHECK_EQ(cutter_build(tiny, kNmPerMm, 1000, words, 16, &c), Status::kOk);  // one dexel
  CHECK_EQ(c.reach_dex, 0);
  CHECK_EQ(c.row_lo[0], 0);
  CHECK_EQ(c.row_hi[0], 0);
}
