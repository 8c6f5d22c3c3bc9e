// The pipeline target's drawing stage: two renderers of the same grid, one
// kept up to date with render_update after every step of the cut (the way
// `dexmill run` and a panel draw), the other drawing each step whole with
// render_full. display/surface/render.h promises that the two give the same pixels,
// bit for bit, and that the rectangles render_update returns cover every
// pixel it changed; both are checked after every step, with the backplot
// (display/overlay/backplot.h promises the same of a path redrawn inside those
// rectangles) and the error colour mode when the input asks for them.
#ifndef DEXMILL_TESTS_FUZZ_RENDER_H
#define DEXMILL_TESTS_FUZZ_RENDER_H

#include <cstring>
#include <vector>

#include "core/assess/assess.h"
#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "display/overlay/backplot.h"
#include "display/colour/error_colours.h"
#include "display/surface/render.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz {

// How the frames are drawn: picked by the input's header.
struct DrawSetup {
  int32_t width = 64, height = 48;
  int32_t pad_pixels = 0;  // past each row: a stride wider than the row
  dexmill::PixelFormat format = dexmill::PixelFormat::kXrgb8888;
  dexmill::RenderOptions opt;
  dexmill::Camera camera;  // fitted by RedrawCheck::init unless `fitted`
  bool fitted = false;
  int32_t zoom_shift = 0;  // > 0 zooms in, < 0 out (parts of the stock off screen)
};

template <class H>
class RedrawCheck {
 public:
  // `design` (may be null) turns on the error colour mode; `path` (may be
  // null) the backplot, whose first `*done` pieces are drawn done.
  void init(dexmill::DexelGrid<H>* g, const DrawSetup& s, const dexmill::DesignGrid* design,
            const dexmill::AssessOptions& aopt, const std::vector<dexmill::PathSegment>* path, const uint32_t* done) {
    using namespace dexmill;
    g_ = g;
    s_ = s;
    path_ = path;
    done_ = done;
    drawn_done_ = 0;
    const int32_t bpp = s.format == PixelFormat::kRgb565 ? 2 : 4;
    stride_ = (s.width + s.pad_pixels) * bpp;
    const size_t words = (static_cast<size_t>(stride_) * s.height + 3) / 4;
    // Padding bytes are never drawn: all three frames start equal there.
    inc_.assign(words, 0x5a5a5a5a);
    full_.assign(words, 0x5a5a5a5a);
    prev_.assign(words, 0x5a5a5a5a);
    const size_t n = renderer_scratch_bytes(*g, s.width, s.height, s.opt.zformat);
    scratch_inc_.assign((n + 7) / 8, 0);
    scratch_full_.assign((n + 7) / 8, 0);
    const FrameView fa{inc_.data(), s.width, s.height, stride_, s.format};
    const FrameView fb{full_.data(), s.width, s.height, stride_, s.format};
    FUZZ_REQUIRE(ok(renderer_init(&inc_r_, *g, fa, s.opt, scratch_inc_.data(), n)));
    FUZZ_REQUIRE(ok(renderer_init(&full_r_, *g, fb, s.opt, scratch_full_.data(), n)));
    Camera c = s.camera;
    if (!s.fitted) camera_fit(&c, renderer_stock_box(inc_r_), s.width, s.height);
    if (s.zoom_shift > 0) {
      c.view_height_nm >>= s.zoom_shift;
      c.distance_nm >>= s.zoom_shift;  // perspective: the eye may come into the scene
    } else if (s.zoom_shift < 0) {
      c.view_height_nm <<= -s.zoom_shift;
      c.distance_nm <<= -s.zoom_shift;
    }
    c.view_height_nm = max_of<int64_t>(c.view_height_nm, 1);
    c.distance_nm = max_of<int64_t>(c.distance_nm, 1);
    renderer_set_camera(&inc_r_, c);
    renderer_set_camera(&full_r_, c);
    // Each renderer its own classes: shared ones would let the full redraw
    // classify what the incremental one forgot.
    if (design) {
      const size_t cells = static_cast<size_t>(g->nx) * static_cast<size_t>(g->ny);
      cls_inc_.assign(cells, 0);
      cls_full_.assign(cells, 0);
      luts_inc_.assign(static_cast<size_t>(kErrorBands) * kShadeLevels, 0);
      luts_full_.assign(static_cast<size_t>(kErrorBands) * kShadeLevels, 0);
      error_colours_init(&err_inc_, *g, *design, aopt, cls_inc_.data(), luts_inc_.data());
      error_colours_init(&err_full_, *g, *design, aopt, cls_full_.data(), luts_full_.data());
      renderer_set_colours(&inc_r_, &err_inc_.colours);
      renderer_set_colours(&full_r_, &err_full_.colours);
    } else {
      renderer_set_colours(&inc_r_, nullptr);
      renderer_set_colours(&full_r_, nullptr);
    }
  }

