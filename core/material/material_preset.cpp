// The built-in materials; see material_preset.h.
//
// Process numbers are typical values, not a machining handbook's: a small
// 3-axis mill, a 6 mm two- or three-flute carbide cutter. Feeds are the
// highest a hobby-to-light-industrial machine would run in the material;
// spindle ranges span the speeds such cutters are run at; densities are
// the materials' usual ones.
#include "core/material/material_preset.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int64_t kNmPerMinPerMmPerMin = kNmPerMm;  // 1 mm/min = 10^6 nm/min

MaterialProcess process(int64_t feed_mm_per_min, int32_t rpm_lo, int32_t rpm_hi, bool coolant, int64_t tol_um,
                        int32_t density_mg_per_cm3) {
  MaterialProcess p;
  p.max_feed_nm_per_min = feed_mm_per_min * kNmPerMinPerMmPerMin;
  p.spindle_min_rpm = rpm_lo;
  p.spindle_max_rpm = rpm_hi;
  p.coolant_allowed = coolant;
  p.tolerance_nm = tol_um * kNmPerUm;
  p.density_mg_per_cm3 = density_mg_per_cm3;
  return p;
}

// Kienzle's coefficients and the thickest chip a tooth may take
// (core/engage/engage_load.h); 0: not known (no force, power or limit).
void cutting(Material* m, int32_t kc11_n_per_mm2, int32_t mc_ppm, int64_t max_chip_um) {
  m->process.kc11_n_per_mm2 = kc11_n_per_mm2;
  m->process.mc_ppm = mc_ppm;
  m->process.max_chip_nm = max_chip_um * kNmPerUm;
}

Material named(const char* name) {
  Material m;
  (void)material_set_name(&m, name);  // the names below are all short enough
  return m;
}

int64_t mid(int64_t a, int64_t b) { return div_floor(a, 2) + div_floor(b, 2) + ((a & 1) & (b & 1)); }

using Build = bool (*)(BoxNm stock, StockComposition* out);

bool single(StockComposition* out, const Material& m) {
  composition_clear(out);
  uint8_t i = 0;
  return ok(composition_add_material(out, m, &i)) && ok(composition_set_default(out, i));
}

bool two_layer(BoxNm s, StockComposition* out) { return single(out, material_abs_laminate(s)); }
bool marble(BoxNm s, StockComposition* out) { return single(out, material_marble(s)); }
bool wood(BoxNm s, StockComposition* out) { return single(out, material_beech(s)); }
bool bronze(BoxNm s, StockComposition* out) { return single(out, material_bronze(s)); }
bool aluminium(BoxNm s, StockComposition* out) { return single(out, material_aluminium(s)); }
bool granite(BoxNm s, StockComposition* out) { return single(out, material_granite(s)); }

// Beech from half the height up (and anything above the block), aluminium
// below: the glue line at mid height.
bool wood_on_aluminium(BoxNm s, StockComposition* out) {
  composition_clear(out);
  uint8_t alu = 0, beech = 0;
  Material w = material_beech(s);
  w.texture.wood.centre_b_nm = mid(s.lo.z_nm, s.hi.z_nm) - 60 * kNmPerMm;
  return ok(composition_add_material(out, material_aluminium(s), &alu)) && ok(composition_add_material(out, w, &beech)) &&
         ok(composition_set_default(out, alu)) &&
         ok(composition_add_layer(out, mid(s.lo.z_nm, s.hi.z_nm), INT64_MAX, beech));
}

struct Preset {
  const char* name;
  Build build;
};
const Preset kPresets[] = {
    {"two-layer", two_layer}, {"marble", marble},   {"wood", wood},
    {"bronze", bronze},       {"aluminium", aluminium}, {"granite", granite},
    {"wood-on-aluminium", wood_on_aluminium},
};
constexpr int32_t kPresetCount = static_cast<int32_t>(sizeof kPresets / sizeof kPresets[0]);

bool same_name(const char* a, const char* b) {
  while (*a && *a == *b) ++a, ++b;
  return *a == *b;
}

}  // namespace

Material material_abs_laminate(BoxNm stock) {
  Material m = named("abs-laminate");
  m.texture.kind = TextureKind::kLayers;
  m.texture.layers.boundary_count = 1;
  m.texture.layers.boundary_z_nm[0] = mid(stock.lo.z_nm, stock.hi.z_nm);  // black above half the height (eq. 4)
  m.texture.layers.colour[0] = Rgb8{232, 192, 24};
  m.texture.layers.colour[1] = Rgb8{24, 24, 24};
  // Engraving laminate: 1500 mm/min, 8000-24000 rpm, coolant harmless,
  // 0.05 mm, ABS about 1.05 g/cm^3.
  m.process = process(1500, 8000, 24000, true, 50, 1050);
  // No Kienzle coefficients we can source for ABS; a tooth's chip up to
  // 0.2 mm (plastics melt on chips much thinner than that, not thicker).
  cutting(&m, 0, 0, 200);
  return m;
}

