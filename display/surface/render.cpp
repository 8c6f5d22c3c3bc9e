// The renderer: full frames and incremental updates (see render.h).
#include "display/surface/render.h"

#include "core/math/fixed.h"
#include "display/raster/clip.h"
#include "display/surface/mesh.h"

namespace dexmill {
namespace {

constexpr size_t kAlign = 8;
inline size_t align_up(size_t n) { return (n + kAlign - 1) / kAlign * kAlign; }

struct ScratchLayout {
  size_t z, top, wall, blocks, tiles, total;
};

ScratchLayout layout(int32_t nx, int32_t ny, int32_t width, int32_t height, ZFormat zf) {
  ScratchLayout l;
  const size_t cells = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  const size_t nblocks = static_cast<size_t>(blocks_across(nx)) * static_cast<size_t>(blocks_across(ny));
  l.z = 0;
  l.top = align_up(l.z + static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(z_bytes(zf)));
  l.wall = align_up(l.top + cells);
  l.blocks = align_up(l.wall + cells);
  l.tiles = align_up(l.blocks + nblocks * sizeof(BlockInfo));
  l.total = align_up(l.tiles + tile_count(width, height));
  return l;
}

// Background colour of row y: a vertical gradient.
template <class H>
uint32_t background_row(const Renderer<H>& r, int32_t y) {
  const Rgb a = r.opt.background_top;
  if (!r.opt.gradient) return pixel_pack(r.fb.format, a);
  const Rgb b = r.opt.background_bottom;
  const int32_t d = max_of<int32_t>(r.fb.height - 1, 1);
  auto mix = [&](int32_t u, int32_t v) { return static_cast<uint8_t>(u + ((v - u) * y + (v > u ? d / 2 : -d / 2)) / d); };
  return pixel_pack(r.fb.format, Rgb{mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)});
}

template <class H>
void clear_rect(Renderer<H>* r, const ScreenRect& rect) {
  for (int32_t y = rect.y0; y < rect.y1; ++y) raster_clear(&r->target, ScreenRect{rect.x0, y, rect.x1, y + 1}, background_row(*r, y));
}

template <class H>
void block_update(Renderer<H>* r, const DexelGrid<H>& g, int32_t bx, int32_t by) {
  BlockInfo& b = r->blocks[static_cast<size_t>(by) * r->bnx + bx];
  block_heights(g, bx, by, r->view.sees_below, &b.zlo_lsb, &b.zhi_lsb);
  ScreenRect s{0, 0, 0, 0};
  if (b.zlo_lsb <= b.zhi_lsb) {
    const GridRect c = block_cells(g, bx, by);
    s = box_rect(r->view, c.i0, c.j0, c.i1, c.j1, b.zlo_lsb, b.zhi_lsb, r->fb.width, r->fb.height);
  }
  b.x0 = static_cast<int16_t>(s.x0);
  b.y0 = static_cast<int16_t>(s.y0);
  b.x1 = static_cast<int16_t>(s.x1);
  b.y1 = static_cast<int16_t>(s.y1);
}

// Draws everything that can touch `rect`, in the same order for a full
// frame and for any rectangle of an update (the depth test keeps the first of
// equal depths, so the order is part of the picture).
template <class H>
void draw_rect(Renderer<H>* r, const DexelGrid<H>& g, const ScreenRect& rect, bool cutter) {
  RasterTarget* t = &r->target;
  t->clip = rect;
  t->lut = r->lut_work;
  MeshPass<H> pass;
  pass.grid = &g;
  pass.view = &r->view;
  pass.shades = &r->shades;
  pass.bottom_shade = r->bottom_shade;
  pass.bottoms = r->view.sees_below;
  pass.target = t;
  pass.colours = r->colours;
  pass.lit = &r->lit;
  t->vertex_rgb = r->colours && r->colours->texture;
  for (int32_t n = 0; n < r->bny; ++n) {
    const int32_t by = r->j_desc ? r->bny - 1 - n : n;
    for (int32_t m = 0; m < r->bnx; ++m) {
      const int32_t bx = r->i_desc ? r->bnx - 1 - m : m;
      const BlockInfo& b = r->blocks[static_cast<size_t>(by) * r->bnx + bx];
      if (b.zlo_lsb > b.zhi_lsb || b.x1 <= rect.x0 || b.x0 >= rect.x1 || b.y1 <= rect.y0 || b.y0 >= rect.y1) continue;
      const bool inside = b.x0 >= rect.x0 && b.x1 <= rect.x1 && b.y0 >= rect.y0 && b.y1 <= rect.y1;
      mesh_draw_cells(pass, block_cells(g, bx, by), r->i_desc, r->j_desc, !inside, b.zlo_lsb, b.zhi_lsb);
    }
  }
  t->vertex_rgb = false;
  // Fixtures after the stock: the stock draws as it does with none (nearest
  // blocks first, its own ties unchanged), and where a fixture's face and
  // the stock's meet at exactly the same depth the stock shows.
  // Before the table, which lies behind them too where they stand on it
  // beside the stock, so that its colour writes under them are skipped;
  // before the cutter, which wins no tie against a fixture it touches.
  if (r->nfixtures > 0) {
    t->lut = r->lut_fixture;
    for (int k = 0; k < r->nfixtures; ++k)
      if (!rect_intersect(rect, r->fixture_mesh[k].rect).empty()) fixture_draw(t, r->view, r->fixture_mesh[k], r->fixture_shades);
  }
  // The table lies wholly behind the stock (below its bottom, seen from
  // above), so drawing it after the stock changes no pixel and skips the
  // colour writes under the stock.
  if (r->table_visible) {
    t->lut = r->lut_table;
    const ClipVertex* q = r->table_quad;
    clip_draw_triangle(t, r->view.proj, q[0], q[1], q[2]);
    clip_draw_triangle(t, r->view.proj, q[0], q[2], q[3]);
  }
  if (cutter && !rect_intersect(rect, r->cutter.rect).empty()) {
    t->lut = r->lut_cutter;
    cutter_draw(t, r->view, r->cutter);
  }
}

// A light's direction d (RenderOptions) in machine coordinates.
UnitQ14 light_direction(const RenderOptions& o, const View& v, const int32_t d[3]) {
  int64_t l[3];
  for (int k = 0; k < 3; ++k) {
    l[k] = o.light_follows_camera ? (static_cast<int64_t>(d[0]) * v.right_q30[k] + static_cast<int64_t>(d[1]) * v.up_q30[k] +
                                     static_cast<int64_t>(d[2]) * v.eye_q30[k])
                                  : static_cast<int64_t>(d[k]);
  }
  return normal_unit_q14(l[0], l[1], l[2]);
}

template <class H>
void prepare_view(Renderer<H>* r) {
  view_build(r->cam, r->scene, r->fb.width, r->fb.height, &r->view);
  const View& v = r->view;
  r->light = Lighting{};
  r->light.light = light_direction(r->opt, v, r->opt.light);
  r->light.fill_light = light_direction(r->opt, v, r->opt.fill_light);
  r->light.ambient_q14 = clamp<int32_t>(r->opt.ambient_q14, 0, 1 << 16);
  r->light.diffuse_q14 = clamp<int32_t>(r->opt.key_q14, 0, 1 << 16);
  r->light.fill_q14 = clamp<int32_t>(r->opt.fill_q14, 0, 1 << 16);
  if (!r->opt.specular) r->light.specular_q14 = 0;
  lighting_finish(&r->light, normal_unit_q14(v.eye_q30[0], v.eye_q30[1], v.eye_q30[2]));
  const int32_t base = shade_base_index(r->light);
  shade_ramp(r->fb.format, r->opt.workpiece, base, r->lut_work);
  shade_ramp(r->fb.format, r->opt.cutter, base, r->lut_cutter);
  shade_ramp(r->fb.format, r->opt.table_colour, base, r->lut_table);
  if (r->nfixtures > 0) {
    shade_ramp(r->fb.format, r->opt.fixture, base, r->lut_fixture);
    fixture_light(r->light, &r->fixture_shades);
    for (int k = 0; k < r->nfixtures; ++k) fixture_place(r->fixtures[k], v, r->fb.width, r->fb.height, &r->fixture_mesh[k]);
  }
  if (const SurfaceColours* c = r->colours)
    for (int32_t k = 0; k < c->nclasses; ++k) shade_ramp(r->fb.format, c->colour[k], base, c->luts + static_cast<size_t>(k) * kShadeLevels);
  lit_ramp(base, &r->lit);
  r->bottom_shade = shade_of_normal(r->light, UnitQ14{0, 0, -16384});
  cutter_light(r->tool, r->light, &r->cutter);
  r->i_desc = v.eye_q30[0] > 0;  // nearer cells first: fewer pixels shaded twice
  r->j_desc = v.eye_q30[1] > 0;
  // The table: a plane a little below the stock, seen only from above.
  const BoxNm& s = r->stock;
  const int64_t margin = max_of(s.hi.x_nm - s.lo.x_nm, s.hi.y_nm - s.lo.y_nm) / 10;
  const int64_t zt = s.lo.z_nm - max_of<int64_t>(r->scene.pitch_nm / 4, 1);
  const PointNm corners[4] = {{s.lo.x_nm - margin, s.lo.y_nm - margin, zt},
                              {s.hi.x_nm + margin, s.lo.y_nm - margin, zt},
                              {s.hi.x_nm + margin, s.hi.y_nm + margin, zt},
                              {s.lo.x_nm - margin, s.hi.y_nm + margin, zt}};
  const int32_t table_shade = shade_of_normal(r->light, UnitQ14{0, 0, 16384});
  for (int k = 0; k < 4; ++k) {
    r->table_quad[k] = view_point(v, corners[k]);
    r->table_quad[k].shade = table_shade;
  }
  r->table_visible = r->opt.table && (v.proj.kind == Projection::kOrthographic ? v.eye_q30[2] > 0 : v.eye.z_nm > zt);
}

template <class H>
void place_cutter(Renderer<H>* r, const CutterPose& c) {
  if (c.visible && r->tool.valid) cutter_place(r->tool, r->view, c.tip, r->fb.width, r->fb.height, &r->cutter);
  else r->cutter.rect = ScreenRect{0, 0, 0, 0};
  r->cutter_pose = c;
}

}  // namespace

