// The embedding API's STL designs (dexmill.h dm_design_from_stl): an STL
// file's bytes as dm_job.design's triangles, read by core/design/stl_mesh.h
// (what `dexmill run --design` reads files with).
#include "core/design/stl_mesh.h"
#include "display/api/dexmill.h"

using namespace dexmill;

namespace {

struct Out {
  dm_triangle* out;
  uint32_t max;
  uint32_t n;
};

bool put(void* ctx, const PointNm* v) {
  Out& o = *static_cast<Out*>(ctx);
  if (o.n == UINT32_MAX) return false;
  if (o.out && o.n < o.max)
    for (int k = 0; k < 3; ++k) {
      o.out[o.n].v_nm[k][0] = v[k].x_nm;
      o.out[o.n].v_nm[k][1] = v[k].y_nm;
      o.out[o.n].v_nm[k][2] = v[k].z_nm;
    }
  ++o.n;
  return true;
}

}  // namespace

extern "C" dm_status dm_design_from_stl(const void* bytes, size_t n, dm_triangle* out, uint32_t max, uint32_t* count) {
  if (!count || (!bytes && n > 0)) return DM_E_ARGUMENT;
  *count = 0;
  Out o{out, max, 0};
  StlScan scan;
  if (!stl_scan(static_cast<const uint8_t*>(bytes), n, PointNm{0, 0, 0}, put, &o, &scan)) return DM_E_DESIGN;
  *count = o.n;
  return out && o.n > max ? DM_E_INDEX : DM_OK;
}
