// core/measure/thin_wall.h: the thinnest wall, by scans.
#include "core/measure/thin_wall.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

namespace {

// Air's height: below every top (tops are 0..2^32 - 1 LSB) by more than
// any wall height in LSB a grid can have.
constexpr int64_t kAirLsb = -(static_cast<int64_t>(1) << 60);

// One scan line: from (i, j) by (di, dj) while on the grid.
struct Scan {
  int32_t i, j, di, dj, n;
};

template <class H>
int64_t top_at(const DexelGrid<H>& g, const Scan& s, int32_t k) {
  if (k < 0 || k >= s.n) return kAirLsb;
  const int32_t i = s.i + s.di * k, j = s.j + s.dj * k;
  return g.is_hole(i, j) ? kAirLsb : static_cast<int64_t>(g.top[g.index(i, j)]);
}

int32_t scan_length(int32_t nx, int32_t ny, int32_t i, int32_t j, int32_t di, int32_t dj) {
  int32_t n = 0;
  while (i >= 0 && j >= 0 && i < nx && j < ny) {
    ++n;
    i += di;
    j += dj;
  }
  return n;
}

// The face is looked at kFaceReach steps crosswise each way from a run's
// end, where it must lie within kFaceShift steps of the end along the
// scan: within atan(3 / 6) = 26.6 degrees of crosswise.
constexpr int32_t kFaceReach = 6;
constexpr int32_t kFaceShift = 3;

template <class H>
bool high_at(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t level) {
  return g.contains(i, j) && !g.is_hole(i, j) && static_cast<int64_t>(g.top[g.index(i, j)]) >= level;
}

// The face at column (i, j), the floor side towards (ox, oy), runs
// crosswise to the scan: kFaceReach steps to either side crosswise, a
// column at least `level` high (on the grid, not a hole) is followed
// towards (ox, oy) by a lower one within kFaceShift steps of the end's
// own place along the scan. A straight face within 26.6 degrees of
// crosswise passes (the four scan directions are 45 degrees apart: every
// face has one, with room for the grid's steps); the tip of a convex
// corner, a chord far from a round island's centre, a wall's last
// kFaceReach columns do not.
template <class H>
bool face_crosswise(const DexelGrid<H>& g, int32_t i, int32_t j, int32_t ox, int32_t oy, int64_t level) {
  for (int side = -1; side <= 1; side += 2) {
    const int32_t qi = i - side * oy * kFaceReach, qj = j + side * ox * kFaceReach;
    bool found = false;
    for (int32_t t = -kFaceShift; t <= kFaceShift && !found; ++t)
      found = high_at(g, qi + t * ox, qj + t * oy, level) && !high_at(g, qi + (t + 1) * ox, qj + (t + 1) * oy, level);
    if (!found) return false;
  }
  return true;
}

// The shortest qualifying runs of one scan, the thinnest kept in *best
// (as run lengths; widths follow from the step).
template <class H>
void scan_walls(const DexelGrid<H>& g, const Scan& s, WallScan kind, int64_t h_lsb, ThinWall* best, int32_t* best_run) {
  for (int32_t a = 0; a < s.n; ++a) {
    const int64_t left = top_at(g, s, a - 1);
    int64_t low = top_at(g, s, a);
    if (low == kAirLsb || low < left + h_lsb) continue;
    for (int32_t b = a; b < s.n; ++b) {
      const int64_t t = top_at(g, s, b);
      low = t < low ? t : low;
      if (low == kAirLsb || low < left + h_lsb) break;
      if (*best_run > 0 && b - a + 1 >= *best_run) break;  // no thinner from here
      const int64_t right = top_at(g, s, b + 1);
      if (right + h_lsb > low) continue;
      // The faces at both ends run crosswise to the scan, or the run is
      // not across the wall (a corner's tip, a chord near a round
      // island's edge) and does not count.
      const int64_t level = (left > right ? left : right) + h_lsb;
      if (!face_crosswise(g, s.i + s.di * a, s.j + s.dj * a, -s.di, -s.dj, level) ||
          !face_crosswise(g, s.i + s.di * b, s.j + s.dj * b, s.di, s.dj, level))
        break;
      *best_run = b - a + 1;
      best->found = true;
      best->scan = kind;
      best->i0 = s.i + s.di * a;
      best->j0 = s.j + s.dj * a;
      best->i1 = s.i + s.di * b;
      best->j1 = s.j + s.dj * b;
      best->top_nm = g.z0_nm + low * g.lsb_nm;
      const int64_t floor = left > right ? left : right;
      best->floor_air = floor == kAirLsb;
      best->floor_nm = best->floor_air ? 0 : g.z0_nm + floor * g.lsb_nm;
      break;
    }
  }
}

}  // namespace