size_t renderer_scratch_bytes_for(int32_t nx, int32_t ny, int32_t width, int32_t height, ZFormat zf) {
  if (nx < 2 || ny < 2 || width < 1 || height < 1) return 0;
  return layout(nx, ny, width, height, zf).total;
}

template <class H>
Status renderer_init(Renderer<H>* r, const DexelGrid<H>& g, const FrameView& fb, const RenderOptions& opt,
                     void* scratch, size_t scratch_bytes) {
  if (!ok(frame_check(fb)) || g.nx < 2 || g.ny < 2 || !g.top || !g.bottom) return Status::kBadArgument;
  if (opt.zformat != ZFormat::kZ16 && opt.zformat != ZFormat::kZ32) return Status::kBadArgument;
  const ScratchLayout l = layout(g.nx, g.ny, fb.width, fb.height, opt.zformat);
  if (!scratch || scratch_bytes < l.total) return Status::kBufferTooSmall;
  uint8_t* base = static_cast<uint8_t*>(scratch);
  r->fb = fb;
  r->opt = opt;
  r->nx = g.nx;
  r->ny = g.ny;
  r->z = base + l.z;
  r->shades.top = base + l.top;
  r->shades.wall = base + l.wall;
  r->blocks = reinterpret_cast<BlockInfo*>(base + l.blocks);
  r->bnx = blocks_across(g.nx);
  r->bny = blocks_across(g.ny);
  r->tiles.flags = base + l.tiles;
  r->tiles.width = fb.width;
  r->tiles.height = fb.height;
  r->tiles.tiles_x = (fb.width + kTileSide - 1) / kTileSide;
  r->tiles.tiles_y = (fb.height + kTileSide - 1) / kTileSide;
  tiles_clear(&r->tiles);
  // The stock: dexel axes in x and y, heights 0 to the highest top now.
  uint32_t hmax = 0;
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) hmax = g.top[k] > hmax ? g.top[k] : hmax;
  r->stock.lo = PointNm{g.x0_nm, g.y0_nm, g.z0_nm};
  r->stock.hi = PointNm{g.x0_nm + (g.nx - 1) * g.pitch_nm, g.y0_nm + (g.ny - 1) * g.pitch_nm,
                        g.z0_nm + static_cast<int64_t>(hmax) * g.lsb_nm};
  // The scene adds the table's margin and room for a tool above the stock.
  const int64_t span = max_of(r->stock.hi.x_nm - r->stock.lo.x_nm, r->stock.hi.y_nm - r->stock.lo.y_nm);
  SceneFrame& s = r->scene;
  s.box.lo = PointNm{r->stock.lo.x_nm - span / 10, r->stock.lo.y_nm - span / 10, r->stock.lo.z_nm - g.pitch_nm};
  s.box.hi = PointNm{r->stock.hi.x_nm + span / 10, r->stock.hi.y_nm + span / 10, r->stock.hi.z_nm + span / 2};
  s.x0_nm = g.x0_nm;
  s.y0_nm = g.y0_nm;
  s.z0_nm = g.z0_nm;
  s.pitch_nm = g.pitch_nm;
  s.lsb_nm = g.lsb_nm;
  s.stock_top_nm = r->stock.hi.z_nm;
  r->scene_bare = s.box;
  r->fixtures = nullptr;
  r->nfixtures = 0;
  r->target = RasterTarget{};
  r->target.color = static_cast<uint8_t*>(fb.pixels);
  r->target.color_stride = fb.stride_bytes;
  r->target.format = fb.format;
  r->target.z = r->z;
  r->target.z_stride = fb.width * z_bytes(opt.zformat);
  r->target.zformat = opt.zformat;
  r->tool = CutterShape{};
  r->cutter_rect = ScreenRect{0, 0, 0, 0};
  r->cam = renderer_fit(*r, ViewPreset::kIso);
  r->need_full = true;
  return Status::kOk;
}

