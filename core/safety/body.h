// The parts of a tool that must never touch material: the shank
// above the flutes and the holder above the stick-out, as rings of a lower
// surface over the radial distance r, and where along a move they come
// lowest over a column. What the safety checks (core/safety/safety.h) compare
// with the material left, the fixtures and the material the cut removed.
//
// Material is a height field seen from below, so only a part's lower surface
// can meet it: a ring is flat at h0 for r_in <= r <= r0, then (r1 > r0) a
// cone rising to h1 at r1. The shank is a flat disc at the flute length, as
// wide as the cutter or its own diameter: against material left after a
// move it finds what the tool passed under (a dexel keeps material above a
// tool deeper in it than its stick-out, core/cut/sweep.h) and what a
// deferred end cap has still to cut; what the cut itself removed above the
// flutes safety.h charges to the shank. A holder cylinder is a flat disc at
// its base; a cone widening upwards is a flat disc of its bottom radius and
// a cone ring to its top radius; one narrowing upwards is its bottom disc.
//
// Error bound (tests/test_body.cpp, double oracle): ring_lowest_nm is within
// 4 nm + 2 nm x the cone's slope of the exact lowest point over the piece,
// for a column displaced by at most 1 nm horizontally (at a flat ring's edge
// the height jumps, so only such a backward bound exists, as for the sweep).
#ifndef DEXMILL_CORE_SAFETY_BODY_H
#define DEXMILL_CORE_SAFETY_BODY_H

#include <stdint.h>

#include "core/canon/arc_chords.h"
#include "core/canon/canon.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class BodyPart : uint8_t { kShank = 0, kHolder = 1 };

struct BodyRing {
  BodyPart part = BodyPart::kHolder;
  int64_t r_in_nm = 0, r0_nm = 0, r1_nm = 0;  // r_in <= r0 <= r1
  int64_t h0_nm = 0, h1_nm = 0;               // above the tip; h1 > h0 when r1 > r0
};
constexpr int kBodyRingsMax = 1 + kHolderSegmentsMax;

struct ToolBody {
  int64_t cutter_r_nm = 0;
  int64_t flute_nm = 0;    // the shank begins here (0: no flute length given, no shank check)
  int64_t stick_nm = 0;    // the holder's face
  int64_t reach_nm = 0;    // the widest ring's outer radius (0: no rings)
  int64_t lowest_nm = 0;   // the lowest ring's h0
  bool centre_cutting = true;
  int nrings = 0;
  BodyRing ring[kBodyRingsMax];
};

// The body of a checked tool.
void tool_body_build(const Tool& t, ToolBody* out);

// A straight piece of the tip's motion, at most kBodyPieceMaxNm long
// horizontally (so that products of offsets stay within int64).
constexpr int64_t kBodyPieceMaxNm = int64_t{1} << 26;
struct BodyPiece {
  PointNm a, b;
  int64_t dx, dy, dz;  // b - a
  int64_t len_nm;      // horizontal length, rounded (0: a plunge)
  int64_t len_q16;     // the same in nm / 2^16: lengths along the piece divide by it
};
BodyPiece body_piece(PointNm a, PointNm b);

// A motion record's pieces in order: a line split evenly, an arc's chords
// of sagitta <= kArcChordSagittaNm (what the cut follows for arcs it does
// not cut exactly), each split again when long.
class BodyPieces {
 public:
  void init(const CanonRecord& r);
  bool next(BodyPiece* out);

 private:
  bool arc_ = false;
  ArcChords chords_;
  PointNm from_{0, 0, 0}, to_{0, 0, 0};  // the chord or line being split
  uint32_t k_ = 0, n_ = 0;               // its pieces done, in all
  bool more_ = false;
};

// The lowest point of ring `g` (z of its lower surface, nm) over piece p
// with the tip moving a to b, at the column (x, y); kBodyNever when the
// ring never covers the column.
constexpr int64_t kBodyNever = INT64_MAX;
int64_t ring_lowest_nm(const BodyRing& g, const BodyPiece& p, int64_t x_nm, int64_t y_nm);

// A lower bound of every tip z ring_lowest_nm takes along p (the ends, and
// the rounded end it may reach past b): no ring is lower over p than this
// plus its h0, so a top at or under that meets the ring nowhere (the body
// test's skip, core/safety/safety.cpp).
int64_t piece_lowest_tip_nm(const BodyPiece& p);

// The tip's z where the cutter (radius r) first covers the column along p,
// or kBodyNever. Material removed there above this + the flute length was
// met by the shank: later positions meet only what earlier ones left, which
// lies under their own flutes (a straight piece covers a column in one run).
int64_t piece_first_cover_z(const BodyPiece& p, int64_t r_nm, int64_t x_nm, int64_t y_nm);

}  // namespace dexmill

#endif