Material material_marble(BoxNm stock) {
  Material m = named("marble");
  m.texture.kind = TextureKind::kMarble;
  m.texture.marble.origin_nm = stock.lo.x_nm;
  // Stone: slow feeds (600 mm/min), 3000-12000 rpm, wet cutting is the
  // rule, 0.05 mm, calcite marble 2.71 g/cm^3.
  m.process = process(600, 3000, 12000, true, 50, 2710);
  // Stone is ground away, not cut as a chip: no Kienzle coefficients, no
  // chip limit.
  return m;
}

Material material_beech(BoxNm stock) {
  Material m = named("beech");
  m.texture.kind = TextureKind::kWood;
  m.texture.wood.axis = Axis::kY;
  m.texture.wood.centre_a_nm = mid(stock.lo.x_nm, stock.hi.x_nm);
  m.texture.wood.centre_b_nm = stock.lo.z_nm - 60 * kNmPerMm;  // flat-sawn: the pith well below the board
  // Hardwood on a router: 3000 mm/min, 12000-24000 rpm, no coolant (paper
  // §2.6: wood soaks it up), 0.1 mm (wood moves), beech 0.72 g/cm^3.
  m.process = process(3000, 12000, 24000, false, 100, 720);
  // An estimate, not a measured coefficient: across the grain, beech
  // takes a tangential force of the order of 7.5 N per mm of edge at a
  // 0.1 mm chip, rising steeply on thinner chips; kc1.1 = 25 N/mm^2 with
  // mc = 0.5 gives that (trust it within a factor of 2). Router cutters
  // take chips up to about 0.3 mm a tooth in hardwood.
  cutting(&m, 25, 500000, 300);
  return m;
}

Material material_bronze(BoxNm stock) {
  (void)stock;  // the patina's scale is the metal's, not the block's
  Material m = named("bronze");
  m.texture.kind = TextureKind::kBronze;
  // Cast bearing bronze: 400 mm/min, 1500-8000 rpm, coolant allowed,
  // 0.02 mm (bearing faces, §2.6), 8.8 g/cm^3.
  m.process = process(400, 1500, 8000, true, 20, 8800);
  // Sandvik Coromant's material table, ISO N3 (copper alloys: kc1 from
  // about 550 N/mm^2 for leaded to 1350 for pure copper, mc 0.25): the
  // bronzes' 700; a 6 mm carbide cutter's chip up to 0.05 mm a tooth.
  cutting(&m, 700, 250000, 50);
  return m;
}

Material material_aluminium(BoxNm stock) {
  (void)stock;
  Material m = named("aluminium");
  m.texture.kind = TextureKind::kPlain;
  m.texture.plain = Rgb8{196, 200, 206};
  // 6061-T6: 1500 mm/min, 6000-24000 rpm, coolant allowed, 0.02 mm,
  // 2.70 g/cm^3.
  m.process = process(1500, 6000, 24000, true, 20, 2700);
  // Sandvik Coromant's material table, ISO N1.2 (wrought aluminium, aged):
  // kc1 = 650 N/mm^2, mc = 0.25; a 6 mm carbide cutter's chip up to 0.06 mm
  // a tooth.
  cutting(&m, 650, 250000, 60);
  return m;
}

Material material_granite(BoxNm stock) {
  (void)stock;
  Material m = named("granite");
  m.texture.kind = TextureKind::kGranite;
  // Hard stone: 300 mm/min, 2000-8000 rpm, wet, 0.05 mm, 2.65 g/cm^3.
  m.process = process(300, 2000, 8000, true, 50, 2650);
  // Ground away like marble: no Kienzle coefficients, no chip limit.
  return m;
}

int32_t material_preset_index(const char* name) {
  for (int32_t k = 0; k < kPresetCount; ++k)
    if (same_name(name, kPresets[k].name)) return k;
  return -1;
}

bool material_preset(const char* name, BoxNm stock, StockComposition* out) {
  // The presets fit the composition's capacities by construction, so a
  // known name always builds.
  const int32_t k = material_preset_index(name);
  return k >= 0 && kPresets[k].build(stock, out);
}

int32_t material_preset_count() { return kPresetCount; }

const char* material_preset_name(int32_t i) { return i >= 0 && i < kPresetCount ? kPresets[i].name : "?"; }

}  // namespace dexmill