template <class H>
BoxNm renderer_stock_box(const Renderer<H>& r) {
  return r.stock;
}

template <class H>
Camera renderer_fit(const Renderer<H>& r, ViewPreset v) {
  Camera c = camera_preset(v);
  camera_fit(&c, r.stock, r.fb.width, r.fb.height);
  return c;
}

template <class H>
void renderer_set_camera(Renderer<H>* r, const Camera& c) {
  r->cam = c;
  r->need_full = true;
}

template <class H>
void renderer_set_tool(Renderer<H>* r, const ToolProfile* p) {
  r->tool = CutterShape{};
  if (p) cutter_shape_build(*p, &r->tool);
  r->need_full = true;  // the shades of the changed shape come with the next full frame
}

template <class H>
Status renderer_set_fixtures(Renderer<H>* r, const BoxNm* boxes, int n) {
  if (n < 0 || (n > 0 && !boxes)) return Status::kBadArgument;
  r->fixtures = n > 0 ? boxes : nullptr;
  r->nfixtures = min_of(n, kFixturesMax);
  // The scene's box, widened to hold every fixture drawn.
  r->scene.box = fixtures_box(r->scene_bare, boxes, r->nfixtures);
  r->need_full = true;
  return n > kFixturesMax ? Status::kBufferTooSmall : Status::kOk;
}

