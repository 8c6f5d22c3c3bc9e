// libFuzzer target: the PGM reader (platform/format/pgm.h), P5 and P2, 8 and 16
// bit, and the design made from the image (core/design/design.h's
// design_from_image, what `run --design FILE.pgm` does). The input is the
// file. The reader must take memory in proportion to the file, not to what
// its header claims. An image that reads must hold width x height samples,
// none above maxval; laid over a small grid, every column inside gets a
// design top between the low and high z, every column outside none.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "platform/format/pgm.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz_pgm {

using namespace dexmill;

int fuzz_pgm(const uint8_t* data, size_t size) {
  const std::vector<unsigned char> bytes(data, data + size);
  PgmImage img;
  std::string err;
  const PgmRead r = pgm_parse("fuzz.pgm", bytes, &img, &err);
  FUZZ_REQUIRE(r != PgmRead::kIoError);
  // Memory in proportion to the file, whatever its header claims (every
  // sample takes a byte at least); `make fuzz` also limits malloc to 64 MB.
  FUZZ_REQUIRE(img.samples.capacity() <= size + 1);
  if (r != PgmRead::kOk) {
    FUZZ_REQUIRE(err.compare(0, 9, "fuzz.pgm:") == 0);
    return 0;
  }
  FUZZ_REQUIRE(img.width >= 1 && img.height >= 1 && img.maxval >= 1 && img.maxval <= 65535);
  FUZZ_REQUIRE(img.samples.size() == static_cast<size_t>(img.width) * static_cast<size_t>(img.height));
  for (uint16_t s : img.samples) FUZZ_REQUIRE(s <= img.maxval);

  // Over the stock of a 20x14 grid, 1 mm pitch, ring of holes around it;
  // the image from z -6 mm (0) to z 0 (maxval).
  static int32_t tops[20 * 14];
  const GridGeometry geo{20, 14, -kNmPerMm, -kNmPerMm, kNmPerMm, -10 * kNmPerMm, 1000};
  DesignGrid d;
  FUZZ_REQUIRE(ok(design_init(&d, geo, tops, 20 * 14)));
  const int64_t zlo = -6 * kNmPerMm, zhi = 0;
  const HeightImage h{img.samples.data(), img.width, img.height, img.maxval};
  FUZZ_REQUIRE(ok(design_from_image(&d, h, 0, 0, 17 * kNmPerMm, 11 * kNmPerMm, zlo, zhi)));
  for (int32_t j = 0; j < geo.ny; ++j)
    for (int32_t i = 0; i < geo.nx; ++i) {
      const int32_t t = tops[d.index(i, j)];
      const bool inside = i >= 1 && i <= 18 && j >= 1 && j <= 12;
      FUZZ_REQUIRE(inside == (t != kNoDesign));
      if (inside) FUZZ_REQUIRE(t >= (zlo - geo.z0_nm) / geo.lsb_nm && t <= (zhi - geo.z0_nm) / geo.lsb_nm);
    }
  return 0;
}

}  // namespace fuzz_pgm

DEXMILL_FUZZ_ENTRY(fuzz_pgm::fuzz_pgm)
