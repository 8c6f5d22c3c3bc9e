// Polar coordinates as LinuxCNC reads them; see polar.h.
#include "core/interp/polar.h"

#include "core/gcode/gvalue.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/math/wide.h"

namespace dexmill {

namespace {

constexpr int64_t kFullTurnDegE9 = 360 * kGValueOne;

// The point at distance rho (may be negative: the other way) and angle a.
void point_at(int64_t rho, uint32_t angle_bam, int64_t* px, int64_t* py) {
  const SinCosQ30 sc = sincos_bam(angle_bam);
  constexpr int64_t kOneQ30 = static_cast<int64_t>(1) << 30;
  *px = muldiv_round(rho, sc.cos_q30, kOneQ30);
  *py = muldiv_round(rho, sc.sin_q30, kOneQ30);
}

}  // namespace

int64_t polar_distance(int64_t x, int64_t y) {
  const U128 v = sum_sq_u128(x, y);
  const uint64_t s = isqrt_u128(v);
  // Up when v > (s + 1/2)^2 = s^2 + s + 1/4, i.e. v > s^2 + s.
  const U128 half_up = u128_add(mul_wide_u64(s, s), U128{0, s});
  return static_cast<int64_t>(u128_less(half_up, v) ? s + 1 : s);
}

GcodeError polar_absolute(int64_t x, int64_t y, const PolarWords& w, bool cycle, int64_t* px, int64_t* py,
                          char* word) {
  if (w.has_radius && !w.has_angle && x == 0 && y == 0 && !cycle) {
    *word = '@';
    return GcodeError::kPolarNoAngle;
  }
  const int64_t rho = w.has_radius ? w.radius_nm : polar_distance(x, y);
  const uint32_t angle = w.has_angle ? bam_of_degrees(w.angle_deg_e9) : atan2_bam(y, x);
  point_at(rho, angle, px, py);
  return GcodeError::kOk;
}

GcodeError polar_incremental(int64_t x, int64_t y, const PolarWords& w, int64_t* px, int64_t* py, char* word) {
  int64_t rho = polar_distance(x, y);
  uint32_t angle = atan2_bam(y, x);
  if (w.has_radius) {
    if (rho == 0) {
      *word = '@';
      return GcodeError::kPolarIncrementalOrigin;
    }
    rho += w.radius_nm;
    if (rho < 0) {  // past the origin: the same line, the other side
      rho = -rho;
      angle += kBamHalfTurn;
    }
  }
  if (w.has_angle) {
    if (rho == 0) {
      *word = '^';
      return GcodeError::kPolarIncrementalOrigin;
    }
    angle += bam_of_degrees(w.angle_deg_e9);
  }
  if (!w.has_radius && !w.has_angle) {
    *px = x;
    *py = y;
    return GcodeError::kOk;
  }
  point_at(rho, angle, px, py);
  return GcodeError::kOk;
}

void PolarSeries::init(int64_t x, int64_t y, int64_t dr_nm, int64_t dangle_deg_e9) {
  x0_ = x;
  y0_ = y;
  rho_ = polar_distance(x, y);
  angle0_bam_ = atan2_bam(y, x);
  flip_bam_ = 0;
  dr_ = dr_nm;
  dangle_ = dangle_deg_e9 % kFullTurnDegE9;
  if (dangle_ < 0) dangle_ += kFullTurnDegE9;
  k_ = 0;
}

bool PolarSeries::next(int64_t* px, int64_t* py, char* word) {
  if (dr_ == 0 && dangle_ == 0) {  // @0 ^0: every repeat at the first point
    *px = x0_;
    *py = y0_;
    return true;
  }
  if (rho_ == 0) {
    *word = dr_ != 0 ? '@' : '^';
    return false;
  }
  if (dr_ != 0) {
    rho_ += dr_;
    if (rho_ < 0) {
      rho_ = -rho_;
      flip_bam_ += kBamHalfTurn;
    }
    if (rho_ == 0 && dangle_ != 0) {
      *word = '^';
      return false;
    }
  }
  ++k_;
  // k * angle, reduced exactly: angle < 3.6e11 and k <= 2.5e7 (repeats are
  // at most 1e6) stay in int64.
  const int64_t turned = k_ * dangle_ % kFullTurnDegE9;
  point_at(rho_, angle0_bam_ + flip_bam_ + bam_of_degrees(turned), px, py);
  return true;
}

}  // namespace dexmill