template <class H>
void renderer_share_frame(Renderer<H>* r, const Renderer<H>& from) {
  r->stock = from.stock;
  r->scene = from.scene;
  r->scene_bare = from.scene.box;
  r->need_full = true;
}

template <class H>
void renderer_set_colours(Renderer<H>* r, const SurfaceColours* c) {
  r->colours = c && c->cls && c->luts && c->nclasses > 0 && c->nclasses <= kMaxColourClasses ? c : nullptr;
  r->need_full = true;
}

namespace {
// A colour mode's classes over r, before r is drawn.
template <class H>
void classify(const Renderer<H>* r, GridRect g) {
  if (r->colours && r->colours->classify) r->colours->classify(r->colours->ctx, g, r->colours->cls);
}
}  // namespace

template <class H>
RenderResult render_full(Renderer<H>* r, DexelGrid<H>* g, const CutterPose& cutter) {
  RenderResult res;
  if (g->nx != r->nx || g->ny != r->ny) return res;
  prepare_view(r);
  shade_grid(*g, r->light, g->bounds(), &r->shades);
  classify(r, g->bounds());
  for (int32_t by = 0; by < r->bny; ++by)
    for (int32_t bx = 0; bx < r->bnx; ++bx) block_update(r, *g, bx, by);
  place_cutter(r, cutter);
  r->target.stats = RasterStats{};
  const ScreenRect all{0, 0, r->fb.width, r->fb.height};
  clear_rect(r, all);
  draw_rect(r, *g, all, !r->cutter.rect.empty());
  r->cutter_rect = r->cutter.rect;
  g->dirty = GridRect::none();
  r->need_full = false;
  res.full = true;
  res.nrects = 1;
  res.rects[0] = all;
  res.stats = r->target.stats;
  return res;
}

