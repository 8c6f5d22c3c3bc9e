// Materials and the stock's composition; see material.h.
#include "core/material/material.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

bool known(const StockComposition& c, uint8_t material) { return material < c.material_count; }

bool in_box(const BoxNm& b, int64_t x, int64_t y, int64_t z) {
  return b.lo.x_nm <= x && x < b.hi.x_nm && b.lo.y_nm <= y && y < b.hi.y_nm && b.lo.z_nm <= z && z < b.hi.z_nm;
}

bool in_cylinder(const CompositionInsert& s, int64_t x, int64_t y, int64_t z) {
  if (z < s.box.lo.z_nm || z >= s.box.hi.z_nm) return false;
  // Coordinates and centre are within +-2^46, so the differences are exact;
  // each is at most the radius (<= 2^30) before squaring, so the sum < 2^61.
  const uint64_t dx = abs_u64(clamp(x, -kCoordLimitNm, kCoordLimitNm) - s.centre_x_nm);
  const uint64_t dy = abs_u64(clamp(y, -kCoordLimitNm, kCoordLimitNm) - s.centre_y_nm);
  const uint64_t r = static_cast<uint64_t>(s.radius_nm);
  return dx <= r && dy <= r && dx * dx + dy * dy <= r * r;
}

}  // namespace

Status material_set_name(Material* m, const char* name) {
  int32_t n = 0;
  while (n <= kMaterialNameMax && name[n]) ++n;  // never past the longest name + 1
  if (n == 0 || n > kMaterialNameMax) return Status::kBadArgument;
  for (int32_t i = 0; i < n; ++i) m->name[i] = name[i];
  m->name[n] = '\0';
  return Status::kOk;
}

void composition_clear(StockComposition* c) {
  c->material_count = 0;
  c->layer_count = 0;
  c->insert_count = 0;
  c->default_material = 0;
}

Status composition_add_material(StockComposition* c, const Material& m, uint8_t* index) {
  if (c->material_count >= kCompositionMaxMaterials) return Status::kBufferTooSmall;
  c->materials[c->material_count] = m;
  *index = static_cast<uint8_t>(c->material_count++);
  return Status::kOk;
}

Status composition_add_layer(StockComposition* c, int64_t z_lo_nm, int64_t z_hi_nm, uint8_t material) {
  if (!known(*c, material) || z_lo_nm >= z_hi_nm) return Status::kBadArgument;
  if (c->layer_count >= kCompositionMaxLayers) return Status::kBufferTooSmall;
  c->layers[c->layer_count++] = CompositionLayer{z_lo_nm, z_hi_nm, material};
  return Status::kOk;
}

Status composition_add_box(StockComposition* c, BoxNm box, uint8_t material) {
  if (!known(*c, material) || box.lo.x_nm >= box.hi.x_nm || box.lo.y_nm >= box.hi.y_nm || box.lo.z_nm >= box.hi.z_nm)
    return Status::kBadArgument;
  if (c->insert_count >= kCompositionMaxInserts) return Status::kBufferTooSmall;
  CompositionInsert s{};
  s.shape = InsertShape::kBox;
  s.material = material;
  s.box = box;
  c->inserts[c->insert_count++] = s;
  return Status::kOk;
}

Status composition_add_cylinder(StockComposition* c, int64_t centre_x_nm, int64_t centre_y_nm, int64_t radius_nm,
                                int64_t z_lo_nm, int64_t z_hi_nm, uint8_t material) {
  if (!known(*c, material) || z_lo_nm >= z_hi_nm || radius_nm < 1 || radius_nm > kCompositionMaxRadiusNm)
    return Status::kBadArgument;
  if (c->insert_count >= kCompositionMaxInserts) return Status::kBufferTooSmall;
  CompositionInsert s{};
  s.shape = InsertShape::kCylinder;
  s.material = material;
  s.box.lo.z_nm = z_lo_nm;
  s.box.hi.z_nm = z_hi_nm;
  s.centre_x_nm = clamp(centre_x_nm, -kCoordLimitNm, kCoordLimitNm);
  s.centre_y_nm = clamp(centre_y_nm, -kCoordLimitNm, kCoordLimitNm);
  s.radius_nm = radius_nm;
  c->inserts[c->insert_count++] = s;
  return Status::kOk;
}

Status composition_set_default(StockComposition* c, uint8_t material) {
  if (!known(*c, material)) return Status::kBadArgument;
  c->default_material = material;
  return Status::kOk;
}

Status composition_set_frame(StockComposition* c, const PartFrame& f) {
  if (!part_frame_keeps_z(f)) return Status::kBadArgument;
  c->frame = f;
  c->framed = !part_frame_is_identity(f);
  return Status::kOk;
}

PointNm composition_part_point(const StockComposition& c, const PointNm& machine) {
  return c.framed ? part_frame_to_part(c.frame, machine) : machine;
}

uint8_t composition_material_at(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_nm) {
  return composition_material_in_part(c, composition_part_point(c, PointNm{x_nm, y_nm, z_nm}));
}

uint8_t composition_material_in_part(const StockComposition& c, const PointNm& part) {
  const int64_t x_nm = part.x_nm, y_nm = part.y_nm, z_nm = part.z_nm;
  for (int32_t i = c.insert_count - 1; i >= 0; --i) {  // later inserts win
    const CompositionInsert& s = c.inserts[i];
    if (s.shape == InsertShape::kBox ? in_box(s.box, x_nm, y_nm, z_nm) : in_cylinder(s, x_nm, y_nm, z_nm))
      return s.material;
  }
  for (int32_t i = c.layer_count - 1; i >= 0; --i)
    if (c.layers[i].z_lo_nm <= z_nm && z_nm < c.layers[i].z_hi_nm) return c.layers[i].material;
  return c.default_material;
}

Rgb8 composition_colour_at(const StockComposition& c, PointNm p) {
  if (c.material_count == 0) return Texture{}.plain;
  const PointNm q = composition_part_point(c, p);
  return texture_colour(c.materials[composition_material_in_part(c, q)].texture, q);
}

}  // namespace dexmill
