// Default stock and grid planning; see stock_plan.h.
#include "core/sim/stock_plan.h"

#include "core/config.h"
#include "core/math/fixed.h"

namespace dexmill {

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

PlanError plan_check_budget(int64_t nx, int64_t ny, const GridBudget& budget, PlanRefusal* why) {
  // Sides within int32 (a grid's, core/grid/grid.h) keep the count within
  // 64 bits; its bytes saturate rather than wrap (and then cannot fit).
  const uint64_t cells = static_cast<uint64_t>(nx) * static_cast<uint64_t>(ny);
  const uint64_t per = max_of(budget.dexel_bytes, kGridDexelBytes);
  const uint64_t need = per != 0 && cells > UINT64_MAX / per ? UINT64_MAX : cells * per;
  if (need <= budget.max_bytes) return PlanError::kOk;
  if (why) *why = PlanRefusal{nx, ny, need, budget.max_bytes};
  return PlanError::kOverBudget;
}

PlanError plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, GridPlan* out,
                    const GridBudget& budget, PlanRefusal* why) {
  const int64_t corners[6] = {stock.lo.x_nm, stock.lo.y_nm, stock.lo.z_nm, stock.hi.x_nm, stock.hi.y_nm, stock.hi.z_nm};
  for (const int64_t c : corners)
    if (c < -kStockCoordMaxNm || c > kStockCoordMaxNm) return PlanError::kBadStock;
  if (stock.lo.x_nm >= stock.hi.x_nm || stock.lo.y_nm >= stock.hi.y_nm || stock.lo.z_nm >= stock.hi.z_nm)
    return PlanError::kBadStock;
  const int64_t sx = stock.hi.x_nm - stock.lo.x_nm, sy = stock.hi.y_nm - stock.lo.y_nm;
  int64_t pitch = pitch_nm;
  if (grid_nx > 0) {
    if (grid_nx < 4 || grid_ny < 4) return PlanError::kGridTooSmall;
    pitch = max_of(div_ceil(sx, grid_nx - 3), div_ceil(sy, grid_ny - 3));
  }
  pitch = max_of<int64_t>(pitch, 1);
  // Dexel axes X0, X0 + p, ... up to the first at or past X1; the grid is
  // the stock's shape (a most-dexels-each-way is the most it may have).
  const int64_t ux = div_ceil(sx, pitch) + 1, uy = div_ceil(sy, pitch) + 1;
  const int64_t nx = ux + 2, ny = uy + 2;
  if (nx > 65535 || ny > 65535) {
    if (why) *why = PlanRefusal{nx, ny, 0, budget.max_bytes};
    return PlanError::kTooManyDexels;
  }
  const PlanError spent = plan_check_budget(nx, ny, budget, why);
  if (spent != PlanError::kOk) return spent;
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
  if (p.top_lsb > height_max<height_t>()) return PlanError::kBadStock;  // taller than 2^m - 1 LSBs of 1 m
  p.stock = StockBox{stock.lo, PointNm{stock.lo.x_nm + (ux - 1) * pitch, stock.lo.y_nm + (uy - 1) * pitch,
                                       stock.lo.z_nm + p.top_lsb * p.geo.lsb_nm}};
  if (!ok(grid_check_geometry(p.geo))) return PlanError::kBadGeometry;
  *out = p;
  return PlanError::kOk;
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

template <class H>
void carve_stock(DexelGrid<H>* g, const GridPlan& plan, const DesignGrid& blank) {
  for (int32_t j = 1; j <= plan.stock_ny; ++j)
    for (int32_t i = 1; i <= plan.stock_nx; ++i) {
      const size_t k = g->index(i, j);
      const int32_t t = blank.top_lsb[blank.index(i, j)];
      g->top[k] = static_cast<H>(t == kNoDesign || t < 1 ? 0 : min_of<int64_t>(t, g->top[k]));
      g->bottom[k] = 0;
    }
  g->dirty = g->bounds();
}

#define DEXMILL_STOCK_INSTANTIATE(H)                                 \
  template void fill_stock<H>(DexelGrid<H>*, const GridPlan&);       \
  template void carve_stock<H>(DexelGrid<H>*, const GridPlan&, const DesignGrid&);
DEXMILL_STOCK_INSTANTIATE(uint8_t)
DEXMILL_STOCK_INSTANTIATE(uint16_t)
DEXMILL_STOCK_INSTANTIATE(uint32_t)
#undef DEXMILL_STOCK_INSTANTIATE

}  // namespace dexmill
