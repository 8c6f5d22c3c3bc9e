// Cutter radius compensation: geometry helpers and the queue of held
// records (see cutter_comp.h; LinuxCNC's interp_queue.cc and interp_find.cc).
#include "core/interp/cutter_comp.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/math/wide.h"
#include "core/canon/arc_chords.h"

namespace dexmill {

namespace {

constexpr int64_t kTurnBam = static_cast<int64_t>(1) << 32;
// LinuxCNC's move_endpoint_and_flush compares an arc's new sweep (radians)
// with its old one plus .0254 in G21 or .001 in G20, and its radii with .01
// program units.
constexpr int64_t kSweepTolMmBam = 17362648;  // 0.0254 rad
constexpr int64_t kSweepTolInchBam = 683563;  // 0.001 rad
constexpr int64_t kRadiusTolMmNm = 10000;
constexpr int64_t kRadiusTolInchNm = 254000;

int64_t abs_i64(int64_t v) { return v < 0 ? -v : v; }

bool is_move(CanonKind k) { return k == CanonKind::kTraverse || k == CanonKind::kFeed || k == CanonKind::kArc; }

}  // namespace

Vec2 comp_plane_xy(Plane p, const PointNm& v) { return Vec2{plane_a(p, v), plane_b(p, v)}; }

PointNm comp_plane_point(Plane p, Vec2 v, int64_t c) { return plane_point(p, v.a, v.b, c); }

uint32_t comp_dir_bam(Vec2 v) { return atan2_bam(v.b, v.a); }

Vec2 comp_polar(Vec2 v, int64_t r_nm, uint32_t t_bam) {
  const SinCosQ30 sc = sincos_bam(t_bam);
  return Vec2{sat_add_i64(v.a, muldiv_round(r_nm, sc.cos_q30, int64_t{1} << 30)),
              sat_add_i64(v.b, muldiv_round(r_nm, sc.sin_q30, int64_t{1} << 30))};
}

int64_t comp_find_turn(Vec2 s, Vec2 c, int32_t turn, Vec2 e) {
  if (turn == 0) return 0;
  const uint32_t from = comp_dir_bam(Vec2{s.a - c.a, s.b - c.b});
  const uint32_t to = comp_dir_bam(Vec2{e.a - c.a, e.b - c.b});
  // One turn sweeps (0, 2 pi] counterclockwise, [-2 pi, 0) clockwise: an
  // end at the start is a whole circle.
  const uint32_t d = turn > 0 ? to - from : from - to;
  const int64_t one = d == 0 ? kTurnBam : static_cast<int64_t>(d);
  const int64_t extra = static_cast<int64_t>(turn > 0 ? turn - 1 : -turn - 1) * kTurnBam;
  return turn > 0 ? one + extra : -(one + extra);
}

namespace {

// sqrt(den^2 - num^2) * 2^16 (0 when |num| >= den), and num * 2^16: the
// legs of the right triangle, fine enough that the floor of the root moves
// the angle by well under a binary angle (|den| < 2^46).
void comp_legs(int64_t num, int64_t den, int64_t* opposite, int64_t* adjacent) {
  const U128 d2 = sq_u128(den), n2 = sq_u128(num);
  *adjacent = u128_less(n2, d2) ? static_cast<int64_t>(isqrt_u128(shl_u128(sub_u128(d2, n2), 32))) : 0;
  *opposite = num * (int64_t{1} << 16);
}

}  // namespace

uint32_t comp_asin_bam(int64_t num, int64_t den) {
  int64_t o, a;
  comp_legs(num, den, &o, &a);
  return atan2_bam(o, a);
}

uint32_t comp_acos_bam(int64_t num, int64_t den) {
  int64_t o, a;
  comp_legs(num, den, &o, &a);
  return atan2_bam(a, o);
}

int comp_dot_sign(int64_t a1, int64_t b1, int64_t a2, int64_t b2) {
  const int s1 = (a1 == 0 || a2 == 0) ? 0 : ((a1 < 0) != (a2 < 0) ? -1 : 1);
  const int s2 = (b1 == 0 || b2 == 0) ? 0 : ((b1 < 0) != (b2 < 0) ? -1 : 1);
  if (s1 == 0) return s2;
  if (s2 == 0 || s1 == s2) return s1;
  // Opposite signs: the larger magnitude wins.
  const U128 m1 = mul_wide_u64(abs_u64(a1), abs_u64(a2)), m2 = mul_wide_u64(abs_u64(b1), abs_u64(b2));
  if (u128_less(m1, m2)) return s2;
  if (u128_less(m2, m1)) return s1;
  return 0;
}

int64_t comp_length(Vec2 v) { return hypot_floor(v.a, v.b); }

void CompQueue::copy_from(const CompQueue& o) {
  n = o.n;
  for (int i = 0; i < n; ++i) e[i] = o.e[i];
  endpoint_valid = o.endpoint_valid;
  endpoint = o.endpoint;
}

bool CompQueue::push(const CanonRecord& r, const PointNm& at, int64_t dir_a, int64_t dir_b, int64_t sweep_bam) {
  if (n >= kCompQueueMax) return false;
  CompEntry& x = e[n];
  x.rec = r;
  x.rec.start = n ? e[n - 1].rec.end : at;
  if (!is_move(r.kind)) x.rec.end = x.rec.start;
  x.dir_a = dir_a;
  x.dir_b = dir_b;
  x.sweep_bam = sweep_bam;
  ++n;
  return true;
}

PointNm CompQueue::dequeue(const CompEmit* out, const PointNm& at) {
  endpoint_valid = false;
  if (n == 0) return at;
  // The first record starts where the tool was when it was held; the others
  // where the one before ends (an end may have moved since).
  PointNm p = e[0].rec.start;
  for (int i = 0; i < n; ++i) {
    CanonRecord& r = e[i].rec;
    r.start = p;
    if (!is_move(r.kind)) r.end = p;
    p = r.end;
    if (out) out->fn(out->ctx, &r);
  }
  n = 0;
  return p;
}

GcodeError CompQueue::move_end_and_flush(Plane p, Vec2 to, bool inch, const CompEmit* out, PointNm* at) {
  if (n == 0) return GcodeError::kOk;  // nothing held: LinuxCNC keeps its endpoint too
  const int64_t sweep_tol = inch ? kSweepTolInchBam : kSweepTolMmBam;
  const int64_t radius_tol = inch ? kRadiusTolInchNm : kRadiusTolMmNm;
  for (int i = 0; i < n; ++i) {
    const CompEntry& x = e[i];
    if (x.rec.kind == CanonKind::kArc) {
      const Vec2 c = comp_plane_xy(p, x.rec.arc.centre);
      const Vec2 old_end = comp_plane_xy(p, x.rec.end);
      const int64_t r1 = comp_length(Vec2{old_end.a - c.a, old_end.b - c.b});
      const int64_t r2 = comp_length(Vec2{to.a - c.a, to.b - c.b});
      if (abs_i64(r1 - r2) > radius_tol) return GcodeError::kCompInternal;
      if (x.sweep_bam != 0 && endpoint_valid) {
        const int64_t l2 = comp_find_turn(endpoint, c, x.rec.arc.turns, to);
        if (abs_i64(l2) > abs_i64(x.sweep_bam) + sweep_tol) return GcodeError::kCompConcaveArc;
      }
    } else if (is_move(x.rec.kind)) {
      // The move would now run against its programmed direction: the path
      // crossed itself, backing up further than the move is long.
      if (endpoint_valid && comp_dot_sign(x.dir_a, x.dir_b, to.a - endpoint.a, to.b - endpoint.b) < 0) {
        return GcodeError::kCompConcaveStraight;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    CanonRecord& r = e[i].rec;
    if (is_move(r.kind)) r.end = comp_plane_point(p, to, plane_c(p, r.end));
  }
  *at = dequeue(out, *at);
  set_endpoint(to);
  return GcodeError::kOk;
}

}  // namespace dexmill
