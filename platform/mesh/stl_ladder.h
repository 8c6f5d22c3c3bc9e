// One merged face of the STL surface, triangulated as it streams past: a
// rectangle in its own plane with coordinates (s, t), two rails s = s_a and
// s = s_b (s_a < s_b) running up in t from a start cap at t0 to an end cap
// at t1. Its polygon holds the rectangle's corners and the points the
// caller keeps on the rails and caps (where a neighbouring face has a
// vertex: platform/mesh/stl_merge.h); they arrive in increasing t, rail points
// as the rows that decide them are read, so the face needs no more memory
// than its start cap's points.
//
// Triangulation (counterclockwise in (s, t)): a fan over the start cap from
// the first point above it, one triangle per rail point (the frontier from
// one rail to the other moves up), and a fan over the end cap from the last
// point of rail b below it. Every triangle has three points not on one line
// (a fan's apex is off its cap's line; rail triangles have points on both
// rails), every polygon side is in exactly one triangle, and every chord in
// exactly two: n points give n - 2 triangles, no T-junction inside the face.
#ifndef DEXMILL_PLATFORM_MESH_STL_LADDER_H
#define DEXMILL_PLATFORM_MESH_STL_LADDER_H

#include <cstdint>
#include <vector>

#include "platform/mesh/stl_cells.h"

namespace dexmill {

// Where a face's (s, t) lies in the grid, and which way it faces.
struct LadderPlane {
  enum Axes : uint8_t {
    kXY,  // s = i, t = j, at height `at` (LSB): tops and bottoms
    kZY,  // s = height, t = j, on the line i = `at`: walls along y
    kZX,  // s = height, t = i, on the line j = `at`: walls along x
  };
  Axes axes;
  int64_t at;
  bool flip;  // counterclockwise in (s, t) is inward: turn every triangle over
  TriangleSink* out;

  GridPoint point(int64_t s, int64_t t) const;
  void triangle(int64_t s0, int64_t t0, int64_t s1, int64_t t1, int64_t s2, int64_t t2) const;
};

class Ladder {
 public:
  // Starts a face with rails at s_a < s_b at t0; `cap_s` are the points
  // kept strictly inside the start cap, increasing.
  void open(int64_t s_a, int64_t s_b, int64_t t0, const std::vector<int64_t>& cap_s);
  // A kept point on rail a (on_b false) or b at t, above the last one fed.
  void feed(bool on_b, int64_t t, const LadderPlane& p);
  // Ends the face at t1 (above every point fed), `cap_s` the points kept
  // strictly inside the end cap, increasing.
  void close(int64_t t1, const std::vector<int64_t>& cap_s, const LadderPlane& p);

 private:
  int64_t s_a_ = 0, s_b_ = 0;
  int64_t t0_ = 0;
  int64_t t_a_ = 0, t_b_ = 0;  // the frontier: the last point on each rail
  std::vector<int64_t> start_cap_s_;  // until the start fan is drawn
  bool fanned_ = true;                // the start cap needs no fan, or has had it
};

}  // namespace dexmill

#endif
