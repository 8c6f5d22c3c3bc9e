// Default stock and grid planning; see run_stock.h.
#include "tools/run_stock.h"

#include <cstdio>

#include "core/config.h"

#include "core/math/fixed.h"
#include "platform/stl_read.h"
#include "tools/cli.h"

namespace dexmill {
namespace cli {

StockBox default_stock(const MotionSummary& s, int64_t max_tool_radius_nm) {
  constexpr int64_t mm = kNmPerMm;
  const BoxAccum& below = s.feed_below_zero_box();
  const BoxAccum& feed = s.feed_box();
  const BoxAccum& any = s.motion_box();
  if (!any.valid) return StockBox{PointNm{-25 * mm, -25 * mm, -10 * mm}, PointNm{25 * mm, 25 * mm, 0}};
  const BoxAccum& xy = below.valid ? below : (feed.valid ? feed : any);
  int64_t top, deepest;
  if (below.valid) {
    top = 0;
    deepest = below.lo.z_nm;
  } else if (feed.valid) {
    top = s.feed_level_top_nm();
    deepest = feed.lo.z_nm;
  } else {
    top = any.lo.z_nm;
    deepest = top;
  }
  const int64_t depth = top - deepest;
  const int64_t bottom = min_of(deepest - max_of(mm, depth / 4), top - 2 * mm);
  const int64_t margin = max_tool_radius_nm + 2 * mm;
  return StockBox{PointNm{xy.lo.x_nm - margin, xy.lo.y_nm - margin, bottom},
                  PointNm{xy.hi.x_nm + margin, xy.hi.y_nm + margin, top}};
}

int64_t default_pitch_nm(const StockBox& stock, int64_t smallest_tool_nm) {
  const int64_t longer = max_of(stock.hi.x_nm - stock.lo.x_nm, stock.hi.y_nm - stock.lo.y_nm);
  const int64_t fine = div_ceil(longer, kDefaultMaxAcross - 3), coarse = div_ceil(longer, kDefaultMinAcross - 3);
  return max_of<int64_t>(1, min_of(coarse, max_of(fine, smallest_tool_nm / kDefaultDexelsPerTool)));
}

bool plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, GridPlan* out,
               std::string* err) {
  const int64_t sx = stock.hi.x_nm - stock.lo.x_nm, sy = stock.hi.y_nm - stock.lo.y_nm;
  int64_t pitch = pitch_nm;
  if (grid_nx > 0) {
    if (grid_nx < 4 || grid_ny < 4) {
      *err = "--grid needs at least 4x4 dexels";
      return false;
    }
    pitch = max_of(div_ceil(sx, grid_nx - 3), div_ceil(sy, grid_ny - 3));
  }
  pitch = max_of<int64_t>(pitch, 1);
  // Dexel axes X0, X0 + p, ... up to the first at or past X1; the grid is
  // the stock's shape (--grid is the most it may have each way).
  const int64_t ux = div_ceil(sx, pitch) + 1, uy = div_ceil(sy, pitch) + 1;
  const int64_t nx = ux + 2, ny = uy + 2;
  if (nx > 65535 || ny > 65535 || nx * ny > kMaxGridCells) {
    char b[200];
    std::snprintf(b, sizeof b, "the grid would be %lldx%lld dexels, more than the %lld M dexels a run may use; "
                  "give a coarser --pitch or --grid", static_cast<long long>(nx), static_cast<long long>(ny),
                  static_cast<long long>(kMaxGridCells >> 20));
    *err = b;
    return false;
  }
  GridPlan p;
  p.stock_nx = static_cast<int32_t>(ux);
  p.stock_ny = static_cast<int32_t>(uy);
  p.geo.nx = static_cast<int32_t>(nx);
  p.geo.ny = static_cast<int32_t>(ny);
  p.geo.pitch_nm = pitch;
  p.geo.x0_nm = stock.lo.x_nm - pitch;
  p.geo.y0_nm = stock.lo.y_nm - pitch;
  p.geo.z0_nm = stock.lo.z_nm;
  const int64_t height = stock.hi.z_nm - stock.lo.z_nm;
  p.geo.lsb_nm = lsb_for_range(height, DEXMILL_HEIGHT_BITS);
  p.top_lsb = div_round(height, p.geo.lsb_nm);
  p.stock = StockBox{stock.lo, PointNm{stock.lo.x_nm + (ux - 1) * pitch, stock.lo.y_nm + (uy - 1) * pitch,
                                       stock.lo.z_nm + p.top_lsb * p.geo.lsb_nm}};
  if (!ok(grid_check_geometry(p.geo))) {
    *err = "the stock and grid give a geometry the dexel grid cannot hold (pitch, size or position out of range)";
    return false;
  }
  *out = p;
  return true;
}

template <class H>
void fill_stock(DexelGrid<H>* g, const GridPlan& plan) {
  grid_block_stock(g, plan.top_lsb);
  for (int32_t j = 0; j < g->ny; ++j) {
    for (int32_t i = 0; i < g->nx; ++i) {
      if (i <= plan.stock_nx && j <= plan.stock_ny) continue;
      const size_t k = g->index(i, j);
      g->top[k] = 0;
      g->bottom[k] = 0;
    }
  }
}

template void fill_stock<uint8_t>(DexelGrid<uint8_t>*, const GridPlan&);
template void fill_stock<uint16_t>(DexelGrid<uint16_t>*, const GridPlan&);
template void fill_stock<uint32_t>(DexelGrid<uint32_t>*, const GridPlan&);

int read_stock_stl(const std::string& path, std::vector<TriangleNm>* tris, StockBox* box) {
  std::string err;
  StlReadInfo info;
  const StlRead r = stl_read(path, PointNm{0, 0, 0},
                             [tris](const PointNm* v, std::string*) {
                               tris->push_back(TriangleNm{{v[0], v[1], v[2]}});
                               return true;
                             },
                             &info, &err);
  if (r != StlRead::kOk) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return r == StlRead::kIoError ? kExitIo : kExitInput;
  }
  BoxAccum b;
  for (const TriangleNm& t : *tris)
    for (const PointNm& p : t.v) b.add(p);
  if (b.lo.x_nm >= b.hi.x_nm || b.lo.y_nm >= b.hi.y_nm || b.lo.z_nm >= b.hi.z_nm) {
    std::fprintf(stderr, "%s: error: the blank is flat (its box has no width, depth or height)\n", path.c_str());
    return kExitInput;
  }
  *box = StockBox{b.lo, b.hi};
  return kExitOk;
}

