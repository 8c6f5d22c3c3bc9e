// Materials and the stock's composition (paper §2.6: material varies inside
// the block; each region brings its own colour and process limits).
//
// A Material is a name, a colour (a texture of texture.h) and the process
// rules the cut must respect in it. A StockComposition says which material
// fills each point of the stock: horizontal layers and inserts (boxes,
// vertical cylinders) over a default material, in fixed capacities (no
// heap). composition_material_at() is what the process rules and the
// display sample; material_preset.h builds the named presets.
#ifndef DEXMILL_CORE_MATERIAL_MATERIAL_H
#define DEXMILL_CORE_MATERIAL_MATERIAL_H

#include <stdint.h>

#include "core/material/colour.h"
#include "core/material/texture.h"
#include "core/math/part_frame.h"
#include "core/point.h"
#include "core/status.h"

namespace dexmill {

constexpr int32_t kMaterialNameMax = 16;  // characters, without the terminating NUL

// What cutting a material allows (paper §2.6). Every field always holds a
// value; a default Material allows everything a small mill can do.
struct MaterialProcess {
  int64_t max_feed_nm_per_min = 20000000000;  // 20 m/min: no practical limit
  int32_t spindle_min_rpm = 0;
  int32_t spindle_max_rpm = 100000;
  bool coolant_allowed = true;                // false: M7/M8 while cutting it is a violation
  int64_t tolerance_nm = 50000;               // accuracy the region needs, 0.05 mm
  int32_t density_mg_per_cm3 = 1000;          // mass removed = volume x density (1000 = 1 g/cm^3)
  // Cutting (core/engage/engage_load.h): Kienzle's specific cutting force
  // kc1.1 and exponent mc (0: not known, no force or power), and the
  // thickest chip a tooth may take (0: no limit; `--check load`).
  int32_t kc11_n_per_mm2 = 0;
  int32_t mc_ppm = 0;
  int64_t max_chip_nm = 0;
};

struct Material {
  char name[kMaterialNameMax + 1] = "stock";
  Texture texture;                            // its colour at any point
  MaterialProcess process;
};

// Copies `name` into m->name; kBadArgument (m unchanged) when it is empty or
// longer than kMaterialNameMax.
Status material_set_name(Material* m, const char* name);

constexpr int32_t kCompositionMaxMaterials = 8;
constexpr int32_t kCompositionMaxLayers = 8;
constexpr int32_t kCompositionMaxInserts = 16;
constexpr int64_t kCompositionMaxRadiusNm = int64_t(1) << 30;  // about 1.07 m

// z_lo <= z < z_hi is `material`.
struct CompositionLayer {
  int64_t z_lo_nm, z_hi_nm;
  uint8_t material;
};

enum class InsertShape : uint8_t { kBox = 0, kCylinder = 1 };

struct CompositionInsert {
  InsertShape shape;
  uint8_t material;
  // kBox: lo <= p < hi on every axis. kCylinder: lo.z <= z < hi.z and
  // (x - centre_x)^2 + (y - centre_y)^2 <= radius^2 (x, y of the box unused).
  BoxNm box;
  int64_t centre_x_nm, centre_y_nm, radius_nm;
};

// Which material fills each point: the last insert containing it, else the
// last layer containing it, else default_material. Layers and inserts refer
// to materials by index into materials[].
struct StockComposition {
  Material materials[kCompositionMaxMaterials];
  int32_t material_count = 0;
  CompositionLayer layers[kCompositionMaxLayers] = {};
  int32_t layer_count = 0;
  CompositionInsert inserts[kCompositionMaxInserts] = {};
  int32_t insert_count = 0;
  uint8_t default_material = 0;
  // Layers, inserts and textures are the part's (core/math/part_frame.h):
  // once a setup has turned the part, a machine point is met at its part
  // point, so the materials follow the part. Unframed: the machine's.
  bool framed = false;
  PartFrame frame = part_frame_identity();
};

// Empties c (no materials, layers or inserts; default material 0).
void composition_clear(StockComposition* c);
// Appends m; its index in *index. kBufferTooSmall when full.
Status composition_add_material(StockComposition* c, const Material& m, uint8_t* index);
// kBadArgument for an unknown material, an empty range (lo >= hi), a box
// empty on any axis, a radius outside 1..kCompositionMaxRadiusNm;
// kBufferTooSmall when full. On failure c is unchanged.
Status composition_add_layer(StockComposition* c, int64_t z_lo_nm, int64_t z_hi_nm, uint8_t material);
Status composition_add_box(StockComposition* c, BoxNm box, uint8_t material);
Status composition_add_cylinder(StockComposition* c, int64_t centre_x_nm, int64_t centre_y_nm, int64_t radius_nm,
                                int64_t z_lo_nm, int64_t z_hi_nm, uint8_t material);
Status composition_set_default(StockComposition* c, uint8_t material);

// Where the part is now (a setup's frame: core/stock/stock_file.h
// StockMeta::frame). kBadArgument, nothing changed, for a turn that does
// not keep Z an axis of its own (no setup makes one).
Status composition_set_frame(StockComposition* c, const PartFrame& f);
// The part point of a machine point (itself when unframed).
PointNm composition_part_point(const StockComposition& c, const PointNm& machine);

// The index of the material at (x, y, z), machine coordinates, nm: always
// below material_count when the composition has a material (0 otherwise).
uint8_t composition_material_at(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_nm);
// The same at a point of the part's frame.
uint8_t composition_material_in_part(const StockComposition& c, const PointNm& part);
// The colour there: the texture of the material there (grey when empty).
Rgb8 composition_colour_at(const StockComposition& c, PointNm p);

}  // namespace dexmill

#endif