const char* wall_scan_name(WallScan s) {
  switch (s) {
    case WallScan::kRow: return "X";
    case WallScan::kColumn: return "Y";
    case WallScan::kDiagonalUp: return "XY";
    case WallScan::kDiagonalDown: return "X-Y";
  }
  return "?";
}

template <class H>
ThinWall thin_wall(const DexelGrid<H>& g, int64_t wall_height_nm) {
  ThinWall w;
  int32_t run = 0;
  const int64_t h_lsb = div_ceil(wall_height_nm, g.lsb_nm);
  for (int32_t j = 0; j < g.ny; ++j) scan_walls(g, Scan{0, j, 1, 0, g.nx}, WallScan::kRow, h_lsb, &w, &run);
  for (int32_t i = 0; i < g.nx; ++i) scan_walls(g, Scan{i, 0, 0, 1, g.ny}, WallScan::kColumn, h_lsb, &w, &run);
  const int32_t axis_run = run;
  // Diagonal steps are sqrt 2 longer: their runs are kept apart (the
  // early stop counts in steps of the scan's own) and compared in nm.
  int32_t diag_run = 0;
  ThinWall d;
  for (int32_t k = 0; k < g.nx + g.ny - 1; ++k) {
    const int32_t i = k < g.nx ? k : 0, j = k < g.nx ? 0 : k - g.nx + 1;
    scan_walls(g, Scan{i, j, 1, 1, scan_length(g.nx, g.ny, i, j, 1, 1)}, WallScan::kDiagonalUp, h_lsb, &d, &diag_run);
  }
  for (int32_t k = 0; k < g.nx + g.ny - 1; ++k) {
    const int32_t i = k < g.nx ? k : 0, j = k < g.nx ? g.ny - 1 : g.ny - 1 - (k - g.nx + 1);
    scan_walls(g, Scan{i, j, 1, -1, scan_length(g.nx, g.ny, i, j, 1, -1)}, WallScan::kDiagonalDown, h_lsb, &d,
               &diag_run);
  }
  const int64_t diag_step_nm = hypot_floor(g.pitch_nm, g.pitch_nm);
  const bool diag_wins = d.found && (!w.found || static_cast<int64_t>(diag_run) * diag_step_nm <
                                                     static_cast<int64_t>(axis_run) * g.pitch_nm);
  int64_t step_nm = g.pitch_nm;
  if (diag_wins) {
    w = d;
    run = diag_run;
    step_nm = diag_step_nm;
  }
  if (!w.found) return w;
  w.width_nm = static_cast<int64_t>(run) * step_nm;
  w.width_error_nm = step_nm;
  w.x_nm = g.x0_nm + div_round((static_cast<int64_t>(w.i0) + w.i1) * g.pitch_nm, 2);
  w.y_nm = g.y0_nm + div_round((static_cast<int64_t>(w.j0) + w.j1) * g.pitch_nm, 2);
  return w;
}

template ThinWall thin_wall<uint8_t>(const DexelGrid<uint8_t>&, int64_t);
template ThinWall thin_wall<uint16_t>(const DexelGrid<uint16_t>&, int64_t);
template ThinWall thin_wall<uint32_t>(const DexelGrid<uint32_t>&, int64_t);

}  // namespace dexmill
