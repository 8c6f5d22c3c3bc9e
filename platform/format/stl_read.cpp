// STL input; see stl_read.h. The reading is core/design/stl_mesh.h's
// (freestanding, the page's too); here the file and the messages.
#include "platform/format/stl_read.h"

#include <cstdint>
#include <vector>

#include "core/design/stl_mesh.h"
#include "platform/os/read_file.h"

namespace dexmill {

namespace {

std::string at_triangle(const std::string& path, uint64_t k, const char* what) {
  return path + ": error: triangle " + std::to_string(k) + ": " + what;
}

// The caller's callback, and the message it stopped with.
struct Handoff {
  const std::function<bool(const PointNm*, std::string*)>* cb;
  std::string message;
};
bool hand_on(void* ctx, const PointNm* v) {
  Handoff& h = *static_cast<Handoff*>(ctx);
  return (*h.cb)(v, &h.message);
}

// The message for a scan's fault in the file `path` of `n` bytes.
std::string fault_text(const std::string& path, const StlScan& s, const Handoff& h, const uint8_t* b, size_t n) {
  const std::string at_line = path + ":" + std::to_string(s.line) + ": error: ";
  const std::string line = s.binary ? "" : " (line " + std::to_string(s.line) + ")";
  switch (s.fault) {
    case StlFault::kNotStl: {
      if (n < 84) return path + ": error: not an STL file (too short for a binary header, no 'solid')";
      const uint64_t count = stl_binary_count(b);
      return path + ": error: not an STL file: binary STL of " + std::to_string(count) + " triangles needs " +
             std::to_string(84 + 50 * count) + " bytes, the file has " + std::to_string(n) + " (truncated?)";
    }
    case StlFault::kNoSolid: return at_line + "expected 'solid' at the start of an ASCII STL file";
    case StlFault::kNoTriangles: return path + ": error: the mesh has no triangles";
    case StlFault::kNotNumber: return at_triangle(path, s.triangles + 1, "vertex is not a number") + line;
    case StlFault::kBeyond: return at_triangle(path, s.triangles + 1, "vertex beyond +-10 m") + line;
    case StlFault::kExpected:
      return at_line + "expected '" + s.expected + "', found " +
             (s.found[0] ? "'" + std::string(s.found) + "'" : std::string("the end of the file"));
    case StlFault::kNoEndsolid: return at_line + "the file ends before 'endsolid' (truncated?)";
    case StlFault::kEndsInFacet: return at_line + "the file ends inside a facet (truncated?)";
    case StlFault::kStopped: return at_triangle(path, s.triangles, h.message.c_str());
    case StlFault::kNone: break;
  }
  return "";
}

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
  Handoff h{&on_triangle, {}};
  StlScan s;
  const bool ok = stl_scan(b.data(), b.size(), offset, hand_on, &h, &s);
  info->triangles = s.triangles;
  info->binary = s.binary;
  if (ok) return StlRead::kOk;
  *err = fault_text(path, s, h, b.data(), b.size());
  return StlRead::kInputError;
}

}  // namespace dexmill
