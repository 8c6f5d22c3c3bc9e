// The material colour mode; see material_colours.h.
#include "display/material_colours.h"

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

namespace {

// The material half an LSB under each top (a hole: class 0, never drawn).
template <class H>
void classify(void* ctx, GridRect r, uint8_t* cls) {
  const MaterialColours<H>* m = static_cast<const MaterialColours<H>*>(ctx);
  const DexelGrid<H>& g = *m->grid;
  const int32_t i0 = max_of(r.i0, int32_t{0}), i1 = min_of(r.i1, g.nx);
  const int32_t j0 = max_of(r.j0, int32_t{0}), j1 = min_of(r.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j)
    for (int32_t i = i0; i < i1; ++i) {
      const size_t at = g.index(i, j);
      const int64_t z = g.z0_nm + static_cast<int64_t>(g.top[at]) * g.lsb_nm - g.lsb_nm / 2;
      const uint8_t k = composition_material_at(*m->comp, g.x0_nm + i * g.pitch_nm, g.y0_nm + j * g.pitch_nm, z);
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

template void material_colours_init<uint8_t>(MaterialColours<uint8_t>*, const DexelGrid<uint8_t>&,
                                             const StockComposition&, uint8_t*, uint32_t*);
template void material_colours_init<uint16_t>(MaterialColours<uint16_t>*, const DexelGrid<uint16_t>&,
                                              const StockComposition&, uint8_t*, uint32_t*);
template void material_colours_init<uint32_t>(MaterialColours<uint32_t>*, const DexelGrid<uint32_t>&,
                                              const StockComposition&, uint8_t*, uint32_t*);

}  // namespace dexmill
