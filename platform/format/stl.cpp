// Streaming STL writer; see stl.h.
#include "platform/format/stl.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "platform/os/output_file.h"
#include "platform/mesh/stl_merge.h"

namespace dexmill {
namespace {

struct Vec3f {
  float x, y, z;
};

void put_f32(uint8_t* p, float v) {
  uint32_t u;
  std::memcpy(&u, &v, 4);
  for (int k = 0; k < 4; ++k) p[k] = static_cast<uint8_t>(u >> (8 * k));  // STL is little-endian
}

class Counter final : public TriangleSink {
 public:
  void triangle(const GridPoint&, const GridPoint&, const GridPoint&) override { ++count; }
  uint64_t count = 0;
};

template <class H>
uint64_t count_triangles(const DexelGrid<H>& g, const SurfaceMaterial& material, int64_t tolerance_lsb) {
  Counter c;
  merged_surface(g, material, tolerance_lsb, &c);
  return c.count;
}

// Triangles as STL records in mm, through a buffer of a thousand.
template <class H>
class Writer final : public TriangleSink {
 public:
  Writer(const DexelGrid<H>& g, OutputFile* f) : g_(g), f_(f), buf_(kBatch * 50), x_mm_(g.nx), y_mm_(g.ny) {
    for (int32_t i = 0; i < g.nx; ++i) x_mm_[i] = mm(g.x0_nm + static_cast<int64_t>(i) * g.pitch_nm);
    for (int32_t j = 0; j < g.ny; ++j) y_mm_[j] = mm(g.y0_nm + static_cast<int64_t>(j) * g.pitch_nm);
  }
  void triangle(const GridPoint& a, const GridPoint& b, const GridPoint& c) override {
    const Vec3f v[3] = {to_mm(a), to_mm(b), to_mm(c)};
    const double ux = v[1].x - v[0].x, uy = v[1].y - v[0].y, uz = v[1].z - v[0].z;
    const double wx = v[2].x - v[0].x, wy = v[2].y - v[0].y, wz = v[2].z - v[0].z;
    double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (len > 0) { nx /= len; ny /= len; nz /= len; }
    uint8_t* p = buf_.data() + used_ * 50;
    put_f32(p, static_cast<float>(nx));
    put_f32(p + 4, static_cast<float>(ny));
    put_f32(p + 8, static_cast<float>(nz));
    for (int k = 0; k < 3; ++k) {
      put_f32(p + 12 + 12 * k, v[k].x);
      put_f32(p + 16 + 12 * k, v[k].y);
      put_f32(p + 20 + 12 * k, v[k].z);
    }
    p[48] = p[49] = 0;
    if (++used_ == kBatch) flush();
  }
  // The same grid point always gives the same floats.
  static float mm(int64_t nm) { return static_cast<float>(static_cast<double>(nm) / 1e6); }
  Vec3f to_mm(const GridPoint& p) const { return Vec3f{x_mm_[p.i], y_mm_[p.j], mm(g_.z0_nm + p.h_lsb * g_.lsb_nm)}; }

  void flush() {
    f_->write(buf_.data(), used_ * 50);
    used_ = 0;
  }

 private:
  static constexpr size_t kBatch = 1024;
  const DexelGrid<H>& g_;
  OutputFile* f_;
  std::vector<uint8_t> buf_;
  size_t used_ = 0;
  std::vector<float> x_mm_, y_mm_;  // of each dexel column and row
};

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
uint64_t stl_triangle_count(const DexelGrid<H>& g, int64_t tolerance_lsb) {
  return count_triangles(g, SurfaceMaterial(g), tolerance_lsb);
}

template <class H>
bool write_stl(const char* path, const DexelGrid<H>& g, int64_t tolerance_lsb, char* err, std::size_t errn) {
  const SurfaceMaterial material(g);
  const uint64_t count = count_triangles(g, material, tolerance_lsb);
  if (count > 0xffffffffu) {
    std::snprintf(err, errn, "cannot write '%s': %llu triangles are more than STL can count", path,
                  static_cast<unsigned long long>(count));
    return false;
  }
  // A fine grid makes a huge mesh: say how big before writing it (an
  // interrupt removes the part written, platform/os/process.h).
  const std::string note = stl_size_note(count, path);
  if (!note.empty()) std::fprintf(stderr, "%s\n", note.c_str());
  OutputFile f;
  if (f.open(path)) {
    uint8_t header[84] = {0};
    std::snprintf(reinterpret_cast<char*>(header), 80, "dexmill workpiece, mm, %dx%d dexels", static_cast<int>(g.nx),
                  static_cast<int>(g.ny));
    for (int k = 0; k < 4; ++k) header[80 + k] = static_cast<uint8_t>(count >> (8 * k));
    f.write(header, sizeof header);
    Writer<H> w(g, &f);
    merged_surface(g, material, tolerance_lsb, &w);
    w.flush();
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

#define DEXMILL_STL_INSTANTIATE(H)                                  \
  template uint64_t stl_triangle_count<H>(const DexelGrid<H>&, int64_t); \
  template bool write_stl<H>(const char*, const DexelGrid<H>&, int64_t, char*, std::size_t);
DEXMILL_STL_INSTANTIATE(uint8_t)
DEXMILL_STL_INSTANTIATE(uint16_t)
DEXMILL_STL_INSTANTIATE(uint32_t)

}  // namespace dexmill