  void set_tool(const dexmill::ToolProfile* p) {
    if (p) {
      profile_ = *p;
      p = &profile_;
    }
    dexmill::renderer_set_tool(&inc_r_, p);
    dexmill::renderer_set_tool(&full_r_, p);
  }

  // One step: the grid's dirty rectangle holds what changed since the last.
  void step(const dexmill::CutterPose& pose) {
    using namespace dexmill;
    std::memcpy(prev_.data(), inc_.data(), inc_.size() * 4);
    const uint32_t n = path_ ? static_cast<uint32_t>(path_->size()) : 0;
    const uint32_t done = path_ ? min_of(*done_, n) : 0;
    if (path_ && done > drawn_done_)
      renderer_invalidate(&inc_r_, backplot_bounds(inc_r_.fb, inc_r_.view, path_->data(), drawn_done_, done));
    const RenderResult res = render_update(&inc_r_, g_, pose);
    FUZZ_REQUIRE(res.nrects >= 0 && res.nrects <= kMaxDirtyRects);
    if (path_) {
      for (int k = 0; k < res.nrects; ++k)
        backplot_draw(inc_r_.fb, depth(inc_r_), inc_r_.view, path_->data(), n, done, res.rects[k], colours_);
      drawn_done_ = done;
    }
    const RenderResult all = render_full(&full_r_, g_, pose);
    FUZZ_REQUIRE(all.full && all.nrects == 1);
    if (path_) backplot_draw(full_r_.fb, depth(full_r_), full_r_.view, path_->data(), n, done, all.rects[0], colours_);
    FUZZ_REQUIRE(std::memcmp(inc_.data(), full_.data(), inc_.size() * 4) == 0);
    if (!res.full) check_covered(res);
    ++steps_;
  }

  uint64_t steps() const { return steps_; }

 private:
  static dexmill::DepthView depth(const dexmill::Renderer<H>& r) {
    dexmill::DepthView d;
    d.z = r.target.z;
    d.stride_bytes = r.target.z_stride;
    d.format = r.target.zformat;
    return d;
  }

  // Every pixel that differs from the frame before lies in a returned
  // rectangle (a platform presents only those).
  void check_covered(const dexmill::RenderResult& res) const {
    const int32_t bpp = s_.format == dexmill::PixelFormat::kRgb565 ? 2 : 4;
    const uint8_t* a = reinterpret_cast<const uint8_t*>(prev_.data());
    const uint8_t* b = reinterpret_cast<const uint8_t*>(inc_.data());
    for (int32_t y = 0; y < s_.height; ++y) {
      const size_t row = static_cast<size_t>(y) * stride_;
      if (std::memcmp(a + row, b + row, static_cast<size_t>(s_.width) * bpp) == 0) continue;
      for (int32_t x = 0; x < s_.width; ++x) {
        if (std::memcmp(a + row + x * bpp, b + row + x * bpp, bpp) == 0) continue;
        bool in = false;
        for (int k = 0; k < res.nrects && !in; ++k) {
          const dexmill::ScreenRect& r = res.rects[k];
          in = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
        }
        FUZZ_REQUIRE(in);
      }
    }
  }

  dexmill::DexelGrid<H>* g_ = nullptr;
  DrawSetup s_;
  int32_t stride_ = 0;
  std::vector<uint32_t> inc_, full_, prev_;
  std::vector<uint64_t> scratch_inc_, scratch_full_;
  dexmill::Renderer<H> inc_r_, full_r_;
  dexmill::ToolProfile profile_{};
  std::vector<uint8_t> cls_inc_, cls_full_;
  std::vector<uint32_t> luts_inc_, luts_full_;
  dexmill::ErrorColours<H> err_inc_, err_full_;
  const std::vector<dexmill::PathSegment>* path_ = nullptr;
  const uint32_t* done_ = nullptr;
  uint32_t drawn_done_ = 0;
  dexmill::BackplotColours colours_;
  uint64_t steps_ = 0;
};

}  // namespace fuzz

#endif
