// `dexmill measure STOCK --thickness` and `--scallop` (tools/CLI.md): the
// thinnest floor and wall (core/measure/thin_floor.h, thin_wall.h) and the
// highest scallop (core/measure/scallop.h), printed with their bounds;
// the picture in tools/cli/cmd_measure_image.cpp.
#include <cstdio>
#include <string>

#include "core/math/fixed.h"
#include "core/measure/scallop.h"
#include "core/measure/thin_floor.h"
#include "core/measure/thin_wall.h"
#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"

namespace dexmill {
namespace cli {

namespace {

int32_t clamp_index(int64_t k, int32_t n) { return static_cast<int32_t>(k < 0 ? 0 : k > n ? n : k); }

std::string xy(int64_t x_nm, int64_t y_nm) { return "X" + measure_mm(x_nm, 3) + " Y" + measure_mm(y_nm, 3); }

void print_scallop(const char* across, const Scallop& s) {
  if (!s.found) {
    std::printf("scallop across %s: none (no crest with a valley on both sides)\n", across);
    return;
  }
  std::printf("scallop across %s: %s mm at %s (crest Z%s over valley Z%s; within %s mm), highest of %d crests\n",
              across, measure_mm(s.height_nm).c_str(), xy(s.x_nm, s.y_nm).c_str(), measure_mm(s.crest_nm).c_str(),
              measure_mm(s.valley_nm).c_str(), measure_mm(s.error_nm).c_str(), s.crests);
}

void print_wall(const DexelGrid<height_t>& g, const ThinWall& w, const std::string& high);

}  // namespace

int measure_thickness(const MeasuredStock& s, int64_t wall_height_nm, const std::string& image_path, int64_t thin_nm) {
  const DexelGrid<height_t>& g = s.grid;
  const ThinFloor f = thin_floor(g);
  if (!f.found)
    std::printf("thinnest floor: none (no column holds material)\n");
  else
    std::printf("thinnest floor: %s mm at %s (top Z%s, bottom Z%s; within %s mm, the column's centre within %s mm of "
                "the place along X and Y)\n",
                measure_mm(f.thickness_nm).c_str(), xy(f.x_nm, f.y_nm).c_str(), measure_mm(f.top_nm).c_str(),
                measure_mm(f.bottom_nm).c_str(), measure_mm(f.thickness_error_nm).c_str(),
                measure_mm(div_ceil(g.pitch_nm, 2), 3).c_str());
  const ThinWall w = thin_wall(g, wall_height_nm);
  const std::string high = "walls at least " + measure_mm(wall_height_nm, 3) + " mm high";
  if (!w.found)
    std::printf("thinnest wall: none (%s)\n", high.c_str());
  else
    print_wall(g, w, high);
  return image_path.empty() ? kExitOk : measure_thin_image(s, image_path, thin_nm, f, w);
}

namespace {

void print_wall(const DexelGrid<height_t>& g, const ThinWall& w, const std::string& high) {
  const std::string floor = w.floor_air ? "air on both sides" : "over Z" + measure_mm(w.floor_nm);
  std::printf("thinnest wall: %s mm across %s at %s (columns %s to %s, top Z%s %s; within %s mm; %s)\n",
              measure_mm(w.width_nm, 3).c_str(), wall_scan_name(w.scan), xy(w.x_nm, w.y_nm).c_str(),
              xy(g.x0_nm + w.i0 * g.pitch_nm, g.y0_nm + w.j0 * g.pitch_nm).c_str(),
              xy(g.x0_nm + w.i1 * g.pitch_nm, g.y0_nm + w.j1 * g.pitch_nm).c_str(), measure_mm(w.top_nm).c_str(),
              floor.c_str(), measure_mm(w.width_error_nm, 3).c_str(), high.c_str());
}

}  // namespace

int measure_scallop(const MeasuredStock& s, const int64_t* region_nm) {
  const DexelGrid<height_t>& g = s.grid;
  GridRect r = g.bounds();
  if (region_nm) {
    // The columns whose centres lie in the box, corners in either order.
    const int64_t x0 = min_of(region_nm[0], region_nm[2]), x1 = max_of(region_nm[0], region_nm[2]);
    const int64_t y0 = min_of(region_nm[1], region_nm[3]), y1 = max_of(region_nm[1], region_nm[3]);
    r.i0 = clamp_index(div_ceil(x0 - g.x0_nm, g.pitch_nm), g.nx);
    r.i1 = clamp_index(div_floor(x1 - g.x0_nm, g.pitch_nm) + 1, g.nx);
    r.j0 = clamp_index(div_ceil(y0 - g.y0_nm, g.pitch_nm), g.ny);
    r.j1 = clamp_index(div_floor(y1 - g.y0_nm, g.pitch_nm) + 1, g.ny);
  }
  if (r.empty()) return fail(kExitUsage, "--scallop's box holds no column of the stock's grid");
  std::printf("scallop region: %s to %s (%d x %d columns)\n",
              xy(g.x0_nm + r.i0 * g.pitch_nm, g.y0_nm + r.j0 * g.pitch_nm).c_str(),
              xy(g.x0_nm + (r.i1 - 1) * g.pitch_nm, g.y0_nm + (r.j1 - 1) * g.pitch_nm).c_str(), r.i1 - r.i0,
              r.j1 - r.j0);
  const ScallopAnswer a = scallop(g, r);
  // "across X": scans along X, so the stepover is in X.
  print_scallop("X", a.along_x);
  print_scallop("Y", a.along_y);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
