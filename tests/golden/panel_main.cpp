// The Cortex-M panel demo (`make panel`): what a controller panel does with
// dexmill, on an emulated MPS2 AN386 board (Cortex-M4F), built freestanding
// with semihosting only for printing. The same file built for the host gives
// the reference output; tools/scripts/panel.sh requires every line that does
// not start with "info" to be identical.
//
// Pipeline (DESIGN.md "One pipeline"): program source -> canonical motion
// records (core/canon.h) -> CutSink (stamping, paper §2.3) -> static dexel
// grid -> grid hash -> [frame render + frame hash: see FRAME below].
//
// Everything lives in static memory sized at compile time; the move list is
// const data in flash. No heap, no stdio, integer only.
#include <stddef.h>
#include <stdint.h>

#include "core/canon.h"
#include "core/config.h"
#include "core/cutter.h"
#include "core/grid.h"
#include "core/stamp.h"
#include "core/tool.h"
#include "tests/golden/board.h"
#include "tests/golden/golden_out.h"

using namespace dexmill;

namespace {

constexpr int64_t um(int64_t v) { return v * kNmPerUm; }
constexpr int64_t mm(int64_t v) { return v * kNmPerMm; }

// ---- the workpiece: a 48 x 32 x 20 mm block at 0.25 mm ---------------------
constexpr int32_t kNx = 192, kNy = 128;
constexpr int64_t kPitchNm = um(250);
constexpr int64_t kStockTopNm = mm(20);
constexpr int64_t kRangeNm = mm(25);  // material range the m-bit heights cover
height_t g_top[kNx * kNy];
height_t g_bottom[kNx * kNy];

// ---- the tool table (T1..T4) ------------------------------------------------
struct PanelTool {
  ToolKind kind;
  int64_t diameter_nm, corner_nm;
  int32_t tip_mdeg;
};
constexpr PanelTool kTools[] = {
    {ToolKind::kFlat, mm(6), 0, 0},          // T1 roughing end mill
    {ToolKind::kBall, mm(4), 0, 0},          // T2 finishing ball
    {ToolKind::kVBit, mm(6), 0, 90000},      // T3 engraving V-bit
    {ToolKind::kBullNose, mm(8), mm(1), 0},  // T4 contouring bull nose
};
constexpr int kToolCount = static_cast<int>(sizeof kTools / sizeof kTools[0]);
constexpr int64_t kToolLengthNm = mm(40);

// Cutter dexel sets need (2K+1)^2 * 2 + ... words each (core/cutter.h), K =
// R / pitch: all of them sized here, at compile time.
constexpr size_t cutter_words_for(int i) {
  return i == kToolCount ? 0
                         : cutter_storage_words(static_cast<int32_t>(kTools[i].diameter_nm / 2 / kPitchNm)) +
                               cutter_words_for(i + 1);
}
constexpr size_t kCutterWords = cutter_words_for(0);
int32_t g_cutter_words[kCutterWords];
CutterDexels g_cutters[kToolCount];

// ---- the demo program: const data in flash ----------------------------------
// One record per canonical command, positions in um. It stands in for G-code
// text in flash until the reader (core/gcode*, core/interp*) lands; then
// play_program() parses the text instead and emits into the same CanonSink.
struct DemoMove {
  CanonKind kind;
  int32_t arg;             // kToolChange: tool number; kSpindle: rpm
  int32_t x_um, y_um, z_um;  // kTraverse, kFeed: end point
};
constexpr CanonKind G0 = CanonKind::kTraverse, G1 = CanonKind::kFeed, M6 = CanonKind::kToolChange;
constexpr int32_t kSafeZ = 25000;
const DemoMove kDemo[] = {
    {M6, 1, 0, 0, 0}, {CanonKind::kSpindle, 12000, 0, 0, 0},
    // T1: ramp into a 28 x 16 mm pocket 4 mm deep, zig-zag, then a deeper
    // inner pocket, then four through holes
    {G0, 0, 10000, 8000, kSafeZ}, {G1, 0, 10000, 8000, 21000}, {G1, 0, 20000, 8000, 16000},
    {G1, 0, 38000, 8000, 16000}, {G1, 0, 38000, 12000, 16000}, {G1, 0, 10000, 12000, 16000},
    {G1, 0, 10000, 16000, 16000}, {G1, 0, 38000, 16000, 16000}, {G1, 0, 38000, 20000, 16000},
    {G1, 0, 10000, 20000, 16000}, {G1, 0, 10000, 24000, 16000}, {G1, 0, 38000, 24000, 16000},
    {G0, 0, 38000, 24000, kSafeZ},
    {G0, 0, 16000, 13000, kSafeZ}, {G1, 0, 16000, 13000, 13000}, {G1, 0, 32000, 13000, 13000},
    {G1, 0, 32000, 19000, 13000}, {G1, 0, 16000, 19000, 13000}, {G1, 0, 16000, 13000, 13000},
    {G0, 0, 16000, 13000, kSafeZ},
    {G0, 0, 4000, 4000, kSafeZ}, {G1, 0, 4000, 4000, -1000}, {G0, 0, 4000, 4000, kSafeZ},
    {G0, 0, 44000, 4000, kSafeZ}, {G1, 0, 44000, 4000, -1000}, {G0, 0, 44000, 4000, kSafeZ},
    {G0, 0, 44000, 28000, kSafeZ}, {G1, 0, 44000, 28000, -1000}, {G0, 0, 44000, 28000, kSafeZ},
    {G0, 0, 4000, 28000, kSafeZ}, {G1, 0, 4000, 28000, -1000}, {G0, 0, 4000, 28000, kSafeZ},
    // T4: a contour around the pocket, 5 mm deep
    {M6, 4, 0, 0, 0},
    {G0, 0, 7000, 5000, kSafeZ}, {G1, 0, 7000, 5000, 15000}, {G1, 0, 41000, 5000, 15000},
    {G1, 0, 41000, 27000, 15000}, {G1, 0, 7000, 27000, 15000}, {G1, 0, 7000, 5000, 15000},
    {G0, 0, 7000, 5000, kSafeZ},
    // T2: finishing ramps across the pocket floor
    {M6, 2, 0, 0, 0},
    {G0, 0, 12000, 14000, kSafeZ}, {G1, 0, 12000, 14000, 16000}, {G1, 0, 36000, 18000, 13500},
    {G1, 0, 12000, 22000, 14500}, {G1, 0, 36000, 10500, 15250}, {G0, 0, 36000, 10500, kSafeZ},
    // T3: engraving on the top face, 0.8 mm deep, and one stroke over the edge
    {M6, 3, 0, 0, 0},
    {G0, 0, 9000, 30000, kSafeZ}, {G1, 0, 9000, 30000, 19200}, {G1, 0, 15000, 30000, 19200},
    {G1, 0, 17000, 28600, 19200}, {G1, 0, 19000, 31000, 19200}, {G1, 0, 21000, 28600, 19200},
    {G1, 0, 23000, 31000, 19200}, {G1, 0, 39000, 30500, 19400}, {G1, 0, 46000, 33500, 19200},
    {G0, 0, 46000, 33500, kSafeZ},
    {CanonKind::kEnd, 0, 0, 0, 0},
};
constexpr int kDemoCount = static_cast<int>(sizeof kDemo / sizeof kDemo[0]);

// The program source: turns the const records into canonical records.
void play_program(CanonSink* sink) {
  CanonRecord r{};
  r.start = PointNm{0, 0, mm(50)};  // machine home, above the work
  for (int i = 0; i < kDemoCount; ++i) {
    const DemoMove& m = kDemo[i];
    r.kind = m.kind;
    r.line = static_cast<uint32_t>(i + 1);
    r.end = r.start;
    if (m.kind == CanonKind::kTraverse || m.kind == CanonKind::kFeed) r.end = PointNm{um(m.x_um), um(m.y_um), um(m.z_um)};
    if (m.kind == CanonKind::kToolChange) r.tool = m.arg;
    if (m.kind == CanonKind::kSpindle) r.spindle_rpm = m.arg;
    sink->emit(r);
    r.start = r.end;
  }
}

// The consumer: cuts every straight move (traverses too: a rapid through
// material is a crash the preview must show) with the tool in the spindle.
class CutSink final : public CanonSink {
 public:
  explicit CutSink(DexelGrid<height_t>* g) : grid_(g) {}
  void emit(const CanonRecord& r) override {
    ++records_;
    switch (r.kind) {
      case CanonKind::kToolChange:
        tool_ = r.tool;
        break;
      case CanonKind::kTraverse:
      case CanonKind::kFeed:
        if (tool_ >= 1 && tool_ <= kToolCount) {
          stamp_line(grid_, g_cutters[tool_ - 1], r.start, r.end, &stats_);
          ++moves_;
        } else {
          ++skipped_;  // no tool in the spindle
        }
        break;
      case CanonKind::kArc:
        ++skipped_;  // arcs need the motion stage's arc stepping: counted, not cut
        break;
      default:
        break;
    }
  }
  CutStats stats_;
  uint32_t records_ = 0, moves_ = 0, skipped_ = 0;

