// Streaming STL writer; see stl.h.
#include "platform/stl.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "display/mesh.h"
#include "platform/output_file.h"

namespace dexmill {
namespace {

struct Vec3f {
  float x, y, z;
};

// Calls emit(a, b, c) for every triangle, counterclockwise seen from outside
// (vertices as grid points: i, j and a height in LSB).
struct GridPoint {
  int32_t i, j;
  int64_t h;
};

const int kDi[4] = {0, 1, 1, 0}, kDj[4] = {0, 0, 1, 1};

template <class H>
int cell_mask(const DexelGrid<H>& g, const std::vector<uint8_t>& material, int32_t i, int32_t j) {
  int mask = 0;
  for (int c = 0; c < 4; ++c) mask |= material[g.index(i + kDi[c], j + kDj[c])] << c;
  return mask;
}

// Which dexels the surface treats as material. The cell table joins
// material across diagonals, but a feature one dexel wide has no width in
// this surface: its walls on both sides meet on the dexel's axis, where its
// vertical edge would be shared by four triangles. Such a dexel is where two
// walls start (one per side); it holds no volume, so it is left out, again
// until none is left, and the surface is 2-manifold.
template <class H>
std::vector<uint8_t> surface_material(const DexelGrid<H>& g) {
  std::vector<uint8_t> m(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny));
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) m[g.index(i, j)] = g.is_hole(i, j) ? 0 : 1;
  for (bool changed = true; changed;) {
    changed = false;
    for (int32_t j = 0; j < g.ny; ++j) {
      for (int32_t i = 0; i < g.nx; ++i) {
        if (!m[g.index(i, j)]) continue;
        int starts = 0;
        for (int c = 0; c < 4; ++c) {  // the cells that have (i, j) as corner c
          const int32_t ci = i - kDi[c], cj = j - kDj[c];
          if (ci < 0 || cj < 0 || ci + 1 >= g.nx || cj + 1 >= g.ny) continue;
          const CellCase& cc = kCellCases[cell_mask(g, m, ci, cj)];
          if (cc.has_wall && cc.wall[0] == c) ++starts;
        }
        if (starts > 1) {
          m[g.index(i, j)] = 0;
          changed = true;
        }
      }
    }
  }
  return m;
}

template <class H, class Emit>
void for_each_triangle(const DexelGrid<H>& g, const std::vector<uint8_t>& material, Emit emit) {
  for (int32_t j = 0; j + 1 < g.ny; ++j) {
    for (int32_t i = 0; i + 1 < g.nx; ++i) {
      const int mask = cell_mask(g, material, i, j);
      if (!mask) continue;
      GridPoint top[4], bot[4];
      for (int c = 0; c < 4; ++c) {
        const int32_t ci = i + kDi[c], cj = j + kDj[c];
        const size_t k = g.index(ci, cj);
        top[c] = GridPoint{ci, cj, static_cast<int64_t>(g.top[k])};
        bot[c] = GridPoint{ci, cj, static_cast<int64_t>(g.bottom[k])};
      }
      const CellCase& cc = kCellCases[mask];
      for (int t = 0; t < cc.ntop; ++t) {
        const uint8_t* v = cc.top[t];
        emit(top[v[0]], top[v[1]], top[v[2]]);
        emit(bot[v[0]], bot[v[2]], bot[v[1]]);
      }
      if (cc.has_wall) {
        // The wall runs from a to b with the material on its left: its
        // outward side faces right, which these windings give.
        const int a = cc.wall[0], b = cc.wall[1];
        emit(top[a], bot[a], bot[b]);
        emit(top[a], bot[b], top[b]);
      }
    }
  }
}

