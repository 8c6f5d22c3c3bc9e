// The material colour mode; see material_colours.h.
#include "display/colour/material_colours.h"

#include "core/math/fixed.h"

namespace dexmill {

Rgb material_swatch(const Material& m) {
  const Texture& t = m.texture;
  Rgb8 c = t.plain;
  switch (t.kind) {
    case TextureKind::kPlain: c = t.plain; break;
    case TextureKind::kLayers: c = t.layers.colour[0]; break;
    case TextureKind::kMarble: c = t.marble.base; break;
    case TextureKind::kWood: c = t.wood.light; break;
    case TextureKind::kBronze: c = t.bronze.base; break;
    case TextureKind::kGranite: c = t.granite.base; break;
  }
  return Rgb{c.r, c.g, c.b};
}

uint32_t material_uncut_tint(uint32_t rgb) {
  constexpr uint32_t kGrey = 150;
  uint32_t out = 0;
  for (int k = 0; k < 24; k += 8) out |= ((((rgb >> k) & 0xFF) + kGrey + 1) / 2) << k;
  return out;
}

namespace {

// The centre height (nm) of the one-LSB slab under height h.
template <class H>
int64_t slab_z_nm(const DexelGrid<H>& g, uint32_t h) {
  return g.z0_nm + static_cast<int64_t>(h) * g.lsb_nm - g.lsb_nm / 2;
}

template <class H>
uint32_t colour_at(const void* ctx, int32_t i, int32_t j, uint32_t h) {
  const MaterialColours<H>* m = static_cast<const MaterialColours<H>*>(ctx);
  const DexelGrid<H>& g = *m->grid;
  // The part's point: a part turned over by a setup keeps its materials.
  const PointNm p = composition_part_point(*m->comp, PointNm{g.x0_nm + i * g.pitch_nm, g.y0_nm + j * g.pitch_nm, slab_z_nm(g, h)});
  const uint8_t k = composition_material_in_part(*m->comp, p);
  const Rgb8 c = texture_colour(m->comp->materials[k].texture, p);
  return static_cast<uint32_t>(c.r) << 16 | static_cast<uint32_t>(c.g) << 8 | c.b;
}

// Textured: the colour under every top in r that changed since it was
// worked out.
template <class H>
void texture_tops(MaterialColours<H>* m, GridRect r) {
  const DexelGrid<H>& g = *m->grid;
  for (int32_t j = r.j0; j < r.j1; ++j)
    for (int32_t i = r.i0; i < r.i1; ++i) {
      const size_t at = g.index(i, j);
      const H t = g.top[at];
      if ((t | g.bottom[at]) == 0 || (m->rgb_valid && m->rgb_top[at] == t)) continue;
      const uint32_t c = colour_at<H>(m, i, j, t);
      m->top_rgb[at] = m->uncut_top_lsb && t >= m->uncut_top_lsb ? material_uncut_tint(c) : c;
      m->rgb_top[at] = t;
    }
}

// The material half an LSB under each top (a hole: class 0, never drawn).
template <class H>
void classify(void* ctx, GridRect r, uint8_t* cls) {
  MaterialColours<H>* m = static_cast<MaterialColours<H>*>(ctx);
  const DexelGrid<H>& g = *m->grid;
  if (m->top_rgb) {
    // Every dexel the first time (whatever r is), then what changed in r.
    texture_tops(m, m->rgb_valid ? r : g.bounds());
    m->rgb_valid = true;
    return;
  }
  const int32_t i0 = max_of(r.i0, int32_t{0}), i1 = min_of(r.i1, g.nx);
  const int32_t j0 = max_of(r.j0, int32_t{0}), j1 = min_of(r.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j)
    for (int32_t i = i0; i < i1; ++i) {
      const size_t at = g.index(i, j);
      const PointNm p =
          composition_part_point(*m->comp, PointNm{g.x0_nm + i * g.pitch_nm, g.y0_nm + j * g.pitch_nm, slab_z_nm(g, g.top[at])});
      const int64_t z = p.z_nm;
      const uint8_t k = composition_material_in_part(*m->comp, p);
      int32_t c = m->first_class[k];
      const Texture& t = m->comp->materials[k].texture;
      if (t.kind == TextureKind::kLayers)  // its band: boundaries at or under z
        for (int32_t b = 0; b < t.layers.boundary_count; ++b) c += z >= t.layers.boundary_z_nm[b];
      cls[at] = static_cast<uint8_t>(min_of<int32_t>(c, m->colours.nclasses - 1));
    }
}

}  // namespace

template <class H>
void material_colours_init(MaterialColours<H>* m, const DexelGrid<H>& g, const StockComposition& c, uint8_t* cls,
                           uint32_t* luts) {
  m->grid = &g;
  m->comp = &c;
  m->colours.cls = cls;
  m->colours.luts = luts;
  int32_t n = 0;
  for (int32_t k = 0; k < c.material_count; ++k) {
    m->first_class[k] = static_cast<uint8_t>(min_of<int32_t>(n, kMaxColourClasses - 1));
    const Texture& t = c.materials[k].texture;
    const int32_t bands = t.kind == TextureKind::kLayers ? t.layers.boundary_count + 1 : 1;
    for (int32_t b = 0; b < bands && n < kMaxColourClasses; ++b, ++n) {
      const Rgb8 band = t.layers.colour[b];
      m->colours.colour[n] = t.kind == TextureKind::kLayers ? Rgb{band.r, band.g, band.b} : material_swatch(c.materials[k]);
    }
  }
  if (n == 0) m->colours.colour[n++] = Rgb{168, 168, 168};
  m->colours.nclasses = n;
  m->colours.classify = classify<H>;
  m->colours.ctx = m;
}

namespace {

// Adds the height of z (nm) to the breaks when it lies inside the grid's range.
template <class H>
void add_break(const DexelGrid<H>& g, int64_t z_nm, SurfaceTexture* t) {
  // Bounds may be open (a layer up to INT64_MAX): compare before subtracting.
  const int64_t top_nm = g.z0_nm + static_cast<int64_t>(static_cast<H>(~H{0})) * g.lsb_nm;
  if (z_nm <= g.z0_nm || z_nm > top_nm || t->nbreaks >= kTextureBreaksMax) return;
  const int64_t h = div_round(z_nm - g.z0_nm, g.lsb_nm);
  if (h <= 0) return;
  int32_t k = t->nbreaks;  // insertion, ascending, no duplicates
  while (k > 0 && t->breaks_lsb[k - 1] > static_cast<uint32_t>(h)) --k;
  if (k > 0 && t->breaks_lsb[k - 1] == static_cast<uint32_t>(h)) return;
  for (int32_t n = t->nbreaks; n > k; --n) t->breaks_lsb[n] = t->breaks_lsb[n - 1];
  t->breaks_lsb[k] = static_cast<uint32_t>(h);
  ++t->nbreaks;
}

}  // namespace

template <class H>
void material_colours_texture(MaterialColours<H>* m, void* mem, uint32_t uncut_top_lsb) {
  const DexelGrid<H>& g = *m->grid;
  const StockComposition& c = *m->comp;
  const size_t cells = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  m->top_rgb = static_cast<uint32_t*>(mem);
  m->rgb_top = reinterpret_cast<H*>(m->top_rgb + cells);
  m->rgb_valid = false;
  m->uncut_top_lsb = uncut_top_lsb;
  SurfaceTexture& t = m->texture;
  t = SurfaceTexture{};
  t.top_rgb = m->top_rgb;
  t.colour_at = colour_at<H>;
  t.ctx = m;
  // Where the colour jumps: the composition's z bounds, the layers' bands
  // (the first kTextureBreaksMax in this order; more are left to the
  // lattice).
  bool varies = false;
  for (int32_t k = 0; k < c.layer_count; ++k) {
    add_break(g, c.layers[k].z_lo_nm, &t);
    add_break(g, c.layers[k].z_hi_nm, &t);
  }
  for (int32_t k = 0; k < c.insert_count; ++k) {
    add_break(g, c.inserts[k].box.lo.z_nm, &t);
    add_break(g, c.inserts[k].box.hi.z_nm, &t);
  }
  for (int32_t k = 0; k < c.material_count; ++k) {
    const Texture& x = c.materials[k].texture;
    if (x.kind == TextureKind::kLayers)
      for (int32_t b = 0; b < x.layers.boundary_count; ++b) add_break(g, x.layers.boundary_z_nm[b], &t);
    varies |= x.kind != TextureKind::kPlain && x.kind != TextureKind::kLayers;
  }
  // Textures that vary inside a material: a lattice of a 16th of the
  // stock's height (kWallSplitsMax strips on its tallest wall).
  uint32_t top = 0;
  for (size_t k = 0; k < cells; ++k) top = max_of<uint32_t>(top, g.top[k]);
  if (varies) t.split_lsb = max_of<uint32_t>(1, (top + kWallSplitsMax - 1) / kWallSplitsMax);
  m->colours.texture = &t;
}

template void material_colours_texture<uint8_t>(MaterialColours<uint8_t>*, void*, uint32_t);
template void material_colours_texture<uint16_t>(MaterialColours<uint16_t>*, void*, uint32_t);
template void material_colours_texture<uint32_t>(MaterialColours<uint32_t>*, void*, uint32_t);

template void material_colours_init<uint8_t>(MaterialColours<uint8_t>*, const DexelGrid<uint8_t>&,
                                             const StockComposition&, uint8_t*, uint32_t*);
template void material_colours_init<uint16_t>(MaterialColours<uint16_t>*, const DexelGrid<uint16_t>&,
                                              const StockComposition&, uint8_t*, uint32_t*);
template void material_colours_init<uint32_t>(MaterialColours<uint32_t>*, const DexelGrid<uint32_t>&,
                                              const StockComposition&, uint8_t*, uint32_t*);

}  // namespace dexmill
