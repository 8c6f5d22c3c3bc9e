// The tool's non-cutting parts and their lowest points over a move; see body.h.
#include "core/safety/body.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

void tool_body_build(const Tool& t, ToolBody* out) {
  ToolBody b;
  b.cutter_r_nm = t.diameter_nm / 2;
  b.stick_nm = t.length_nm;
  b.centre_cutting = t.centre_cutting;
  const int64_t full = profile_full_height_nm(tool_profile(t));
  // A flute length under the cutting shape's own height (a ball's flutes
  // end under its equator) is read as ending at the shape's top.
  b.flute_nm = t.flute_length_nm > 0 ? max_of(t.flute_length_nm, full) : 0;
  if (b.flute_nm > 0 && b.flute_nm < b.stick_nm) {
    BodyRing& g = b.ring[b.nrings++];
    g.part = BodyPart::kShank;
    g.r0_nm = g.r1_nm = max_of(b.cutter_r_nm, t.shank_diameter_nm / 2);
    g.h0_nm = g.h1_nm = b.flute_nm;
  }
  int64_t base = b.stick_nm;
  for (int k = 0; k < t.holder_segments; ++k) {
    const HolderSegment& h = t.holder[k];
    BodyRing& g = b.ring[b.nrings++];
    g.part = BodyPart::kHolder;
    g.r0_nm = h.bottom_diameter_nm / 2;
    g.r1_nm = max_of(g.r0_nm, h.top_diameter_nm / 2);
    g.h0_nm = base;
    g.h1_nm = g.r1_nm > g.r0_nm ? base + h.height_nm : base;
    base += h.height_nm;
  }
  b.lowest_nm = INT64_MAX;
  for (int k = 0; k < b.nrings; ++k) {
    b.reach_nm = max_of(b.reach_nm, b.ring[k].r1_nm);
    b.lowest_nm = min_of(b.lowest_nm, b.ring[k].h0_nm);
  }
  if (b.nrings == 0) b.lowest_nm = 0;
  *out = b;
}

BodyPiece body_piece(PointNm a, PointNm b) {
  BodyPiece p;
  p.a = a;
  p.b = b;
  p.dx = b.x_nm - a.x_nm;
  p.dy = b.y_nm - a.y_nm;
  p.dz = b.z_nm - a.z_nm;
  // |dx|, |dy| <= 2^26: len^2 < 2^53, and shifted by 32 within 128 bits.
  p.len_q16 = static_cast<int64_t>(isqrt_u128(shl_u128(sum_sq_u128(p.dx, p.dy), 32)));
  p.len_nm = div_round(p.len_q16, 65536);
  return p;
}

void BodyPieces::init(const CanonRecord& r) {
  arc_ = r.kind == CanonKind::kArc;
  if (arc_) chords_.init(r, kArcChordSagittaNm);
  from_ = to_ = r.start;
  k_ = n_ = 0;
  more_ = true;
  if (!arc_) {
    to_ = r.end;
    n_ = 1;
  }
}

bool BodyPieces::next(BodyPiece* out) {
  if (k_ == n_) {  // the next chord, split in pieces short enough
    if (!arc_ || !more_) return false;
    from_ = to_;
    if (!chords_.next(&to_)) {
      more_ = false;
      return false;
    }
    k_ = n_ = 0;
    n_ = 1;
  }
  if (k_ == 0 && n_ == 1) {
    const int64_t len = hypot_floor(to_.x_nm - from_.x_nm, to_.y_nm - from_.y_nm);
    n_ = static_cast<uint32_t>(len / kBodyPieceMaxNm + 1);
  }
  const auto at = [this](uint32_t k) {
    if (k == n_) return to_;
    return PointNm{from_.x_nm + muldiv_round(to_.x_nm - from_.x_nm, k, n_),
                   from_.y_nm + muldiv_round(to_.y_nm - from_.y_nm, k, n_),
                   from_.z_nm + muldiv_round(to_.z_nm - from_.z_nm, k, n_)};
  };
  *out = body_piece(at(k_), at(k_ + 1));
  ++k_;
  return true;
}

