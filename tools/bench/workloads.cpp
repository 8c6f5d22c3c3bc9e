// The benchmark jobs.
//
// Paper (Table 2): zig milling of a design surface in x-parallel stripes one
// dexel apart with a ball cutter; at the end of each stripe the cutter is
// lifted, returns to the other edge without cutting, and is lowered onto the
// next stripe; like the paper's prototype, the return is still simulated.
// Per stripe that is N steps of one dexel cutting, 1 lifting, N returning and
// 1 lowering: 2N + 2 instances of motion. Table 2's counts come out exactly:
//   w1: 80x40 grid,   9-dexel ball, 40 stripes,  N = 79  -> 40 * 160 = 6 400
//   w2: 128x128 grid, 12-dexel ball, 64 stripes, N = 128 -> 64 * 258 = 16 512
//   w3: 256x256 grid, 6-dexel ball, 128 stripes, N = 256 -> 128 * 514 = 65 792
// (in w2 and w3 the design part spans the central half of the rows). The
// cutting stroke follows the design surface as a CAM program writes it: a
// vertex on a dexel wherever the chord would leave the surface by more than
// 0.01 mm; stamping places an instance at every dexel along those moves,
// sweeping cuts each move once.
#include "tools/bench/workloads.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace dexmill {
namespace {

constexpr int64_t kPitchNm = 500000;  // 0.5 mm dexels for the paper jobs

// A smooth relief (z of the tool tip), mm in and nm out.
int64_t relief_nm(double x_mm, double y_mm, double base_mm, double amp_mm, double wx_mm, double wy_mm) {
  double z = base_mm + amp_mm * std::sin(x_mm / wx_mm) * std::cos(y_mm / wy_mm);
  return static_cast<int64_t>(std::llround(z * 1e6));
}

void block(Workload* w, int32_t nx, int32_t ny, int64_t pitch, int64_t top_nm) {
  w->geo = GridGeometry{nx, ny, 0, 0, pitch, 0, lsb_for_range(top_nm + 5 * kNmPerMm, 16)};
  w->stock_top_nm = top_nm;
}

Tool ball(int64_t d_nm) {
  Tool t;
  t.kind = ToolKind::kBall;
  t.diameter_nm = d_nm;
  t.flute_length_nm = 20 * kNmPerMm;
  t.length_nm = 60 * kNmPerMm;
  return t;
}

void paper(Workload* w, int32_t n_grid, int32_t ny, int32_t ball_dex, int32_t stripes, int32_t first_row, int32_t n_steps,
           int64_t instances) {
  block(w, n_grid, ny, kPitchNm, 20 * kNmPerMm);
  w->tool = ball(ball_dex * kPitchNm);
  w->paper_instances = instances;
  const double p_mm = kPitchNm / 1e6;
  const int64_t safe = 22 * kNmPerMm;
  auto z = [&](int32_t i, int32_t j) { return relief_nm(i * p_mm, j * p_mm, 15, 3, 40, 9); };
  const int64_t tol_nm = 10000;
  w->path.push_back(PointNm{0, (first_row - 1) * kPitchNm, safe});
  for (int32_t s = 0; s < stripes; ++s) {
    const int32_t j = first_row + s;
    const int64_t y = j * kPitchNm;
    w->path.push_back(PointNm{0, y, z(0, j)});  // lower onto the stripe
    // Greedy chord tolerance: extend each move while every dexel it passes
    // stays within tol of the surface.
    for (int32_t i0 = 0; i0 < n_steps;) {
      int32_t i1 = i0 + 1;
      while (i1 < n_steps) {
        const int32_t next = i1 + 1;
        bool fits = true;
        for (int32_t k = i0 + 1; k < next && fits; ++k) {
          const int64_t chord = z(i0, j) + (z(next, j) - z(i0, j)) * (k - i0) / (next - i0);
          fits = std::llabs(chord - z(k, j)) <= tol_nm;
        }
        if (!fits) break;
        i1 = next;
      }
      w->path.push_back(PointNm{i1 * kPitchNm, y, z(i1, j)});
      i0 = i1;
    }
    w->path.push_back(PointNm{n_steps * kPitchNm, y, safe});  // lift
    w->path.push_back(PointNm{0, y, safe});                   // return, not cutting
  }
}

// A part of n x n dexels at 0.1 mm: zig-zag finishing of a relief with a
// vertex every 0.3 mm and 0.5 mm stepover, then an Archimedean spiral pocket
// 1 mm deeper from the centre out, 0.3 mm segments and 0.5 mm stepover.
void scale(Workload* w, int32_t n) {
  const int64_t pitch = 100000;
  block(w, n, n, pitch, 20 * kNmPerMm);
  w->tool = ball(3 * kNmPerMm);
  w->paper_instances = 0;
  const double size_mm = n * pitch / 1e6;
  const int64_t safe = 22 * kNmPerMm;
  auto z = [&](double x, double y) { return relief_nm(x, y, 16, 2, size_mm / 9, size_mm / 7); };
  w->path.push_back(PointNm{0, 0, safe});
  bool forward = true;
  for (double y = 0.5; y < size_mm - 0.5; y += 0.5) {
    const int segs = static_cast<int>(size_mm / 0.3);
    for (int k = 0; k <= segs; ++k) {
      double x = forward ? k * size_mm / segs : size_mm - k * size_mm / segs;
      w->path.push_back(PointNm{static_cast<int64_t>(std::llround(x * 1e6)), static_cast<int64_t>(std::llround(y * 1e6)),
                                z(x, y)});
    }
    forward = !forward;
  }
  const double cx = size_mm / 2, cy = size_mm / 2, rmax = size_mm / 2 - 2;
  w->path.push_back(PointNm{w->path.back().x_nm, w->path.back().y_nm, safe});
  w->path.push_back(PointNm{static_cast<int64_t>(cx * 1e6), static_cast<int64_t>(cy * 1e6), safe});
  w->pocket_start = w->path.size() - 1;
  // r = b * theta with b = stepover / 2 pi; arc length steps of ~0.3 mm.
  const double b = 0.5 / (2 * 3.14159265358979323846);
  for (double th = 0.0; b * th < rmax;) {
    const double r = b * th;
    const double x = cx + r * std::cos(th), y = cy + r * std::sin(th);
    w->path.push_back(PointNm{static_cast<int64_t>(std::llround(x * 1e6)), static_cast<int64_t>(std::llround(y * 1e6)),
                              z(x, y) - kNmPerMm});
    th += 0.3 / std::sqrt(r * r + b * b);
  }
}

}  // namespace

bool make_workload(const char* name, Workload* w) {
  w->name = name;
  w->path.clear();
  w->pocket_start = 0;
  if (!std::strcmp(name, "paper-w1")) paper(w, 80, 40, 9, 40, 0, 79, 6400);
  else if (!std::strcmp(name, "paper-w2")) paper(w, 128, 128, 12, 64, 32, 128, 16512);
  else if (!std::strcmp(name, "paper-w3")) paper(w, 256, 256, 6, 128, 64, 256, 65792);
  else if (!std::strcmp(name, "scale-1k")) scale(w, 1024);
  else if (!std::strcmp(name, "scale-4k")) scale(w, 4096);
  else return false;
  return true;
}

}  // namespace dexmill
