// Reading STL meshes (binary and ASCII), for the design part (`--design
// FILE.stl`): each vertex becomes integer nanometres once, here (floats end
// in platform/), and each triangle is handed to a callback, so no mesh is
// held in memory. Binary is recognised by its size (84 + 50 n bytes for the
// count n in its header), whatever its first bytes say (many binary files
// start with "solid"); anything else must be ASCII STL.
//
// Errors name the file and the triangle (1-based) or the line:
//   part.stl: error: triangle 1207: vertex is not a number
//   part.stl:12: error: expected 'vertex', found 'vertx'
// A truncated file, a file with no triangle, a coordinate that is not
// finite or beyond +-10 m: input errors (exit 1). Unreadable: an I/O error.
#ifndef DEXMILL_PLATFORM_FORMAT_STL_READ_H
#define DEXMILL_PLATFORM_FORMAT_STL_READ_H

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/point.h"

namespace dexmill {

enum class StlRead : uint8_t { kOk, kInputError, kIoError };

struct StlReadInfo {
  uint64_t triangles = 0;
  bool binary = false;
};

// Calls on_triangle(v0, v1, v2) for every facet (machine coordinates, nm,
// `offset` added); the callback returns false to stop with its own message
// (*err set by the caller's lambda through `err`). On failure *err holds the
// whole message ("FILE: error: ...").
StlRead stl_read(const std::string& path, const PointNm& offset,
                 const std::function<bool(const PointNm*, std::string*)>& on_triangle, StlReadInfo* info,
                 std::string* err);

// The same over a file's bytes already in memory; `name` stands for the
// file in messages (the fuzz target, tests/fuzz/fuzz_stl.cpp, reads no file).
StlRead stl_parse(const std::string& name, const std::vector<unsigned char>& bytes, const PointNm& offset,
                  const std::function<bool(const PointNm*, std::string*)>& on_triangle, StlReadInfo* info,
                  std::string* err);

}  // namespace dexmill

#endif