namespace {

// The column in the piece's frame: s along from a (nm, may be outside
// [0, len]), v across (|v|, nm).
struct Local {
  int64_t s, v;
  int64_t cross;  // |v| * len exactly (a plunge: 0)
  int64_t len_q16;
  uint64_t len2;  // len^2, exact
};

Local local_of(const BodyPiece& p, int64_t x, int64_t y) {
  const int64_t px = x - p.a.x_nm, py = y - p.a.y_nm;
  if (p.len_q16 == 0) return Local{0, hypot_floor(px, py), 0, 0, 0};
  // |px|, |py| <= piece + reach < 2^30, |dx|, |dy| <= 2^26: within int64.
  const int64_t dot = px * p.dx + py * p.dy;
  int64_t cross = px * p.dy - py * p.dx;
  if (cross < 0) cross = -cross;
  const uint64_t len2 = static_cast<uint64_t>(p.dx * p.dx) + static_cast<uint64_t>(p.dy * p.dy);
  return Local{muldiv_round(dot, 65536, p.len_q16), muldiv_round(cross, 65536, p.len_q16), cross, p.len_q16, len2};
}

// Half the chord of the circle of radius r at the column's cross offset
// (-1: none), from the exact cross product: sqrt(r^2 len^2 - cross^2) / len,
// one rounding (a rounded v would cost v / w nm where the chord is short).
int64_t half_chord(int64_t r, const Local& c) {
  if (c.v > r + 1) return -1;
  if (c.len_q16 == 0) return c.v > r ? -1 : static_cast<int64_t>(isqrt_round_u64(static_cast<uint64_t>(r * r - c.v * c.v)));
  // r^2 len^2 with len^2 = dx^2 + dy^2 exactly: (r len)^2 from len_q16 would round.
  const U128 rl = mul_wide_u64(static_cast<uint64_t>(r) * static_cast<uint64_t>(r), c.len2);
  const U128 x2 = mul_wide_u64(static_cast<uint64_t>(c.cross), static_cast<uint64_t>(c.cross));
  if (u128_less(rl, x2)) return -1;
  const uint64_t root = isqrt_u128(sub_u128(rl, x2));  // r len < 2^56
  return muldiv_round(static_cast<int64_t>(root), 65536, c.len_q16);
}

// Where along the piece the column is at a distance within [r_in, r_out]:
// up to two intervals of s in [0, len].
struct Spans {
  int n = 0;
  int64_t lo[2], hi[2];
};

Spans spans_of(const BodyPiece& p, const Local& c, int64_t r_in, int64_t r_out) {
  Spans sp;
  const int64_t w_out = half_chord(r_out, c);
  if (w_out < 0) return sp;
  const int64_t lo = max_of<int64_t>(0, c.s - w_out), hi = min_of(p.len_nm, c.s + w_out);
  if (lo > hi) return sp;
  const int64_t w_in = r_in > 0 && c.v < r_in ? half_chord(r_in, c) : -1;
  if (w_in <= 0) {  // no hole (a hole of one point changes no minimum)
    sp.lo[0] = lo;
    sp.hi[0] = hi;
    sp.n = 1;
    return sp;
  }
  if (lo <= c.s - w_in) {
    sp.lo[sp.n] = lo;
    sp.hi[sp.n] = min_of(hi, c.s - w_in);
    ++sp.n;
  }
  if (c.s + w_in <= hi) {
    sp.lo[sp.n] = max_of(lo, c.s + w_in);
    sp.hi[sp.n] = hi;
    ++sp.n;
  }
  return sp;
}

int64_t z_at(const BodyPiece& p, int64_t s) {
  if (p.len_q16 == 0) return p.a.z_nm;
  return p.a.z_nm + muldiv_round(p.dz, s * 65536, p.len_q16);
}

int bit_length(U128 v) {
  int n = 0;
  uint64_t w = v.hi ? v.hi : v.lo;
  while (w) { ++n; w >>= 1; }
  return v.hi ? n + 64 : n;
}

U128 shr_u128(U128 v, int s) {
  if (s <= 0) return v;
  if (s >= 64) return U128{0, v.hi >> (s - 64)};
  return U128{v.hi >> s, (v.lo >> s) | (v.hi << (64 - s))};
}

// The minimizer of g(s) = dz/len * s + k * d(s), k = dh/dr, d(s) the
// column's distance: where g' = 0, at s - c.s = -sign(dz) |dz| dr |v| /
// sqrt(dh^2 len^2 - dz^2 dr^2) when |dz| dr < dh len; else g is monotone
// and *side says which end (-1: the low end, +1: the high end).
int64_t cone_minimizer(const BodyPiece& p, const Local& c, int64_t dh, int64_t dr, int* side) {
  *side = 0;
  U128 a = mul_wide_u64(static_cast<uint64_t>(dh), static_cast<uint64_t>(p.len_q16));
  U128 b = shl_u128(mul_wide_u64(abs_u64(p.dz), static_cast<uint64_t>(dr)), 16);
  if (!u128_less(b, a)) {
    *side = p.dz < 0 ? 1 : -1;  // falling: g decreases along s
    return 0;
  }
  const int shift = max_of(bit_length(a), bit_length(b)) - 62;
  a = shr_u128(a, shift);
  b = shr_u128(b, shift);
  const uint64_t root = isqrt_u128(sub_u128(mul_wide_u64(a.lo, a.lo), mul_wide_u64(b.lo, b.lo)));
  if (root == 0 || b.lo / root >= (uint64_t{1} << 30)) {  // |s* - s| beyond any piece
    *side = p.dz < 0 ? 1 : -1;
    return 0;
  }
  const int64_t off = muldiv_wide(static_cast<int64_t>(b.lo), c.v, static_cast<int64_t>(root), true);
  return p.dz < 0 ? c.s + off : c.s - off;
}

}  // namespace

