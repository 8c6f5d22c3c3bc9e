// Arc and helix chord stepping; see arc_chords.h for the bound.
#include "core/canon/arc_chords.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/math/wide.h"

namespace dexmill {

int64_t plane_a(Plane p, const PointNm& v) { return p == Plane::kXY ? v.x_nm : p == Plane::kZX ? v.z_nm : v.y_nm; }
int64_t plane_b(Plane p, const PointNm& v) { return p == Plane::kXY ? v.y_nm : p == Plane::kZX ? v.x_nm : v.z_nm; }
int64_t plane_c(Plane p, const PointNm& v) { return p == Plane::kXY ? v.z_nm : p == Plane::kZX ? v.y_nm : v.x_nm; }
PointNm plane_point(Plane p, int64_t a, int64_t b, int64_t c) {
  if (p == Plane::kXY) return PointNm{a, b, c};
  if (p == Plane::kZX) return PointNm{b, c, a};
  return PointNm{c, a, b};
}

namespace {

constexpr int64_t kTurnBam = static_cast<int64_t>(1) << 32;
constexpr uint32_t kMaxChords = 0x7fffffffu;

// r * q30 / 2^30 rounded (half up), exact for any r.
int64_t scale_q30(int64_t r, int32_t q) {
  if (r < (static_cast<int64_t>(1) << 32)) {
    int64_t p = r * q;
    return (p + (static_cast<int64_t>(1) << 29)) >> 30;
  }
  return muldiv_round(r, q, static_cast<int64_t>(1) << 30);
}

// Largest chord angle whose sagitta on radius r is <= s: 2 acos(1 - s/r),
// less a margin for CORDIC, capped at a quarter turn.
int64_t max_chord_bam(int64_t r, int64_t s) {
  if (s >= r) return kBamQuarterTurn;
  // Half chord c = sqrt(2rs - s^2); half angle = atan2(c, r - s).
  U128 two_rs = mul_wide_u64(static_cast<uint64_t>(2 * r), static_cast<uint64_t>(s));
  int64_t c = static_cast<int64_t>(isqrt_u128(sub_u128(two_rs, sq_u128(s))));
  int64_t half = atan2_bam(c, r - s);
  int64_t theta = 2 * half - 8;
  if (theta > kBamQuarterTurn) theta = kBamQuarterTurn;
  if (theta < 1) theta = 1;
  return theta;
}

}  // namespace

void ArcChords::init(const CanonRecord& arc, int64_t max_sagitta_nm) {
  plane_ = arc.arc.plane;
  end_ = arc.end;
  ca_ = plane_a(plane_, arc.arc.centre);
  cb_ = plane_b(plane_, arc.arc.centre);
  const int64_t sa = plane_a(plane_, arc.start) - ca_, sb = plane_b(plane_, arc.start) - cb_;
  const int64_t ea = plane_a(plane_, arc.end) - ca_, eb = plane_b(plane_, arc.end) - cb_;
  c0_ = plane_c(plane_, arc.start);
  dc_ = plane_c(plane_, arc.end) - c0_;
  r0_ = hypot_floor(sa, sb);
  const int64_t r1 = hypot_floor(ea, eb);
  dr_ = r1 - r0_;
  a0_ = atan2_bam(sb, sa);
  const uint32_t a1 = atan2_bam(eb, ea);
  dir_ = arc.arc.turns < 0 ? -1 : 1;
  const int64_t turns = arc.arc.turns < 0 ? -static_cast<int64_t>(arc.arc.turns) : arc.arc.turns;
  int64_t base = dir_ > 0 ? static_cast<uint32_t>(a1 - a0_) : static_cast<uint32_t>(a0_ - a1);
  if (sa == ea && sb == eb) base = kTurnBam;  // full circle
  total_ = base + (turns > 1 ? (turns - 1) * kTurnBam : 0);
  const int64_t s = max_sagitta_nm < 1 ? 1 : max_sagitta_nm;
  const int64_t rmax = r0_ > r1 ? r0_ : r1;
  const int64_t theta = rmax > 0 ? max_chord_bam(rmax, s) : kBamQuarterTurn;
  int64_t n = (total_ + theta - 1) / theta;
  if (n < 1) n = 1;
  if (n > kMaxChords) n = kMaxChords;
  n_ = static_cast<uint32_t>(n);
  k_ = 0;
  step_q_ = static_cast<uint64_t>(total_) / n_;
  step_r_ = static_cast<uint64_t>(total_) % n_;
}

bool ArcChords::next(PointNm* p) {
  if (k_ >= n_) return false;
  ++k_;
  if (k_ == n_) {
    *p = end_;
    return true;
  }
  // Angle from the start: total * k / n, exactly, modulo one turn.
  *p = point_at(step_q_ * k_ + (step_r_ * k_) / n_);
  return true;
}

PointNm ArcChords::point_at(uint64_t along) const {
  if (along >= static_cast<uint64_t>(total_)) return end_;
  const uint32_t ang = dir_ > 0 ? static_cast<uint32_t>(a0_ + along) : static_cast<uint32_t>(a0_ - along);
  const int64_t along_s = static_cast<int64_t>(along);
  int64_t r = r0_;
  if (dr_) r += muldiv_round(dr_, along_s, total_);
  int64_t c = c0_;
  if (dc_) c += muldiv_round(dc_, along_s, total_);
  const SinCosQ30 sc = sincos_bam(ang);
  return plane_point(plane_, ca_ + scale_q30(r, sc.cos_q30), cb_ + scale_q30(r, sc.sin_q30), c);
}

}  // namespace dexmill
