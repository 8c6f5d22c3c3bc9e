// Golden section "builtin": the paper's four workpieces (core/design/
// builtin.h) pinned bit for bit, one line per design: its grid at
// m = 16 bits, the lowest, highest and mean design top (LSB) and the hash of
// every top. The designs are evaluated column by column, so even the
// 256 x 256 free-form surface needs no memory here.
#include <stdint.h>

#include "core/design/builtin.h"
#include "core/math/hash.h"
#include "tests/golden/golden.h"

using namespace dexmill;

namespace golden {

void golden_builtin(Out& out) {
  for (int32_t k = 0; k < builtin_design_count(); ++k) {
    const BuiltinDesign& b = builtin_design_at(k);
    const GridGeometry geo = builtin_geometry(b, 16);
    Hash64 h;
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    int64_t sum = 0;
    for (int32_t j = 0; j < geo.ny; ++j)
      for (int32_t i = 0; i < geo.nx; ++i) {
        const int32_t t = builtin_top_lsb(b, geo, i, j);
        lo = t < lo ? t : lo;
        hi = t > hi ? t : hi;
        sum += t;
        h.uint_le(static_cast<uint32_t>(t), 4);
      }
    out.str("builtin ").str(b.name).kv("nx", geo.nx).kv("ny", geo.ny).kv("pitch_nm", geo.pitch_nm);
    out.kv("lsb_nm", geo.lsb_nm).kv("ball", b.ball_dexels).kv("min", lo).kv("max", hi);
    out.kv("mean", sum / (static_cast<int64_t>(geo.nx) * geo.ny)).kx("tops", h.value()).end();
  }
}

}  // namespace golden
