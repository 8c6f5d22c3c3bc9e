// A merged face's streaming triangulation; see stl_ladder.h.
#include "platform/mesh/stl_ladder.h"

namespace dexmill {

GridPoint LadderPlane::point(int64_t s, int64_t t) const {
  switch (axes) {
    case kXY: return GridPoint{static_cast<int32_t>(s), static_cast<int32_t>(t), at};
    case kZY: return GridPoint{static_cast<int32_t>(at), static_cast<int32_t>(t), s};
    case kZX: break;
  }
  return GridPoint{static_cast<int32_t>(t), static_cast<int32_t>(at), s};
}

void LadderPlane::triangle(int64_t s0, int64_t t0, int64_t s1, int64_t t1, int64_t s2, int64_t t2) const {
  const GridPoint a = point(s0, t0), b = point(s1, t1), c = point(s2, t2);
  if (flip)
    out->triangle(a, c, b);
  else
    out->triangle(a, b, c);
}

void Ladder::open(int64_t s_a, int64_t s_b, int64_t t0, const std::vector<int64_t>& cap_s) {
  s_a_ = s_a;
  s_b_ = s_b;
  t0_ = t_a_ = t_b_ = t0;
  start_cap_s_ = cap_s;
  fanned_ = cap_s.empty();
}

void Ladder::feed(bool on_b, int64_t t, const LadderPlane& p) {
  const int64_t s = on_b ? s_b_ : s_a_;
  if (!fanned_) {
    // The first point above the start cap sees all of it: fan from there.
    int64_t prev = s_a_;
    for (const int64_t c : start_cap_s_) {
      p.triangle(prev, t0_, c, t0_, s, t);
      prev = c;
    }
    p.triangle(prev, t0_, s_b_, t0_, s, t);
    start_cap_s_.clear();
    start_cap_s_.shrink_to_fit();
    fanned_ = true;
  } else {
    p.triangle(s_a_, t_a_, s_b_, t_b_, s, t);
  }
  (on_b ? t_b_ : t_a_) = t;
}

void Ladder::close(int64_t t1, const std::vector<int64_t>& cap_s, const LadderPlane& p) {
  feed(false, t1, p);
  // Rail b's last point is below t1 and sees the whole end cap.
  int64_t prev = s_b_;
  for (auto it = cap_s.rbegin(); it != cap_s.rend(); ++it) {
    p.triangle(s_b_, t_b_, prev, t1, *it, t1);
    prev = *it;
  }
  p.triangle(s_b_, t_b_, prev, t1, s_a_, t1);
}

}  // namespace dexmill