template <class H>
RenderResult render_update(Renderer<H>* r, DexelGrid<H>* g, const CutterPose& cutter) {
  if (r->need_full) return render_full(r, g, cutter);
  RenderResult res;
  if (g->nx != r->nx || g->ny != r->ny) return res;
  r->target.stats = RasterStats{};
  const GridRect d{max_of<int32_t>(g->dirty.i0, 0), max_of<int32_t>(g->dirty.j0, 0), min_of(g->dirty.i1, g->nx),
                   min_of(g->dirty.j1, g->ny)};
  if (!d.empty()) {
    // Shades reach kShadeReach dexels past a change (gradient, then blur),
    // and a cell draws from its four corners.
    constexpr int32_t R = kShadeReach;
    const GridRect s{max_of<int32_t>(d.i0 - R, 0), max_of<int32_t>(d.j0 - R, 0), min_of<int32_t>(d.i1 + R, g->nx),
                     min_of<int32_t>(d.j1 + R, g->ny)};
    shade_grid(*g, r->light, s, &r->shades);
    // A class that looks at neighbours (surface_colours.h) recomputes them
    // itself, up to kClassReach away: inside the cells redrawn below.
    static_assert(kClassReach <= kShadeReach, "the cells redrawn reach kShadeReach dexels past a change");
    classify(r, d);
    const GridRect cells{max_of<int32_t>(s.i0 - 1, 0), max_of<int32_t>(s.j0 - 1, 0), min_of<int32_t>(s.i1, g->nx - 1),
                         min_of<int32_t>(s.j1, g->ny - 1)};
    const int32_t bx0 = cells.i0 / kBlockCells, bx1 = (cells.i1 - 1) / kBlockCells;
    const int32_t by0 = cells.j0 / kBlockCells, by1 = (cells.j1 - 1) / kBlockCells;
    // The cells' heights before and after: their blocks' ranges.
    uint32_t zlo = UINT32_MAX, zhi = 0;
    for (int pass = 0; pass < 2; ++pass) {
      for (int32_t by = by0; by <= by1; ++by) {
        for (int32_t bx = bx0; bx <= bx1; ++bx) {
          if (pass == 1) block_update(r, *g, bx, by);
          const BlockInfo& b = r->blocks[static_cast<size_t>(by) * r->bnx + bx];
          if (b.zlo_lsb > b.zhi_lsb) continue;
          zlo = min_of(zlo, b.zlo_lsb);
          zhi = max_of(zhi, b.zhi_lsb);
        }
      }
    }
    if (zlo <= zhi)
      tiles_mark(&r->tiles, box_rect(r->view, cells.i0, cells.j0, cells.i1, cells.j1, zlo, zhi, r->fb.width, r->fb.height));
  }
  const bool moved = !(cutter.visible == r->cutter_pose.visible && cutter.tip == r->cutter_pose.tip);
  if (moved) {
    tiles_mark(&r->tiles, r->cutter_rect);
    place_cutter(r, cutter);
    tiles_mark(&r->tiles, r->cutter.rect);
  }
  res.nrects = tiles_rects(&r->tiles, res.rects, kMaxDirtyRects);
  for (int k = 0; k < res.nrects; ++k) {
    clear_rect(r, res.rects[k]);
    draw_rect(r, *g, res.rects[k], !r->cutter.rect.empty());
  }
  r->cutter_rect = r->cutter.rect;
  g->dirty = GridRect::none();
  res.stats = r->target.stats;
  return res;
}

template <class H>
void renderer_invalidate(Renderer<H>* r, const ScreenRect& rect) {
  if (!r->need_full) tiles_mark(&r->tiles, rect);
}

#define DEXMILL_RENDER_INSTANTIATE(H)                                                                       \
  template void renderer_invalidate<H>(Renderer<H>*, const ScreenRect&);                                    \
  template Status renderer_init<H>(Renderer<H>*, const DexelGrid<H>&, const FrameView&, const RenderOptions&, \
                                   void*, size_t);                                                          \
  template BoxNm renderer_stock_box<H>(const Renderer<H>&);                                                 \
  template Camera renderer_fit<H>(const Renderer<H>&, ViewPreset);                                          \
  template void renderer_set_camera<H>(Renderer<H>*, const Camera&);                                        \
  template void renderer_set_tool<H>(Renderer<H>*, const ToolProfile*);                                     \
  template void renderer_set_colours<H>(Renderer<H>*, const SurfaceColours*);                                \
  template Status renderer_set_fixtures<H>(Renderer<H>*, const BoxNm*, int);                                 \
  template void renderer_share_frame<H>(Renderer<H>*, const Renderer<H>&);                                   \
  template RenderResult render_full<H>(Renderer<H>*, DexelGrid<H>*, const CutterPose&);                     \
  template RenderResult render_update<H>(Renderer<H>*, DexelGrid<H>*, const CutterPose&);
DEXMILL_RENDER_INSTANTIATE(uint8_t)
DEXMILL_RENDER_INSTANTIATE(uint16_t)
DEXMILL_RENDER_INSTANTIATE(uint32_t)

}  // namespace dexmill
