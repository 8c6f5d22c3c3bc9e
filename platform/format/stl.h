// The final workpiece as a closed binary STL, for comparison with the CAD
// model: the cell surface of platform/mesh/stl_cells.h (tops, bottoms turned
// over, walls where material meets holes) with coplanar cells merged into
// larger faces (platform/mesh/stl_merge.h): flat floors and untouched tops,
// straight walls. Every edge is shared by exactly two triangles with
// opposite directions, and the solid is the cell surface's to the last bit
// (or, with a tolerance, its tops within it: platform/mesh/stl_plane.h).
//
// Streaming: one pass counts the triangles (the header needs the count
// first, and standard output or a pipe cannot be rewound to patch it), a
// second writes them through a small buffer; no mesh is held in memory.
// Coordinates are machine millimetres as float32, the same integer grid
// point always giving the same float, so shared vertices match bit for bit.
#ifndef DEXMILL_PLATFORM_FORMAT_STL_H
#define DEXMILL_PLATFORM_FORMAT_STL_H

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/grid/grid.h"

namespace dexmill {

template <class H>
uint64_t stl_triangle_count(const DexelGrid<H>& g, int64_t tolerance_lsb);

// Writes the surface to `path` atomically, its tops within tolerance_lsb
// of the grid's (at most 1: exact; platform/mesh/stl_merge.h). False with a message on failure
// (an I/O error, or more than 2^32 - 1 triangles).
template <class H>
bool write_stl(const char* path, const DexelGrid<H>& g, int64_t tolerance_lsb, char* err, std::size_t errn);

// write_stl says on standard error how large the file will be when it is
// over this size: the line stl_size_note gives (empty below it).
constexpr uint64_t kStlAnnounceBytes = uint64_t{256} << 20;
std::string stl_size_note(uint64_t triangles, const char* path);

}  // namespace dexmill

#endif
