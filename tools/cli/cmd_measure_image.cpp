// `dexmill measure STOCK --thickness --image FILE.png [--thin MM]`
// (tools/CLI.md): the part drawn as `dexmill run --color thin` draws it
// (display/colour/thin_colours.h through tools/run/run_colours.h, the
// legend included; the iso view at 640 x 480), the floors thinner than
// --thin in orange and red, and the thinnest floor's and wall's places
// marked (cyan: the floor's column, magenta: the wall's middle, at their
// tops).
#include <cstdio>
#include <string>
#include <vector>

#include "platform/format/image_file.h"
#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"
#include "tools/run/run_colours.h"
#include "tools/run/run_render.h"

namespace dexmill {
namespace cli {

int measure_thin_image(const MeasuredStock& s, const std::string& path, int64_t thin_nm, const ThinFloor& floor,
                       const ThinWall& wall) {
  RunOptions o;
  o.view.color = ViewOptions::Color::kThin;
  o.view.thin_nm = thin_nm;
  DexelGrid<height_t> g = s.grid;  // a render consumes the grid's dirty rectangle: a copy's
  RunColours c;
  run_colours_start(&c, o, g, nullptr, nullptr, nullptr, false);
  constexpr int32_t kWidth = 640, kHeight = 480;
  std::vector<uint32_t> pixels(static_cast<size_t>(kWidth) * kHeight, 0);
  FrameView fb;
  fb.pixels = pixels.data();
  fb.width = kWidth;
  fb.height = kHeight;
  fb.stride_bytes = kWidth * 4;
  fb.format = PixelFormat::kXrgb8888;
  RenderOutput out;
  std::string err;
  if (!out.init(g, fb, CameraChoice{}, &err)) return fail(kExitUsage, "--image: %s", err.c_str());
  out.set_colours(c.colours());
  out.set_legend(&c.legend);
  std::vector<PointNm> floor_mark, wall_mark;
  if (floor.found) floor_mark.push_back(PointNm{floor.x_nm, floor.y_nm, floor.top_nm});
  if (wall.found) wall_mark.push_back(PointNm{wall.x_nm, wall.y_nm, wall.top_nm});
  out.add_marks(&floor_mark, Rgb{0, 220, 255});
  out.add_marks(&wall_mark, Rgb{255, 40, 255});
  out.draw(&g, CutterPose{});
  char e[1400];
  if (!write_frame_image(path.c_str(), ImageFormat::kPng, out.view(), e, sizeof e)) return fail(kExitIo, "%s", e);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
