// The span rasterizer, paper §2.4's polygons drawn without OpenGL.
//
// Triangles arrive in screen space with kSubpixelBits fraction bits. Coverage
// is decided by three integer edge functions evaluated at pixel centres,
// exactly (64-bit products, no rounding), with the top-left fill rule: a
// pixel centre on an edge belongs to the triangle only if that edge is a top
// edge (horizontal, the triangle below it) or a left edge. Two triangles that
// share an edge therefore leave no crack and draw no pixel twice, and whether
// a pixel is covered never depends on the clip rectangle.
//
// Each row's covered pixels form one span [x0, x1), filled left to right with
// the depth test; a triangle whose bounding box holds at most 3 x 3 pixel
// centres (most of them on fine grids) takes a shorter path with the same
// coverage rule and barycentric attributes.
//
// Attributes (depth and shade) are planes a + gx*x + gy*y with integer
// gradients rounded once per triangle; the value at a pixel is a function of
// the pixel and the triangle only, so stepping along a clipped span gives the
// same bits as stepping along the whole span (incremental redraw relies on
// it). Truncating the gradients costs under 1 LSB of gradient per pixel of
// distance from vertex 0: at most 1/4 shade step and 2^7 depth units across
// the guard band, both inside the margins below.
#ifndef DEXMILL_DISPLAY_RASTER_RASTER_H
#define DEXMILL_DISPLAY_RASTER_RASTER_H

#include <stddef.h>
#include <stdint.h>

#include "display/raster/framebuffer.h"

namespace dexmill {

constexpr int kSubpixelBits = 4;               // screen coordinates are q4
constexpr int32_t kSubpixelOne = 1 << kSubpixelBits;
// Vertices may lie this far outside the frame; farther ones are clipped
// geometrically first (display/raster/clip.h). Keeps every coordinate below 2^17 q4.
constexpr int32_t kGuardPx = 2048;

// Vertex depths lie in [kDepthMargin, kDepthMax - kDepthMargin]; smaller is
// nearer. The margin absorbs gradient rounding, so interpolated depths never
// leave [0, kDepthMax).
constexpr int kDepthBits = 24;
constexpr int32_t kDepthMax = 1 << kDepthBits;
constexpr int32_t kDepthMargin = 1 << 12;

// Shades index a 256-entry table of pixel values (display/surface/shade.h).
constexpr int32_t kShadeLevels = 256;

enum class ZFormat : uint8_t {
  kZ16 = 0,  // uint16 per pixel: the top 16 of the 31 interpolated depth bits
  kZ32 = 1,  // uint32 per pixel: all 31 bits (24 integer + 7 fraction)
};
int32_t z_bytes(ZFormat f);

struct RasterVertex {
  int32_t x_q4, y_q4;  // screen position; pixel (px, py) has its centre at (16px + 8, 16py + 8)
  int32_t depth;       // [kDepthMargin, kDepthMax - kDepthMargin], smaller is nearer
  int32_t shade;       // 0 .. kShadeLevels - 1
  uint32_t rgb = 0;    // with RasterTarget::vertex_rgb: the lit colour, 0x00RRGGBB
};

struct RasterStats {
  uint64_t triangles = 0;       // submitted to raster_triangle
  uint64_t pixels_written = 0;  // fragments that passed the depth test
};

// Where and how triangles are drawn. Colour and depth buffers are caller
// memory of the frame's size; `clip` limits writes (within the frame).
struct RasterTarget {
  uint8_t* color = nullptr;
  int32_t color_stride = 0;  // bytes
  PixelFormat format = PixelFormat::kXrgb8888;
  uint8_t* z = nullptr;
  int32_t z_stride = 0;  // bytes
  ZFormat zformat = ZFormat::kZ32;
  ScreenRect clip{0, 0, 0, 0};
  const uint32_t* lut = nullptr;  // kShadeLevels stored pixel values
  bool cull_back = true;          // drop triangles seen from behind (clockwise on screen)
  // Colour per vertex (paper §2.7.1: a 3-D texture evaluated at the
  // vertices, Gouraud between them): the three channels of RasterVertex::rgb
  // are interpolated like the shade and packed per pixel; `lut` and `shade`
  // are unused.
  bool vertex_rgb = false;
  // Coverage count mode (the fill-rule tests, overdraw pictures): each
  // covered pixel adds 1 to the byte at `color` + y * color_stride + x; no
  // depth test, no depth or colour write.
  bool count_coverage = false;
  RasterStats stats;
};

// Depth-tested, Gouraud-shaded triangle (a shade through `lut`, or with
// vertex_rgb a colour per vertex). Front faces are counterclockwise
// as seen on the screen (x right, y down).
void raster_triangle(RasterTarget* t, const RasterVertex& a, const RasterVertex& b, const RasterVertex& c);

// Clears colour (to `color_value`) and depth (to the farthest value) in r.
void raster_clear(RasterTarget* t, const ScreenRect& r, uint32_t color_value);

}  // namespace dexmill

#endif
