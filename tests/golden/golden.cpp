// The section list, the driver and the scratch memory of the golden program
// (see golden.h; the formatting is in golden_out.cpp).
#include "tests/golden/golden.h"

namespace golden {

// ---- the sections, in output order: add a line to add output --------------
const Section kSections[] = {
    {"math", golden_math},
    {"tool", golden_tool},
    {"stamp", golden_stamp},
    {"mill", golden_mill},
    {"path", golden_path},
    {"flow", golden_flow},
    {"motion", golden_motion},
    {"frame", golden_frame},
    {"safety", golden_safety},
    {"texture", golden_texture},
    {"regress", golden_regress},
    {"builtin", golden_builtin},
    {"demo", golden_demo},
};
const size_t kSectionCount = sizeof kSections / sizeof kSections[0];

namespace {
// Bump the format version when the shape of the output (not its values)
// changes, so an old golden.out is obviously stale.
constexpr int kFormatVersion = 1;
int g_failures = 0;

// Enough for every section: the largest users are the tool section's 12 mm
// V-bit at a 0.13 mm pitch (17 484 cutter words, 70 KiB) and the m=32
// stamp-test grid (2 x 82 x 62 x 4 bytes plus four cutters, 46 KiB).
constexpr size_t kArenaBytes = 2048 * 1024;  // the demo section's 256 x 256 workpiece with its frame
alignas(8) unsigned char g_arena_bytes[kArenaBytes];
Arena g_arena;
}  // namespace

size_t Arena::capacity() const { return kArenaBytes; }

void* Arena::take_bytes(size_t bytes, size_t align) {
  size_t at = (used_ + align - 1) / align * align;
  if (at > kArenaBytes || bytes > kArenaBytes - at) return nullptr;
  used_ = at + bytes;
  return g_arena_bytes + at;
}

Arena& arena() { return g_arena; }

void fail(Out& out, const char* what) {
  ++g_failures;
  out.str("FAIL ").str(what).end();
}

int run_all(Out::WriteFn write) {
  Out out(write);
  out.str("dexmill golden output").kv("format", kFormatVersion).kv("sections", static_cast<int64_t>(kSectionCount)).end();
  for (size_t i = 0; i < kSectionCount; ++i) {
    out.str("[").str(kSections[i].name).str("]").end();
    arena().reset();
    kSections[i].run(out);
  }
  // The line count is part of the output: a target that silently dropped
  // lines cannot match.
  out.str("end").kv("lines", out.lines() + 1).kv("failures", g_failures).end();
  return g_failures ? 1 : 0;
}

}  // namespace golden