template <class H>
Vec3f to_mm(const DexelGrid<H>& g, const GridPoint& p) {
  const double x = static_cast<double>(g.x0_nm + static_cast<int64_t>(p.i) * g.pitch_nm) / 1e6;
  const double y = static_cast<double>(g.y0_nm + static_cast<int64_t>(p.j) * g.pitch_nm) / 1e6;
  const double z = static_cast<double>(g.z0_nm + p.h * g.lsb_nm) / 1e6;
  return Vec3f{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

void put_f32(uint8_t* p, float v) {
  uint32_t u;
  std::memcpy(&u, &v, 4);
  for (int k = 0; k < 4; ++k) p[k] = static_cast<uint8_t>(u >> (8 * k));  // STL is little-endian
}

template <class H>
uint64_t count_triangles(const DexelGrid<H>& g, const std::vector<uint8_t>& material) {
  uint64_t n = 0;
  for_each_triangle(g, material, [&n](const GridPoint&, const GridPoint&, const GridPoint&) { ++n; });
  return n;
}

}  // namespace

std::string stl_size_note(uint64_t triangles, const char* path) {
  const uint64_t bytes = 84 + 50 * triangles;
  if (bytes <= kStlAnnounceBytes) return std::string();
  char b[1300];
  std::snprintf(b, sizeof b, "dexmill: writing a %.1f GB STL (%llu triangles) to '%s'", static_cast<double>(bytes) / 1e9,
                static_cast<unsigned long long>(triangles), path);
  return b;
}

template <class H>
uint64_t stl_triangle_count(const DexelGrid<H>& g) {
  return count_triangles(g, surface_material(g));
}

template <class H>
bool write_stl(const char* path, const DexelGrid<H>& g, char* err, std::size_t errn) {
  const std::vector<uint8_t> material = surface_material(g);
  const uint64_t count = count_triangles(g, material);
  if (count > 0xffffffffu) {
    std::snprintf(err, errn, "cannot write '%s': %llu triangles are more than STL can count", path,
                  static_cast<unsigned long long>(count));
    return false;
  }
  // A fine grid makes a huge mesh: say how big before writing it (an
  // interrupt removes the part written, platform/process.h).
  const std::string note = stl_size_note(count, path);
  if (!note.empty()) std::fprintf(stderr, "%s\n", note.c_str());
  OutputFile f;
  if (f.open(path)) {
    uint8_t header[84] = {0};
    std::snprintf(reinterpret_cast<char*>(header), 80, "dexmill workpiece, mm, %dx%d dexels", static_cast<int>(g.nx),
                  static_cast<int>(g.ny));
    for (int k = 0; k < 4; ++k) header[80 + k] = static_cast<uint8_t>(count >> (8 * k));
    f.write(header, sizeof header);
    constexpr size_t kBatch = 1024;
    std::vector<uint8_t> buf(kBatch * 50);
    size_t used = 0;
    for_each_triangle(g, material, [&](const GridPoint& a, const GridPoint& b, const GridPoint& c) {
      const Vec3f v[3] = {to_mm(g, a), to_mm(g, b), to_mm(g, c)};
      const double ux = v[1].x - v[0].x, uy = v[1].y - v[0].y, uz = v[1].z - v[0].z;
      const double wx = v[2].x - v[0].x, wy = v[2].y - v[0].y, wz = v[2].z - v[0].z;
      double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
      const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
      if (len > 0) { nx /= len; ny /= len; nz /= len; }
      uint8_t* p = buf.data() + used * 50;
      put_f32(p, static_cast<float>(nx));
      put_f32(p + 4, static_cast<float>(ny));
      put_f32(p + 8, static_cast<float>(nz));
      for (int k = 0; k < 3; ++k) {
        put_f32(p + 12 + 12 * k, v[k].x);
        put_f32(p + 16 + 12 * k, v[k].y);
        put_f32(p + 20 + 12 * k, v[k].z);
      }
      p[48] = p[49] = 0;
      if (++used == kBatch) {
        f.write(buf.data(), used * 50);
        used = 0;
      }
    });
    f.write(buf.data(), used * 50);
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

#define DEXMILL_STL_INSTANTIATE(H)                                  \
  template uint64_t stl_triangle_count<H>(const DexelGrid<H>&); \
  template bool write_stl<H>(const char*, const DexelGrid<H>&, char*, std::size_t);
DEXMILL_STL_INSTANTIATE(uint8_t)
DEXMILL_STL_INSTANTIATE(uint16_t)
DEXMILL_STL_INSTANTIATE(uint32_t)

}  // namespace dexmill
