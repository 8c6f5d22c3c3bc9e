// The backplot: the toolpath drawn over a frame with the frame's camera, as
// AXIS, CNCjs and CAMotics show it. Rapids dashed and feeds solid in
// colours of their own. The moves already made are strong and depth-tested
// against the frame's depth buffer (the part hides what is behind it); the
// moves to come are pale and drawn over everything, since most of them run
// inside stock not yet cut. Neither writes the depth buffer.
//
// Exactness: each segment is clipped to the view and projected the way the
// triangles are (display/raster/clip.h), then drawn one pixel per step along its
// longer screen axis; which pixel a step lights and its depth depend on the
// segment only, never on the clip rectangle, so redrawing every segment
// inside a rectangle (in program order: a later segment covers an earlier
// one) gives the pixels a full redraw gives there. The depth test lets a
// segment through where it lies no farther than `kBackplotDepthBias` depth
// units behind the surface: a path runs on the surface it cuts (the tool
// tip on the floor), so it must win against that surface, not lose to
// rounding.
#ifndef DEXMILL_DISPLAY_OVERLAY_BACKPLOT_H
#define DEXMILL_DISPLAY_OVERLAY_BACKPLOT_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/camera.h"
#include "display/raster/framebuffer.h"
#include "display/overlay/overlay.h"

namespace dexmill {

enum class PathKind : uint8_t { kRapid = 0, kFeed = 1 };

// One straight piece of the path (an arc is several, its chords).
struct PathSegment {
  PointNm a, b;  // tool tip, machine coordinates
  PathKind kind;
};

struct BackplotColours {
  Rgb rapid_todo{196, 186, 140}, rapid_done{255, 226, 40};
  Rgb feed_todo{156, 200, 236}, feed_done{24, 100, 255};
};

constexpr int32_t kBackplotMinDepthBias = 1 << 10;
// Rapids are drawn 4 pixels on, 4 off along their longer screen axis.
constexpr int32_t kBackplotDashPx = 4;

// Draws segs[0, n) over fb inside `clip` (clipped to the frame), those
// before index `done` in the done colours, depth-tested against z (the
// frame's depth buffer; its format says how depths are stored), each line
// width_px pixels across and its dashes width_px times as long: 2 in a
// frame supersampled 2x2 (display/view/supersample.h), so the averaged picture
// shows a line one of its pixels wide at full strength, anti-aliased.
// Returns the rectangle of the pixels it may have changed (empty if none).
ScreenRect backplot_draw(const FrameView& fb, const DepthView& z, const View& v, const PathSegment* segs, uint32_t n,
                         uint32_t done, ScreenRect clip, const BackplotColours& colours, int32_t width_px = 1);

// The depth bias of a view (above), in depth units.
int32_t backplot_depth_bias(const View& v);

// The screen rectangle segs[from, to) may light (empty when none is in
// view): what changes when they turn from to-come to done.
ScreenRect backplot_bounds(const FrameView& fb, const View& v, const PathSegment* segs, uint32_t from, uint32_t to,
                           int32_t width_px = 1);

}  // namespace dexmill

#endif