template <class H>
int carve_stock(DexelGrid<H>* g, const GridPlan& plan, const std::vector<TriangleNm>& tris) {
  const size_t cells = static_cast<size_t>(g->nx) * static_cast<size_t>(g->ny);
  std::vector<int32_t> tops(cells);
  DesignGrid d;
  if (!ok(design_init(&d, plan.geo, tops.data(), cells)))
    return fail(kExitUsage, "a blank wider than %.2f m cannot be read from STL", static_cast<double>(kDesignRangeNm) * 1e-9);
  for (const TriangleNm& t : tris) (void)design_add_triangle(&d, t);  // within the box: in range
  for (int32_t j = 1; j <= plan.stock_ny; ++j)
    for (int32_t i = 1; i <= plan.stock_nx; ++i) {
      const size_t k = g->index(i, j);
      const int32_t t = tops[k];
      g->top[k] = static_cast<H>(t == kNoDesign || t < 1 ? 0 : min_of<int64_t>(t, g->top[k]));
      g->bottom[k] = 0;
    }
  g->dirty = g->bounds();
  return kExitOk;
}

template int carve_stock<uint8_t>(DexelGrid<uint8_t>*, const GridPlan&, const std::vector<TriangleNm>&);
template int carve_stock<uint16_t>(DexelGrid<uint16_t>*, const GridPlan&, const std::vector<TriangleNm>&);
template int carve_stock<uint32_t>(DexelGrid<uint32_t>*, const GridPlan&, const std::vector<TriangleNm>&);

}  // namespace cli
}  // namespace dexmill
