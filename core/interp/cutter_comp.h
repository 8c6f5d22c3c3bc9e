// Cutter radius compensation (G40, G41, G42, G41.1, G42.1) as LinuxCNC 2.9
// makes it (rs274ngc: interp_convert.cc convert_straight_comp1/comp2 and
// convert_arc_comp1/comp2, interp_queue.cc): the state, the queue of held
// canonical records, and the integer geometry. The interpreter's side (which
// block does what, the errors at their lines) is core/interp/interp_comp.cpp.
//
// LinuxCNC compensates with a one-move lookahead: the compensated move is
// held until the next one fixes the corner between them (a convex corner
// gets an arc around the programmed corner point, a concave one moves the
// held move's end back to where the two offset paths meet). Records made
// while a move is held (a Z-only move, a spindle or coolant change, a dwell)
// are held behind it. The queue here has a fixed capacity, kCompQueueMax
// records; a program that holds more gets an error naming the limit.
//
// Geometry is in the plane's coordinates (a, b) (arc_center.h: (X, Y) in
// G17, (Z, X) in G18; comp is refused in G19 as in LinuxCNC), nm. Angles are
// binary angles (core/math/trig.h, 2^32 a turn); LinuxCNC's decisions
// (convex, concave, tangent: 0.05 rad) are taken on angles from exact
// integer direction vectors, within 4 bam (6e-9 rad) of LinuxCNC's doubles.
//
// Error bounds. The points the geometry makes are rounded to 1 nm, so the
// error is that rounding carried through the corner's construction:
//   an offset point (a point plus r towards an angle from exact vectors):
//     within 1 nm + 1e-8 * r;
//   a concave corner's meeting point: the rounding of the points it is made
//     from over the sine of the angle the two paths meet at (LinuxCNC calls
//     a corner concave from 0.05 rad on), so tens of nm at worst;
//   the first arc of compensation (its new centre, on the line from the
//     offset end through the programmed centre): ill-conditioned when that
//     centre lies far off, as in LinuxCNC: relative to the arc's radius.
// tests/test_cutter_comp.cpp runs 4000 random paths of lines and arcs
// through a double-precision model of LinuxCNC's code: the same decisions
// and errors on every one, move ends within 35 nm (50 checked), entry arc
// centres within 1.1e-6 of the radius (2e-6 checked); rs274 itself agrees
// within its printed 4 decimals (tools/scripts/oracle-check.sh).
#ifndef DEXMILL_CORE_INTERP_CUTTER_COMP_H
#define DEXMILL_CORE_INTERP_CUTTER_COMP_H

#include <stdint.h>

#include "core/gcode/error.h"
#include "core/canon/canon.h"
#include "core/point.h"

namespace dexmill {

// Records the queue holds at most (LinuxCNC: no limit). It holds the last
// compensated move and what came after it in the same plane position: a
// real program holds 1 to 5.
constexpr int kCompQueueMax = 16;  // GcodeError::kCompQueueFull's message says 16

// LinuxCNC's TOLERANCE_CONCAVE_CORNER, 0.05 rad, in binary angles.
constexpr int64_t kCompCornerTolBam = 34178445;

// Modal compensation state (part of InterpState, copied per block).
struct CompState {
  int8_t side;           // 0 off, +1 left (G41), -1 right (G42), after a negative radius swapped it
  bool first_move;       // LinuxCNC's cutter_comp_firstmove: the next move is the entry move
  bool arc_not_allowed;  // after G40 that ended compensation: the next move must be straight
  int64_t radius_nm;     // >= 0; 0 leaves moves uncompensated
  PointNm prog;          // the programmed point (LinuxCNC program_x/y/z), path frame
  // The direction of the programmed path at `prog` (unnormalised, exact):
  // the tool stands at prog + side * radius * (its left normal).
  int64_t tan_a, tan_b;
};

struct Vec2 {
  int64_t a, b;
};

// The plane's coordinates of a point, and a point from them.
Vec2 comp_plane_xy(Plane p, const PointNm& v);
PointNm comp_plane_point(Plane p, Vec2 v, int64_t c);

// Direction of v (atan2), binary angle.
uint32_t comp_dir_bam(Vec2 v);
// v + r * (cos t, sin t), rounded to nm.
Vec2 comp_polar(Vec2 v, int64_t r_nm, uint32_t t_bam);
// Angle to the left (+1) or right (-1) normal of a direction.
inline uint32_t comp_normal_bam(uint32_t dir_bam, int side) {
  return side > 0 ? dir_bam + 0x40000000u : dir_bam - 0x40000000u;
}
// LinuxCNC's find_turn: the signed sweep from s to e around c in the
// direction and number of turns of `turn`, binary angles (0 when turn == 0).
int64_t comp_find_turn(Vec2 s, Vec2 c, int32_t turn, Vec2 e);
// asin(num / den) and acos(num / den) for |num| <= den, 0 < den < 2^46
// (within 3 bam of the exact angle).
uint32_t comp_asin_bam(int64_t num, int64_t den);
uint32_t comp_acos_bam(int64_t num, int64_t den);
// Sign of a1 * a2 + b1 * b2 (exact: 128-bit products).
int comp_dot_sign(int64_t a1, int64_t b1, int64_t a2, int64_t b2);
// LinuxCNC's TOOL_INSIDE_ARC: the tool is on the centre's side of an arc.
inline bool comp_inside_arc(int side, int32_t turn) { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }
// |v|, rounded down to nm.
int64_t comp_length(Vec2 v);

// A held record with what LinuxCNC keeps beside it to move its end.
struct CompEntry {
  CanonRecord rec;
  int64_t dir_a, dir_b;  // straight moves: LinuxCNC's direction (its sign test only)
  int64_t sweep_bam;     // arcs: the sweep LinuxCNC recorded (0: none, no test)
};

// Receives the records the queue lets go (Interp::emit_now).
struct CompEmit {
  void (*fn)(void* ctx, CanonRecord* r);
  void* ctx;
};

// LinuxCNC's queue (interp_queue.cc). Used twice a block: on a scratch copy
// while the block is checked (emit null: only the errors), then for real.
struct CompQueue {
  CompEntry e[kCompQueueMax];
  int n;
  bool endpoint_valid;   // LinuxCNC's endpoint: where the held move started
  Vec2 endpoint;

  void clear() {
    n = 0;
    endpoint_valid = false;
    endpoint = Vec2{0, 0};
  }
  void copy_from(const CompQueue& o);
  void set_endpoint(Vec2 v) {
    endpoint = v;
    endpoint_valid = true;
  }
  // Holds a record; it starts where the held ones end (or at `at`).
  // False when the queue is full (nothing held).
  [[nodiscard]] bool push(const CanonRecord& r, const PointNm& at, int64_t dir_a, int64_t dir_b, int64_t sweep_bam);
  // LinuxCNC's dequeue_canons: lets every record go, in order; returns
  // where the tool is after them (`at` when none is held).
  PointNm dequeue(const CompEmit* out, const PointNm& at);
  // LinuxCNC's move_endpoint_and_flush: every held move ends at `to`
  // instead (in the plane), then all go. Errors (nothing changed then):
  // a held straight move would run backwards (kCompConcaveStraight), a held arc would sweep further than it was programmed
  // (kCompConcaveArc), or an arc's radius would change (kCompInternal).
  // `inch`: LinuxCNC's tolerances are in program units.
  [[nodiscard]] GcodeError move_end_and_flush(Plane p, Vec2 to, bool inch, const CompEmit* out, PointNm* at);
};

}  // namespace dexmill

#endif
