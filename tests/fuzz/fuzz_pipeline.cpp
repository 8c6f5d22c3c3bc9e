// libFuzzer target: bytes -> G-code reader -> interpreter -> cutting into a
// small grid (sweep or stamp, by the first byte) -> rendering a small frame.
// Any crash, sanitizer report, broken grid invariant or non-deterministic
// frame is a bug. `make fuzz SECONDS=N`.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/cut/mill.h"
#include "core/grid/grid.h"
#include "core/motion/interp.h"
#include "core/tool/tool.h"
#include "tests/fuzz/fuzz_render.h"

using namespace dexmill;

namespace {

class Library : public ToolLibrary {
 public:
  bool tool(int32_t number, Tool* out) const override {
    if (number < 0 || number > 5) return false;
    Tool t;
    t.kind = static_cast<ToolKind>(number % 4);
    t.diameter_nm = (1 + number) * kNmPerMm;
    t.corner_radius_nm = t.diameter_nm / 4;
    t.tip_angle_mdeg = 60000 + 10000 * number;
    t.flute_length_nm = 10 * kNmPerMm;
    t.length_nm = 40 * kNmPerMm;
    *out = t;
    return true;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const CutMode mode = (data[0] & 1) ? CutMode::kStamp : CutMode::kSweep;
  const bool inch = (data[0] & 2) != 0;
  const uint8_t view = static_cast<uint8_t>(data[0] >> 2);
  ++data;
  --size;
  static std::vector<uint16_t> top(48 * 40), bottom(48 * 40);
  static std::vector<int32_t> words(cutter_storage_words(64));
  DexelGrid<uint16_t> g;
  GridGeometry geo{48, 40, -1000000, -1000000, 500000, -5000000, 1000};
  if (!ok(grid_init(&g, geo, top.data(), bottom.data(), top.size()))) abort();
  grid_block_stock(&g, 20000);
  Library lib;
  Mill<uint16_t> mill(&g, mode, &lib, words.data(), words.size());
  Tool first;
  lib.tool(1, &first);
  if (!ok(mill.set_tool(first))) abort();
  InterpOptions opt;
  opt.inch = inch;
  Interp interp(&mill, opt);
  (void)interp_run_text(&interp, reinterpret_cast<const char*>(data), size, nullptr);
  mill.flush();
  // Invariants of the dexel set: bottom <= top, holes are 0/0.
  for (size_t k = 0; k < top.size(); ++k) {
    if (bottom[k] > top[k]) abort();
  }
  // Drawing is slow next to reading and cutting: one input in eight.
  if (view & 0x20) fuzz_render(g, tool_profile(mill.tool()), mill.position(), view);
  return 0;
}
