// libFuzzer target: the STL reader (platform/format/stl_read.h), binary and ASCII,
// and the design built from its triangles (core/design/design.h). The input
// is the file. A mesh that reads is laid on a grid fitted to its box, as
// `run --design` and `--stock FILE.stl` do, and every column's design top
// is checked against exact 128-bit arithmetic: inside the triangle's XY
// projection (edges included) or not, decided exactly, and the highest
// such triangle's height within 0.5 LSB + 2 nm (design.h's bound).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "platform/format/stl_read.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz_stl {

using namespace dexmill;

constexpr size_t kMaxTriangles = 64;  // kept for the exact check (the reader goes on past it)
constexpr int32_t kMaxSide = 24;

using I128 = __int128;

I128 edge(I128 ax, I128 ay, I128 bx, I128 by, I128 px, I128 py) { return (bx - ax) * (py - ay) - (by - ay) * (px - ax); }

// Column (px, py) against triangle t (coordinates relative to the grid's
// origin): false when its axis misses the XY projection or the projection
// has no area; else the height's numerator and denominator (den > 0).
bool height_over(const I128 x[3], const I128 y[3], const I128 z[3], I128 px, I128 py, I128* num, I128* den) {
  I128 w0 = edge(x[1], y[1], x[2], y[2], px, py);
  I128 w1 = edge(x[2], y[2], x[0], y[0], px, py);
  I128 w2 = edge(x[0], y[0], x[1], y[1], px, py);
  I128 area = w0 + w1 + w2;
  if (area == 0) return false;
  if (area < 0) {
    w0 = -w0;
    w1 = -w1;
    w2 = -w2;
    area = -area;
  }
  if (w0 < 0 || w1 < 0 || w2 < 0) return false;
  *num = w0 * z[0] + w1 * z[1] + w2 * z[2];
  *den = area;
  return true;
}

I128 floor_div(I128 a, I128 b) {
  const I128 q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

// a / b > c / d for b, d > 0: numerators reach 2^95 and denominators 2^63,
// so compare the whole parts, then the fractions (cross products < 2^126).
bool greater(I128 a, I128 b, I128 c, I128 d) {
  const I128 qa = floor_div(a, b), qc = floor_div(c, d);
  if (qa != qc) return qa > qc;
  return (a - qa * b) * d > (c - qc * d) * b;
}

int fuzz_stl(const uint8_t* data, size_t size) {
  const std::vector<unsigned char> bytes(data, data + size);
  static std::vector<TriangleNm> tris;
  tris.clear();
  uint64_t seen = 0;
  StlReadInfo info;
  std::string err;
  const StlRead r = stl_parse("fuzz.stl", bytes, PointNm{0, 0, 0},
                              [&seen](const PointNm* v, std::string*) {
                                ++seen;
                                if (tris.size() < kMaxTriangles) tris.push_back(TriangleNm{{v[0], v[1], v[2]}});
                                return true;
                              },
                              &info, &err);
  FUZZ_REQUIRE(r != StlRead::kIoError);
  FUZZ_REQUIRE(seen == info.triangles);
  if (r != StlRead::kOk) {
    FUZZ_REQUIRE(err.compare(0, 9, "fuzz.stl:") == 0);
    return 0;
  }
  FUZZ_REQUIRE(info.triangles > 0);
  // Binary exactly when the size is that of the count in the header (an
  // ASCII file may have the size of some count, not of its own).
  const uint64_t count = size >= 84 ? (static_cast<uint64_t>(data[80]) | static_cast<uint64_t>(data[81]) << 8 |
                                       static_cast<uint64_t>(data[82]) << 16 | static_cast<uint64_t>(data[83]) << 24)
                                    : 0;
  FUZZ_REQUIRE(info.binary == (size >= 84 && size == 84 + 50 * count));

  // A grid over the mesh's box (the box's lower corner on a dexel axis).
  PointNm lo = tris[0].v[0], hi = lo;
  for (const TriangleNm& t : tris)
    for (const PointNm& p : t.v) {
      lo = PointNm{min_of(lo.x_nm, p.x_nm), min_of(lo.y_nm, p.y_nm), min_of(lo.z_nm, p.z_nm)};
      hi = PointNm{max_of(hi.x_nm, p.x_nm), max_of(hi.y_nm, p.y_nm), max_of(hi.z_nm, p.z_nm)};
    }
  const int64_t span = max_of(hi.x_nm - lo.x_nm, hi.y_nm - lo.y_nm);
  GridGeometry geo;
  geo.pitch_nm = max_of<int64_t>(1, div_ceil(span, kMaxSide - 3));
  geo.nx = static_cast<int32_t>(div_ceil(hi.x_nm - lo.x_nm, geo.pitch_nm) + 3);
  geo.ny = static_cast<int32_t>(div_ceil(hi.y_nm - lo.y_nm, geo.pitch_nm) + 3);
  geo.x0_nm = lo.x_nm - geo.pitch_nm;
  geo.y0_nm = lo.y_nm - geo.pitch_nm;
  geo.z0_nm = lo.z_nm;
  geo.lsb_nm = lsb_for_range(max_of<int64_t>(hi.z_nm - lo.z_nm, 1), 16);
  static std::vector<int32_t> tops(kMaxSide * kMaxSide);
  DesignGrid d;
  if (!ok(design_init(&d, geo, tops.data(), tops.size()))) return 0;  // wider than the design's range
  std::vector<bool> added(tris.size());
  for (size_t k = 0; k < tris.size(); ++k) added[k] = ok(design_add_triangle(&d, tris[k]));

  const I128 lsb = geo.lsb_nm;
  for (int32_t j = 0; j < geo.ny; ++j)
    for (int32_t i = 0; i < geo.nx; ++i) {
      bool any = false;
      I128 best_num = 0, best_den = 1;
      for (size_t k = 0; k < tris.size(); ++k) {
        if (!added[k]) continue;
        I128 x[3], y[3], z[3];
        for (int v = 0; v < 3; ++v) {
          x[v] = tris[k].v[v].x_nm - geo.x0_nm;
          y[v] = tris[k].v[v].y_nm - geo.y0_nm;
          z[v] = tris[k].v[v].z_nm - geo.z0_nm;
        }
        I128 num, den;
        if (!height_over(x, y, z, static_cast<I128>(i) * geo.pitch_nm, static_cast<I128>(j) * geo.pitch_nm, &num, &den))
          continue;
        if (!any || greater(num, den, best_num, best_den)) {
          best_num = num;
          best_den = den;
        }
        any = true;
      }
      const int32_t top = tops[d.index(i, j)];
      FUZZ_REQUIRE(any == (top != kNoDesign));
      if (!any) continue;
      // |top * lsb - num / den| <= lsb / 2 + 2, times 2 den.
      I128 diff = 2 * (static_cast<I128>(top) * lsb * best_den - best_num);
      if (diff < 0) diff = -diff;
      FUZZ_REQUIRE(diff <= (lsb + 4) * best_den);
    }
  return 0;
}

}  // namespace fuzz_stl

DEXMILL_FUZZ_ENTRY(fuzz_stl::fuzz_stl)
