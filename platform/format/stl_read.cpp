// STL input; see stl_read.h.
#include "platform/format/stl_read.h"

#include <strings.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "platform/os/read_file.h"

namespace dexmill {

namespace {

constexpr double kMaxCoordMm = 10000.0;  // 10 m, as G-code positions

std::string at_triangle(const std::string& path, uint64_t k, const char* what) {
  return path + ": error: triangle " + std::to_string(k) + ": " + what;
}

// mm (as read) -> nm with the offset; false when not finite or too large.
bool to_nm(double mm, int64_t offset_nm, int64_t* nm) {
  if (!std::isfinite(mm) || std::fabs(mm) > kMaxCoordMm) return false;
  *nm = static_cast<int64_t>(std::llround(mm * 1e6)) + offset_nm;
  return true;
}

uint32_t le32(const unsigned char* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}
float le_float(const unsigned char* p) {
  const uint32_t u = le32(p);
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

StlRead read_binary(const std::string& path, const std::vector<unsigned char>& b, const PointNm& off,
                    const std::function<bool(const PointNm*, std::string*)>& cb, StlReadInfo* info, std::string* err) {
  const uint32_t n = le32(&b[80]);
  for (uint32_t k = 0; k < n; ++k) {
    const unsigned char* f = &b[84 + 50 * static_cast<size_t>(k)];
    PointNm v[3];
    for (int i = 0; i < 3; ++i) {
      const unsigned char* c = f + 12 + 12 * i;  // after the normal
      if (!to_nm(le_float(c), off.x_nm, &v[i].x_nm) || !to_nm(le_float(c + 4), off.y_nm, &v[i].y_nm) ||
          !to_nm(le_float(c + 8), off.z_nm, &v[i].z_nm)) {
        const float x = le_float(c), y = le_float(c + 4), z = le_float(c + 8);
        const bool nan = !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z);
        *err = at_triangle(path, k + 1ull, nan ? "vertex is not a number" : "vertex beyond +-10 m");
        return StlRead::kInputError;
      }
    }
    ++info->triangles;
    std::string m;
    if (!cb(v, &m)) {
      *err = at_triangle(path, k + 1ull, m.c_str());
      return StlRead::kInputError;
    }
  }
  return StlRead::kOk;
}

// ASCII STL: solid NAME / facet normal x y z / outer loop / vertex x y z (3)
// / endloop / endfacet ... / endsolid. Words are case-insensitive.
class AsciiStl {
 public:
  AsciiStl(const std::string& path, const std::vector<unsigned char>& b) : path_(path), b_(b) {}

  StlRead read(const PointNm& off, const std::function<bool(const PointNm*, std::string*)>& cb, StlReadInfo* info,
               std::string* err) {
    std::string w;
    if (!word(&w) || !is(w, "solid")) return fail("expected 'solid' at the start of an ASCII STL file", err);
    skip_line();  // the solid's name
    for (;;) {
      if (!word(&w)) return fail("the file ends before 'endsolid' (truncated?)", err);
      if (is(w, "endsolid")) break;
      if (!is(w, "facet")) return expected("facet", w, err);
      skip_line();  // normal nx ny nz: recomputed from the vertices where needed
      if (!word(&w) || !is(w, "outer")) return expected("outer loop", w, err);
      if (!word(&w) || !is(w, "loop")) return expected("loop", w, err);
      PointNm v[3];
      const uint64_t k = info->triangles + 1;
      for (int i = 0; i < 3; ++i) {
        if (!word(&w)) return fail("the file ends inside a facet (truncated?)", err);
        if (!is(w, "vertex")) return expected("vertex", w, err);
        int64_t* c[3] = {&v[i].x_nm, &v[i].y_nm, &v[i].z_nm};
        const int64_t o[3] = {off.x_nm, off.y_nm, off.z_nm};
        for (int a = 0; a < 3; ++a) {
          double mm;
          if (!word(&w) || !number(w, &mm)) {
            *err = at_triangle(path_, k, "vertex is not a number") + " (line " + std::to_string(line_) + ")";
            return StlRead::kInputError;
          }
          if (!to_nm(mm, o[a], c[a])) {
            *err = at_triangle(path_, k, "vertex beyond +-10 m") + " (line " + std::to_string(line_) + ")";
            return StlRead::kInputError;
          }
        }
      }
      if (!word(&w) || !is(w, "endloop")) return expected("endloop", w, err);
      if (!word(&w) || !is(w, "endfacet")) return expected("endfacet", w, err);
      ++info->triangles;
      std::string m;
      if (!cb(v, &m)) {
        *err = at_triangle(path_, k, m.c_str());
        return StlRead::kInputError;
      }
    }
    return StlRead::kOk;
  }

