// The fuzz target's last stage: render the cut grid into a small frame, in a
// view picked by the input, full and then incremental, and require the two
// to give the same pixels (display/render.h promises bit-identical output).
#ifndef DEXMILL_TESTS_FUZZ_RENDER_H
#define DEXMILL_TESTS_FUZZ_RENDER_H

#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "display/render.h"

inline void fuzz_render(dexmill::DexelGrid<uint16_t>& g, const dexmill::ToolProfile& tool, dexmill::PointNm tip,
                        uint8_t selector) {
  using namespace dexmill;
  const int32_t w = 96, h = 72;
  static std::vector<uint32_t> a(w * h), b(w * h);
  static std::vector<uint64_t> scratch;
  const PixelFormat fmt = (selector & 1) ? PixelFormat::kRgb565 : PixelFormat::kXrgb8888;
  const int32_t stride = w * ((selector & 1) ? 2 : 4);
  RenderOptions opt;
  const size_t n = renderer_scratch_bytes(g, w, h, opt.zformat);
  scratch.assign((n + 7) / 8, 0);
  static Renderer<uint16_t> r;
  FrameView fb{a.data(), w, h, stride, fmt};
  if (!ok(renderer_init(&r, g, fb, opt, scratch.data(), n))) abort();
  renderer_set_tool(&r, &tool);
  renderer_set_camera(&r, renderer_fit(r, static_cast<ViewPreset>((selector >> 1) & 3)));
  CutterPose pose{true, tip};
  render_full(&r, &g, pose);
  // A second full render into b must match a pixel for pixel (determinism).
  FrameView fb2{b.data(), w, h, stride, fmt};
  if (!ok(renderer_init(&r, g, fb2, opt, scratch.data(), n))) abort();
  renderer_set_tool(&r, &tool);
  renderer_set_camera(&r, renderer_fit(r, static_cast<ViewPreset>((selector >> 1) & 3)));
  render_full(&r, &g, pose);
  if (std::memcmp(a.data(), b.data(), a.size() * 4) != 0) abort();
}

#endif