int64_t ring_lowest_nm(const BodyRing& g, const BodyPiece& p, int64_t x, int64_t y) {
  // Covered all along: the disc of radius r0 about the column holds both
  // ends, so the whole piece (it is convex), and the flat part is lowest at
  // the lower end (a cone only rises from it). Most of a wide holder's
  // columns over a short move; no root, no wide division.
  if (g.r_in_nm == 0) {
    const int64_t r0 = g.r0_nm;
    const int64_t ax = x - p.a.x_nm, ay = y - p.a.y_nm, bx = x - p.b.x_nm, by = y - p.b.y_nm;
    if (ax >= -r0 && ax <= r0 && ay >= -r0 && ay <= r0 && bx >= -r0 && bx <= r0 && by >= -r0 && by <= r0 &&
        ax * ax + ay * ay <= r0 * r0 && bx * bx + by * by <= r0 * r0)
      return min_of(p.a.z_nm, p.b.z_nm) + g.h0_nm;
  }
  // Out of reach (farther than r1 from the piece): no division either.
  {
    const int64_t r1 = g.r1_nm;
    const int64_t ax = x - p.a.x_nm, ay = y - p.a.y_nm, bx = x - p.b.x_nm, by = y - p.b.y_nm;
    const auto within = [r1](int64_t u, int64_t v) { return u >= -r1 && u <= r1 && v >= -r1 && v <= r1 && u * u + v * v <= r1 * r1; };
    if (!within(ax, ay) && !within(bx, by)) {
      if (p.len_q16 == 0) return kBodyNever;
      const int64_t dot = ax * p.dx + ay * p.dy;
      const uint64_t len2 = static_cast<uint64_t>(p.dx * p.dx) + static_cast<uint64_t>(p.dy * p.dy);
      if (dot <= 0 || static_cast<uint64_t>(dot) >= len2) return kBodyNever;  // past an end, and not near it
      const int64_t cross = ax * p.dy - ay * p.dx;
      if (u128_less(mul_wide_u64(static_cast<uint64_t>(r1) * static_cast<uint64_t>(r1), len2), sq_u128(cross)))
        return kBodyNever;
    }
  }
  const Local c = local_of(p, x, y);
  int64_t best = kBodyNever;
  if (p.len_q16 == 0) {  // a plunge: the distance stays, z runs from a to b
    const int64_t d = c.v;
    if (d < g.r_in_nm || d > g.r1_nm) return kBodyNever;
    const int64_t h = d <= g.r0_nm ? g.h0_nm : g.h0_nm + muldiv_round(g.h1_nm - g.h0_nm, d - g.r0_nm, g.r1_nm - g.r0_nm);
    return min_of(p.a.z_nm, p.b.z_nm) + h;
  }
  // The flat part: z is linear in s, lowest at an end of a span.
  const Spans flat = spans_of(p, c, g.r_in_nm, g.r0_nm);
  for (int k = 0; k < flat.n; ++k)
    best = min_of(best, g.h0_nm + z_at(p, p.dz >= 0 ? flat.lo[k] : flat.hi[k]));
  if (g.r1_nm <= g.r0_nm) return best;
  // The cone: convex in s, lowest at its minimizer clamped into a span.
  const Spans cone = spans_of(p, c, max_of(g.r_in_nm, g.r0_nm), g.r1_nm);
  if (cone.n == 0) return best;
  const int64_t dh = g.h1_nm - g.h0_nm, dr = g.r1_nm - g.r0_nm;
  int side = 0;
  const int64_t star = cone_minimizer(p, c, dh, dr, &side);
  for (int k = 0; k < cone.n; ++k) {
    const int64_t s = side < 0 ? cone.lo[k] : side > 0 ? cone.hi[k] : clamp(star, cone.lo[k], cone.hi[k]);
    const int64_t ds = s - c.s;
    const int64_t d = clamp<int64_t>(hypot_floor(ds, c.v), g.r0_nm, g.r1_nm);
    best = min_of(best, z_at(p, s) + g.h0_nm + muldiv_round(dh, d - g.r0_nm, dr));
  }
  return best;
}

int64_t piece_lowest_tip_nm(const BodyPiece& p) {
  // z_at is monotone in s and ring_lowest_nm takes s in [0, len_nm]: the
  // lowest is at an end (len_nm rounds the length, so z_at there may pass b).
  return min_of(min_of(p.a.z_nm, p.b.z_nm), z_at(p, p.len_nm));
}

int64_t piece_first_cover_z(const BodyPiece& p, int64_t r_nm, int64_t x, int64_t y) {
  const Local c = local_of(p, x, y);
  const int64_t w = half_chord(r_nm, c);
  if (w < 0) return kBodyNever;
  if (p.len_q16 == 0) return p.a.z_nm;
  const int64_t lo = max_of<int64_t>(0, c.s - w);
  if (lo > min_of(p.len_nm, c.s + w)) return kBodyNever;
  return z_at(p, lo);
}

}  // namespace dexmill