 private:
  DexelGrid<height_t>* grid_;
  int32_t tool_ = 0;
};

bool build_cutters(const DexelGrid<height_t>& g) {
  size_t used = 0;
  for (int t = 0; t < kToolCount; ++t) {
    Tool tool;
    tool.kind = kTools[t].kind;
    tool.diameter_nm = kTools[t].diameter_nm;
    tool.corner_radius_nm = kTools[t].corner_nm;
    tool.tip_angle_mdeg = kTools[t].tip_mdeg;
    tool.flute_length_nm = mm(20);
    tool.length_nm = kToolLengthNm;
    if (!ok(tool_check(tool))) return false;
    const ToolProfile p = tool_profile(tool);
    const size_t words = cutter_storage_words(cutter_reach_dex(p, g.pitch_nm));
    if (words > kCutterWords - used) return false;
    if (!ok(cutter_build(p, g.pitch_nm, g.lsb_nm, g_cutter_words + used, words, &g_cutters[t]))) return false;
    used += words;
  }
  return true;
}

// ==== FRAME: render + frame hash (to add when display/ lands) ================
// The panel is a 480x272 RGB565 TFT (a common 4.3" controller display). Once
// display/ provides the renderer, this function:
//   1. owns static buffers beside the grid, sized here at compile time:
//        uint16_t g_frame[kFrameW * kFrameH];   // RGB565, 261 120 bytes
//        uint16_t g_zbuf[kFrameW * kFrameH];    // 16-bit z, 261 120 bytes
//   2. renders `g` into them (a camera framing the whole block),
//   3. prints "panel frame 480x272 rgb565 hash=<16 hex>" with the hash over
//      the pixels as little-endian bytes (core/hash.h), never raw memory,
//   4. brackets the render with golden::board_instructions() like the cut,
//      and prints the count on an "info" line.
// panel.sh compares every non-"info" line with the host build, so the frame
// hash is checked with no change to the scripts.
constexpr int32_t kFrameW = 480, kFrameH = 272;
void render_frame(golden::Out& out, const DexelGrid<height_t>& g) {
  (void)g;
  out.str("panel display").kv("w", kFrameW).kv("h", kFrameH).str(" rgb565");
  out.kv("frame_bytes", static_cast<int64_t>(kFrameW) * kFrameH * 2).str(" renderer=pending-display").end();
}

void info_instructions(golden::Out& out, const char* what, uint64_t n, uint64_t per) {
  out.str("info instructions ").str(what).kv("n", static_cast<int64_t>(n));
  if (per) out.kv("per_dexel_update_x100", static_cast<int64_t>(n * 100u / per));
  out.end();
}

}  // namespace