 private:
  bool word(std::string* w) {
    w->clear();
    while (pos_ < b_.size() && std::isspace(b_[pos_])) {
      if (b_[pos_] == '\n') ++line_;
      ++pos_;
    }
    while (pos_ < b_.size() && !std::isspace(b_[pos_]) && w->size() < 64) w->push_back(static_cast<char>(b_[pos_++]));
    return !w->empty();
  }
  void skip_line() {
    while (pos_ < b_.size() && b_[pos_] != '\n') ++pos_;
  }
  static bool is(const std::string& w, const char* k) { return strcasecmp(w.c_str(), k) == 0; }
  static bool number(const std::string& w, double* v) {
    char* end = nullptr;
    errno = 0;
    *v = std::strtod(w.c_str(), &end);
    return end && *end == 0 && end != w.c_str() && errno != ERANGE;
  }
  StlRead fail(const char* what, std::string* err) {
    *err = path_ + ":" + std::to_string(line_) + ": error: " + what;
    return StlRead::kInputError;
  }
  StlRead expected(const char* want, const std::string& found, std::string* err) {
    *err = path_ + ":" + std::to_string(line_) + ": error: expected '" + want + "', found " +
           (found.empty() ? std::string("the end of the file") : "'" + found + "'");
    return StlRead::kInputError;
  }
  const std::string& path_;
  const std::vector<unsigned char>& b_;
  size_t pos_ = 0;
  uint32_t line_ = 1;
};

}  // namespace

StlRead stl_read(const std::string& path, const PointNm& offset,
                 const std::function<bool(const PointNm*, std::string*)>& on_triangle, StlReadInfo* info,
                 std::string* err) {
  *info = StlReadInfo{};
  // Design meshes are read whole (a few hundred MB at most).
  std::vector<unsigned char> b;
  switch (read_whole_file(path, static_cast<size_t>(1) << 31, &b, err)) {
    case ReadFile::kOk: break;
    case ReadFile::kTooLarge: return StlRead::kInputError;
    case ReadFile::kIoError: return StlRead::kIoError;
  }
  return stl_parse(path, b, offset, on_triangle, info, err);
}

StlRead stl_parse(const std::string& path, const std::vector<unsigned char>& b, const PointNm& offset,
                  const std::function<bool(const PointNm*, std::string*)>& on_triangle, StlReadInfo* info,
                  std::string* err) {
  *info = StlReadInfo{};
  StlRead r;
  if (b.size() >= 84 && b.size() == 84 + 50 * static_cast<uint64_t>(le32(&b[80]))) {
    info->binary = true;
    r = read_binary(path, b, offset, on_triangle, info, err);
  } else {
    // ASCII STL is text: a NUL byte means binary STL of the wrong size. An
    // empty file's data() may be null, which memchr must not get even for
    // 0 bytes (fuzzer: UBSan, nonnull argument).
    const bool text = b.empty() || std::memchr(b.data(), 0, b.size()) == nullptr;
    size_t k = 0;
    while (k < b.size() && std::isspace(b[k])) ++k;
    if (!text || b.size() - k < 5 || strncasecmp(reinterpret_cast<const char*>(&b[k]), "solid", 5) != 0) {
      *err = path + ": error: " +
             (b.size() >= 84 ? "not an STL file: binary STL of " + std::to_string(le32(&b[80])) +
                                   " triangles needs " + std::to_string(84 + 50 * static_cast<uint64_t>(le32(&b[80]))) +
                                   " bytes, the file has " + std::to_string(b.size()) + " (truncated?)"
                             : std::string("not an STL file (too short for a binary header, no 'solid')"));
      return StlRead::kInputError;
    }
    r = AsciiStl(path, b).read(offset, on_triangle, info, err);
  }
  if (r == StlRead::kOk && info->triangles == 0) {
    *err = path + ": error: the mesh has no triangles";
    return StlRead::kInputError;
  }
  return r;
}

}  // namespace dexmill
