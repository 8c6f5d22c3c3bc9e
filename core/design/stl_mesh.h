// STL meshes read from bytes in memory, freestanding (integer only, no
// heap): binary STL (an 80-byte header, a count, 50 bytes a facet) and
// ASCII STL (solid / facet normal / outer loop / vertex x y z x3 / endloop
// / endfacet / endsolid, words case-insensitive), vertices in mm turned to
// nm exactly, rounded to nearest (ties away from zero). What a design and
// a stock blank are read with: platform/format/stl_read.cpp over a file
// (its messages), the page over a File's bytes (platform/web/web_colour.cpp).
#ifndef DEXMILL_CORE_DESIGN_STL_MESH_H
#define DEXMILL_CORE_DESIGN_STL_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "core/point.h"

namespace dexmill {

enum class StlFault : uint8_t {
  kNone,
  kNotStl,        // neither binary STL of its size nor text starting with "solid"
  kNoSolid,       // text whose first word is not "solid" ("solidx")
  kNoTriangles,   // a mesh of none
  kNotNumber,     // a vertex's coordinate does not parse (or is NaN in binary)
  kBeyond,        // a coordinate beyond +-10 m (or infinite)
  kExpected,      // a word other than `expected` (found: the word, "" at the end)
  kNoEndsolid,    // the text ends before "endsolid"
  kEndsInFacet,   // the text ends inside a facet
  kStopped        // the caller's on_triangle said stop
};

constexpr size_t kStlWordMax = 64;  // longer words are read as several
constexpr int64_t kStlMaxCoordNm = 10000LL * 1000 * 1000;  // 10 m, as G-code positions

struct StlScan {
  uint64_t triangles = 0;  // read (and handed on) before the fault, if any
  bool binary = false;
  StlFault fault = StlFault::kNone;
  uint32_t line = 1;                 // ASCII: the line the reader is on
  const char* expected = nullptr;    // kExpected: "facet", "outer loop", ...
  char found[kStlWordMax + 1] = {};  // kExpected: the word found
};

// Hands every facet of b[0, n) to on_triangle(ctx, v) (three vertices,
// machine coordinates, `offset` added); it returns false to stop. True when
// the whole mesh was read (out->fault kNone); else out says why and where.
bool stl_scan(const uint8_t* b, size_t n, const PointNm& offset, bool (*on_triangle)(void* ctx, const PointNm* v),
              void* ctx, StlScan* out);

// A binary header's facet count (n >= 84 bytes).
uint32_t stl_binary_count(const uint8_t* b);

}  // namespace dexmill

#endif