int main(int, char**) {
  golden::Out out(golden::board_write);
  const uint64_t t0 = golden::board_instructions();

  DexelGrid<height_t> g;
  const int bits = static_cast<int>(sizeof(height_t) * 8);
  const GridGeometry geo{kNx, kNy, kPitchNm / 2, kPitchNm / 2, kPitchNm, 0, lsb_for_range(kRangeNm, bits)};
  if (!ok(grid_init(&g, geo, g_top, g_bottom, static_cast<size_t>(kNx) * kNy)) || !build_cutters(g)) {
    out.str("panel FAIL set-up").end();
    return 1;
  }
  grid_block_stock(&g, grid_height_of_z(g, kStockTopNm));
  out.str("panel grid").kv("nx", kNx).kv("ny", kNy).kv("m", bits).kv("pitch_nm", g.pitch_nm).kv("lsb_nm", g.lsb_nm);
  out.kv("grid_bytes", static_cast<int64_t>(sizeof g_top + sizeof g_bottom));
  out.kv("cutter_bytes", static_cast<int64_t>(sizeof g_cutter_words)).end();
  const uint64_t t1 = golden::board_instructions();

  CutSink sink(&g);
  play_program(&sink);
  const uint64_t t2 = golden::board_instructions();

  const uint64_t hash = grid_hash(g);
  const uint64_t t3 = golden::board_instructions();
  out.str("panel program").kv("records", sink.records_).kv("moves", sink.moves_).kv("skipped", sink.skipped_).end();
  out.str("panel cut").kv("instances", static_cast<int64_t>(sink.stats_.instances));
  out.kv("dexel_updates", static_cast<int64_t>(sink.stats_.dexel_updates)).end();
  out.str("panel grid").kx("hash", hash).end();

  render_frame(out, g);

  if (t3 != 0) {
    out.str("info clock: ").str(golden::board_clock_name()).end();
    info_instructions(out, "setup(grid+cutters)", t1 - t0, 0);
    info_instructions(out, "cut", t2 - t1, sink.stats_.dexel_updates);
    info_instructions(out, "grid_hash", t3 - t2, 0);
  }
  return 0;
}
