// Canned cycles G73, G81, G82, G83, G85, G89 with G98/G99 and L repeats, as
// LinuxCNC runs them (interp_cycles.cc, convert_cycle_xy and CYCLE_MACRO),
// in any of the three planes. Planning checks everything and cannot emit;
// emitting cannot fail, so a cycle block stays atomic.
#ifndef DEXMILL_CORE_MOTION_CYCLES_H
#define DEXMILL_CORE_MOTION_CYCLES_H

#include <stdint.h>

#include "core/motion/canon.h"
#include "core/point.h"

namespace dexmill {

// LinuxCNC's G83_RAPID_DELTA: 0.010 in, also 0.254 mm in G21.
constexpr int64_t kPeckBackoffNm = 254000;

struct CyclePlan {
  int16_t code;          // 730, 810, 820, 830, 850, 890
  Plane plane;
  int64_t a, b;          // first hole before adding the increment (plane coords, path frame)
  int64_t inc_a, inc_b;  // added before each repeat (G91), else 0
  int64_t repeats;       // L >= 1
  bool raise_first;      // below R: straight up to R first
  int64_t start_a, start_b;  // current position in the plane
  int64_t current_c;     // level of the first positioning move (after raising)
  int64_t r_c, bottom_c, clear_c;
  int64_t q_nm;          // peck (G73, G83)
  int64_t dwell_ms;      // G82, G89
};

// Receives the moves of a cycle (traverse or feed to a point, or a dwell).
class CycleOut {
 public:
  virtual void move(CanonKind kind, const PointNm& to) = 0;
  virtual void dwell(int64_t ms) = 0;

 protected:
  ~CycleOut() = default;
};

// Emits every move of the planned cycle, in LinuxCNC's order.
void cycle_emit(const CyclePlan& p, CycleOut* out);

// Number of pecks of G73/G83 from r down to bottom with increment q (q > 0).
int64_t cycle_peck_count(int64_t r_c, int64_t bottom_c, int64_t q_nm);

}  // namespace dexmill

#endif
