// Test scenes for the display: grids milled with the project's own cutting
// code (core/cut/stamp.h), renderers over std::vector memory, and PPM dumps of
// frames for looking at (DEXMILL_TEST_IMAGES=DIR; tests/ppm2png.py turns them
// into PNG).
#ifndef DEXMILL_TESTS_SCENE_UTIL_H
#define DEXMILL_TESTS_SCENE_UTIL_H

#include <cstdint>
#include <vector>

#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "display/surface/render.h"

namespace t {

using dexmill::DexelGrid;

// A grid and its memory.
template <class H>
struct TestGrid {
  DexelGrid<H> g;
  std::vector<H> top, bottom;
};

// nx x ny dexels at `pitch_nm`, the stock grid_block_stock'ed to `height_nm`,
// LSB from lsb_for_range(1.25 * height).
template <class H>
void make_block(TestGrid<H>* tg, int32_t nx, int32_t ny, int64_t pitch_nm, int64_t height_nm);

// A cutter dexel set for a tool at the grid's pitch and LSB.
struct TestCutter {
  dexmill::Tool tool;
  dexmill::ToolProfile profile;
  std::vector<int32_t> words;
  dexmill::CutterDexels c;
};
template <class H>
void make_cutter(const DexelGrid<H>& g, const dexmill::Tool& tool, TestCutter* out);

dexmill::Tool ball_tool(int64_t diameter_nm);
dexmill::Tool flat_tool(int64_t diameter_nm);
dexmill::Tool bull_tool(int64_t diameter_nm, int64_t corner_nm);
dexmill::Tool vbit_tool(int64_t diameter_nm, int32_t angle_mdeg);

// A pocketed block: 60 x 40 dexels of 1 mm, 20 mm high; a flat pocket 6 mm
// deep, a ball-end channel, a V groove, and a through hole (flat end mill
// plunged through), so holes, diagonals and walls all appear.
template <class H>
void make_pocketed(TestGrid<H>* tg);

// A frame and the renderer's memory.
struct TestFrame {
  std::vector<uint32_t> pixels;  // large enough for either format
  dexmill::FrameView fb;
  std::vector<uint64_t> scratch;
};
void make_frame(TestFrame* f, int32_t w, int32_t h, dexmill::PixelFormat fmt);

template <class H>
bool init_renderer(dexmill::Renderer<H>* r, const DexelGrid<H>& g, TestFrame* f,
                   const dexmill::RenderOptions& opt = dexmill::RenderOptions());

// Writes the frame as DIR/NAME.ppm when DEXMILL_TEST_IMAGES=DIR is set.
void dump_frame(const dexmill::FrameView& fb, const char* name);

// Pixels that differ between `now` and `before` (same size and format)
// outside every rectangle of res: what an incremental redraw failed to report.
int uncovered_changes(const dexmill::FrameView& now, const dexmill::FrameView& before, const dexmill::RenderResult& res);
// Prints the first pixel where an incremental frame differs from a full one
// and dumps both as <prefix>_actual and <prefix>_expected.
void report_first_difference(const char* what, int step, const dexmill::FrameView& incremental,
                             const dexmill::FrameView& full, const char* prefix);

}  // namespace t

#endif
