// The documented ranges' corners (core/README.md, invariant 4: nothing
// overflows silently): the smallest and largest tool of each shape (flat, ball,
// bull nose at both corner radii, V-bits at both angle limits and on the
// slopes of their cones), the finest and coarsest pitch and LSB, the
// longest grid sides, the tallest stock and coordinates at the
// interpreter's limits, each through every motion kind (rapid, lines along
// each axis, the pure plunge up and down, XY and 3-D diagonals, the
// steepest ramp short of a plunge and the gentlest one, arcs in G17, G18 and
// G19, a helix and a helix of several turns, and LinuxCNC's G2 with R of
// 100 m) in both cut modes and every height width. The program's ranges
// are stated where they are decided: core/tool/tool.h (tools),
// core/grid/grid.h and core/sim/stock_plan.h (grids, stock),
// core/cut/sweep.h (the sweep's own bound on the radius), core/interp/interp.h
// (coordinates). `make test SAN=1` runs this under ASan + UBSan with
// -fno-sanitize-recover, and with DEXMILL_CHECKED_ARITH (core/config.h), so
// that a product the code assumes fits (mul_shift_fit) and does not ends
// the run there: that is the proof that nothing overflows. The normal build
// checks that each corner cuts what a cut may (material removed, no top
// raised) in well under a second.
//
// Then values just past each range are refused with the message that
// names it: by the tool spec (core/tool/spec.h), the grid plan
// (core/sim/stock_plan.h), the sweep (core/cut/sweep.h) and `dexmill run`.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/cut/mill.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/sim/stock_plan.h"
#include "core/tool/spec.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = kNmPerMm;

// nm as G-code mm with every digit (exact: 6 decimals).
std::string mm_text(int64_t nm) {
  char b[48];
  const uint64_t a = abs_u64(nm);
  std::snprintf(b, sizeof b, "%s%llu.%06llu", nm < 0 ? "-" : "", static_cast<unsigned long long>(a / kMm),
                static_cast<unsigned long long>(a % kMm));
  return b;
}

struct Program {
  std::string text;
  void add(const char* fmt_words, std::initializer_list<std::pair<char, int64_t>> words) {
    text += fmt_words;
    for (const auto& w : words) {
      text += ' ';
      text += w.first;
      text += mm_text(w.second);
    }
    text += '\n';
  }
};

// Every motion kind over the stock box b (centred on the origin, top at
// b.hi.z) with a tool of radius r: the path's size follows the tool and the
// stock, so that the moves cut. cone_slope: a V-bit's cot(a/2), whose
// ramps along the cone's own slope (and just either side of it) are the
// V-bit's hardest case; 0 for the other shapes.
std::string motion_program(const StockBox& b, int64_t r, double cone_slope) {
  const int64_t top = b.hi.z_nm, height = b.hi.z_nm - b.lo.z_nm;
  const int64_t sx = max_of<int64_t>(1, min_of(r, (b.hi.x_nm - b.lo.x_nm) / 2));
  const int64_t sy = max_of<int64_t>(1, min_of(r, (b.hi.y_nm - b.lo.y_nm) / 2));
  const int64_t d = max_of<int64_t>(1, min_of(r, height / 2));
  // (Arcs of LinuxCNC's least radius at least, 1.27 um: core/interp/arc_center.h.)
  const int64_t ra = max_of<int64_t>(min_of(sx, sy), 2000);
  const int64_t up = min_of(top + r + 1, kGcodeMaxCoordNm);
  Program p;
  p.text = "G21 G90 G94 G17 F1000 M3 S10000\n";
  p.add("G0", {{'X', -sx}, {'Y', -sy}, {'Z', up}});   // rapid
  p.add("G1", {{'Z', top - d}});                      // plunge down
  p.add("G1", {{'X', sx}});                           // +X
  p.add("G1", {{'Y', sy}});                           // +Y
  p.add("G1", {{'X', -sx}});                          // -X
  p.add("G1", {{'Y', -sy}});                          // -Y
  p.add("G1", {{'X', sx}, {'Y', sy}});                // XY diagonal
  p.add("G1", {{'X', -sx}, {'Y', -sy}, {'Z', top - 2 * d}});  // 3-D diagonal
  p.add("G1", {{'X', sx}, {'Z', top - d}});           // ramp up along X
  p.add("G1", {{'Y', sy}, {'Z', top - 2 * d}});       // ramp down along Y
  // The steepest ramp short of a plunge (2^24:1, core/cut/sweep_piece.h)
  // and beyond it, and the gentlest: 1 nm of Z over the path.
  p.add("G1", {{'X', sx - 1}, {'Z', up}});
  p.add("G1", {{'X', sx}, {'Z', top - d}});
  p.add("G1", {{'X', -sx}, {'Z', top - d - 1}});
  p.add("G1", {{'Z', up}});                           // plunge up
  // The steepest ramp along X, (2^24 - 1):1 over 100 nm, up and down.
  const int64_t steep = ((int64_t{1} << 24) - 1) * 100;
  p.add("G0", {{'X', -sx}, {'Y', 0}, {'Z', top - d}});
  p.add("G1", {{'X', -sx + 100}, {'Z', top - d + steep}});
  p.add("G1", {{'X', -sx + 200}, {'Z', top - d}});
  p.add("G0", {{'Z', up}});
  if (cone_slope > 0) {
    // Along the cone's slope and 1e-7 either side of it, over 2 sx (or
    // shorter, where the drop would pass the coordinates' limit).
    for (const double f : {1 - 1e-7, 1.0, 1 + 1e-7, 1 - 1e-3}) {
      const double run_nm = std::min(2.0 * double(sx), 0.9 * double(kGcodeMaxCoordNm) / (cone_slope * f));
      const int64_t run = max_of<int64_t>(1, static_cast<int64_t>(run_nm));
      const int64_t drop = static_cast<int64_t>(std::llround(double(run) * cone_slope * f));
      const int64_t z0 = min_of(top + d, kGcodeMaxCoordNm - 1);
      p.add("G0", {{'X', -sx}, {'Y', 0}, {'Z', z0}});
      p.add("G1", {{'X', -sx + run}, {'Z', z0 - drop}});
      p.add("G0", {{'Z', up}});
    }
  }
  // Arcs: a level half circle and a full one in G17, a helix, a helix of
  // several turns, then G18 and G19.
  p.add("G0", {{'X', -ra}, {'Y', 0}, {'Z', top - d}});
  p.add("G2", {{'X', ra}, {'Y', 0}, {'I', ra}, {'J', 0}});
  p.add("G3", {{'X', ra}, {'Y', 0}, {'I', -ra}, {'J', 0}});
  p.add("G2", {{'X', -ra}, {'Y', 0}, {'Z', top - 2 * d}, {'I', -ra}, {'J', 0}});
  p.add("G3 P3", {{'X', -ra}, {'Y', 0}, {'Z', top - d}, {'I', ra}, {'J', 0}});
  p.add("G18 G2", {{'X', ra}, {'Z', top - d}, {'I', ra}, {'K', 0}});
  p.add("G3", {{'X', -ra}, {'Z', top - d}, {'I', -ra}, {'K', 0}});
  p.add("G0", {{'Y', -ra}});
  p.add("G19 G2", {{'Y', ra}, {'Z', top - d}, {'J', ra}, {'K', 0}});
  p.add("G3", {{'Y', -ra}, {'Z', top - d}, {'J', -ra}, {'K', 0}});
  p.text += "G17\n";
  // The exact helix's limits (core/cut/sweep_arc.cpp): just wider than the
  // tool, and of radius 2^27 nm over several turns.
  const int64_t rh = max_of<int64_t>(r + 1, 2000), rbig = int64_t{1} << 27;
  p.add("G0", {{'X', -rh}, {'Y', 0}, {'Z', top - d}});
  p.add("G2", {{'X', rh}, {'Y', 0}, {'Z', top - d - 1}, {'I', rh}, {'J', 0}});
  p.add("G0", {{'X', -rbig}, {'Y', 0}, {'Z', top - d}});
  p.add("G3 P2", {{'X', -rbig}, {'Y', 0}, {'Z', top - 2 * d}, {'I', rbig}, {'J', 0}});
  p.add("G0", {{'X', sx}, {'Y', -sy}, {'Z', top - d}});  // a rapid through the stock
  // The interpreter's limits (core/interp/interp.h): the corners of the
  // +-10 m box, a 3-D diagonal between them through the stock's top, a
  // plunge to -10 m and an arc of R 100 m.
  const int64_t lim = kGcodeMaxCoordNm;
  p.add("G0", {{'Z', lim}});
  p.add("G0", {{'X', -lim}, {'Y', -lim}});
  p.add("G1", {{'X', lim}, {'Y', lim}, {'Z', -lim}});
  p.add("G0", {{'Z', lim}});
  p.add("G0", {{'X', lim}, {'Y', -lim}});
  p.add("G1", {{'Z', -lim}});
  p.add("G2", {{'X', -lim}, {'Y', -lim}, {'R', 10 * lim - 1}});
  p.add("G0", {{'Z', lim}});
  p.text += "M2\n";
  return p.text;
}

Tool sim_tool(const char* spec) {
  Tool t;
  CHECK(tool_spec_parse(spec, std::strlen(spec), &t) == ToolSpecError::kOk);
  return t;
}

class OneTool : public ToolLibrary {
 public:
  explicit OneTool(const Tool& t) : t_(t) {}
  bool tool(int32_t, Tool* out) const override {
    *out = t_;
    return true;
  }

 private:
  Tool t_;
};

struct Corner {
  const char* what;
  const char* tool;  // a --tool spec
  StockBox stock;    // nm
  int64_t pitch_nm;  // or 0 with grid_nx, grid_ny
  int32_t grid_nx, grid_ny;
  int64_t program_top_nm = 0;  // where the program sees the stock's top, when not at it (nothing is cut)
  bool far() const { return program_top_nm != 0; }
};

StockBox box_mm(double x, double y, double z) {  // centred on the origin, top at 0
  const int64_t hx = std::llround(x * 5e5), hy = std::llround(y * 5e5), hz = std::llround(z * 1e6);
  return StockBox{PointNm{-hx, -hy, -hz}, PointNm{hx, hy, 0}};
}

StockBox raised(StockBox b, int64_t top_nm) {  // the same box with its top at top_nm
  const int64_t dz = top_nm - b.hi.z_nm;
  b.lo.z_nm += dz;
  b.hi.z_nm += dz;
  return b;
}

// Cuts the motion program into the corner's grid with H-bit heights in
// `mode` (each corner is inside what its mode takes); false when the
// stock is taller than H's heights hold.
template <class H>
bool cut_corner(const Corner& c, CutMode mode, uint64_t* removed_lsb) {
  Tool tool;
  CHECK(tool_spec_parse(c.tool, std::strlen(c.tool), &tool) == ToolSpecError::kOk);
  GridPlan plan;
  const PlanError pe = plan_grid(c.stock, c.grid_nx, c.grid_ny, c.pitch_nm, &plan);
  CHECK(pe == PlanError::kOk);
  if (pe != PlanError::kOk) return false;
  // The height LSB for H (the plan's is for the build's heights).
  const int64_t height = plan.stock.hi.z_nm - plan.stock.lo.z_nm;
  plan.geo.lsb_nm = lsb_for_range(height, int(sizeof(H) * 8));
  plan.top_lsb = div_round(height, plan.geo.lsb_nm);
  // A stock taller than 2^m - 1 LSB of 1 m (255 m for 8-bit heights) is
  // outside the grid's range (the engine refuses it, core/sim/simulation.h).
  if (plan.geo.lsb_nm > 1000 * kMm || plan.top_lsb > height_max<H>()) return false;
  const size_t cells = size_t(plan.geo.nx) * size_t(plan.geo.ny);
  std::vector<H> top(cells), bottom(cells);
  DexelGrid<H> g;
  CHECK(ok(grid_init(&g, plan.geo, top.data(), bottom.data(), cells)));
  fill_stock(&g, plan);
  uint64_t before = 0;
  for (size_t k = 0; k < cells; ++k) before += top[k] - bottom[k];
  const ToolProfile prof = tool_profile(tool);
  SweepTool st;
  CHECK(mode == CutMode::kSweep ? ok(sweep_tool_prepare(prof, g.lsb_nm, &st))
                                : cutter_reach_dex(prof, g.pitch_nm) <= kCutterMaxReach);
  // The stamp's cutter holds heights of at most 2^30 LSB (core/tool/cutter.h):
  // a 2 m stick-out over a stock of 32-bit heights of 1 nm is past it.
  if (mode == CutMode::kStamp && div_round(prof.length_nm, g.lsb_nm) > (int64_t{1} << 30)) return false;
  std::vector<int32_t> words(mill_words(mode, prof, g) + 1);
  OneTool lib(tool);
  Mill<H> mill(&g, mode, &lib, words.data(), words.size());
  const Status s = mill.set_tool(tool);
  CHECK(ok(s));
  if (!ok(s)) return false;
  double cone_slope = 0;
  if (tool.kind == ToolKind::kVBit) cone_slope = 1 / std::tan(double(tool.tip_angle_mdeg) / 2000 * 3.14159265358979 / 180);
  const std::string text = motion_program(c.far() ? raised(plan.stock, c.program_top_nm) : plan.stock,
                                          tool.diameter_nm / 2, cone_slope);
  InterpOptions opt;
  Interp interp(&mill, opt);
  GcodeDiag first{};
  const uint32_t errors = interp_run_text(&interp, text.data(), text.size(), &first);
  CHECK_EQ(errors, 0u);
  if (errors) std::printf("  %s: line %u: error %d\n%s", c.what, first.line, int(first.code), text.c_str());
  mill.finish();
  CHECK(ok(mill.status()));
  // A cut only lowers tops: none above the stock's.
  uint64_t after = 0;
  for (size_t k = 0; k < cells; ++k) {
    CHECK_LE(int64_t(top[k]), plan.top_lsb);
    after += top[k] - bottom[k];
  }
  CHECK_LE(after, before);
  *removed_lsb = before - after;
  return true;
}

// The corners. Tools: the sweep takes radii up to 2^28 nm (a 536.87 mm
// diameter), the stamp any diameter up to 1000 mm whose cutter spans at
// most 4095 dexels; a V-bit's angle is 1 to 179.999 degrees and its cone at
// most 10 m tall (the stick-out's limit: so a 1-degree bit is at most
// 174.5 mm across). The stamp places the whole cutter every pitch, so its
// corners keep the grid small where the pitch is fine.
const Corner kSweepCorners[] = {
    // Tool sizes on grids that hold them.
    {"flat 1 um, pitch 1 nm", "flat:0.001", box_mm(0.0003, 0.0001, 0.0004), 1, 0, 0},
    {"ball 1 um, pitch 1 nm", "ball:0.001", box_mm(0.0003, 0.0001, 0.0004), 1, 0, 0},
    {"bull 1 um, corner 1 nm", "bull:0.001:0.000001", box_mm(0.0003, 0.0001, 0.0004), 1, 0, 0},
    {"bull 1 um, corner R", "bull:0.001:0.0005", box_mm(0.0003, 0.0001, 0.0004), 1, 0, 0},
    {"vbit 1 um, 1 deg", "vbit:0.001:1", box_mm(0.0003, 0.0001, 0.06), 1, 0, 0},
    {"vbit 1 um, 179.999 deg", "vbit:0.001:179.999", box_mm(0.0003, 0.0001, 0.0004), 1, 0, 0},
    {"flat 536.87 mm (the sweep's largest)", "flat:536.87", box_mm(1200, 900, 400), 0, 40, 40},
    {"ball 536.87 mm", "ball:536.87", box_mm(1200, 900, 400), 0, 40, 40},
    {"bull 536.87 mm, corner 1 nm", "bull:536.87:0.000001", box_mm(1200, 900, 400), 0, 40, 40},
    {"bull 536.87 mm, corner R", "bull:536.87:268.435", box_mm(1200, 900, 400), 0, 40, 40},
    {"vbit 536.87 mm, 179.999 deg", "vbit:536.87:179.999", box_mm(1200, 900, 400), 0, 40, 40},
    {"vbit 536.87 mm, 30 deg", "vbit:536.87:30", box_mm(1200, 900, 1200), 0, 40, 40},
    {"vbit 254 mm, 30 deg (the G18 arc's)", "vbit:254:30", box_mm(600, 400, 600), 0, 40, 40},
    {"vbit 174.5 mm, 1 deg", "vbit:174.5:1", box_mm(400, 400, 9000), 0, 40, 40},
    // Grids: the longest sides, the coarsest pitch, the tallest stock, the
    // finest LSB.
    {"grid 65535 x 4", "ball:3", box_mm(65.532, 0.002, 2), 1000, 0, 0},
    {"grid 4 x 65535", "bull:0.5:0.2", box_mm(0.002, 65.532, 2), 1000, 0, 0},
    {"pitch 1 m, 20 m stock", "ball:536.87", box_mm(20000, 20000, 2000), 1000 * kMm, 0, 0},
    {"pitch 1 m, vbit", "vbit:536.87:60", box_mm(20000, 20000, 2000), 1000 * kMm, 0, 0},
    {"stock 1 km tall", "ball:536.87", box_mm(2000, 2000, 1000000), 0, 32, 32},
    {"stock 2 um tall (LSB 1 nm)", "vbit:500:90", box_mm(2000, 2000, 0.002), 0, 32, 32},
    {"stock 20 m wide, 10 m tall", "vbit:20:10", box_mm(20000, 20000, 10000), 0, 64, 64},
    {"pitch 1 m, LSB 1 nm", "flat:536.87", box_mm(20000, 20000, 0.002), 1000 * kMm, 0, 0},
    // 1 km above the program's +-10 m on LSBs of 1 nm: tips 2^48 V below z0.
    {"stock at 1 km, LSB 1 nm", "ball:536.87", raised(box_mm(2000, 2000, 0.002), 1000000 * kMm), 0, 32, 32, -1},
};

// The stamp's cutter at its widest (4095 dexels: pitch = R / 2047) and at
// the finest pitch, over small grids.
const Corner kStampCorners[] = {
    {"flat 1 um, pitch 1 nm", "flat:0.001", box_mm(0.00002, 0.00002, 0.0004), 1, 0, 0},
    {"ball 1 um, pitch 1 nm", "ball:0.001", box_mm(0.00002, 0.00002, 0.0004), 1, 0, 0},
    {"bull 1 um, corner 1 nm", "bull:0.001:0.000001", box_mm(0.00002, 0.00002, 0.0004), 1, 0, 0},
    {"vbit 1 um, 1 deg", "vbit:0.001:1", box_mm(0.00002, 0.00002, 0.06), 1, 0, 0},
    {"vbit 1 um, 179.999 deg", "vbit:0.001:179.999", box_mm(0.00002, 0.00002, 0.0004), 1, 0, 0},
    {"flat 1000 mm, 4095 dexels across", "flat:1000", box_mm(6, 6, 400), 244260, 0, 0},
    // The other shapes' 1 m at 1025 dexels (building 4095^2 rays of a
    // curved profile takes a second; the index arithmetic is the flat's).
    {"ball 1000 mm", "ball:1000", box_mm(12, 12, 400), 976000, 0, 0},
    {"bull 1000 mm, corner 1 nm", "bull:1000:0.000001", box_mm(12, 12, 400), 976000, 0, 0},
    {"bull 1000 mm, corner R", "bull:1000:500", box_mm(12, 12, 400), 976000, 0, 0},
    {"vbit 1000 mm, 179.999 deg", "vbit:1000:179.999", box_mm(12, 12, 400), 976000, 0, 0},
    {"vbit 174.5 mm, 1 deg", "vbit:174.5:1", box_mm(6, 6, 9000), 170000, 0, 0},
    {"grid 65535 x 4", "ball:0.01", box_mm(65.532, 0.002, 2), 1000, 0, 0},
    {"grid 4 x 65535", "vbit:0.01:60", box_mm(0.002, 65.532, 2), 1000, 0, 0},
    {"pitch 1 m, 1 m tool", "flat:1000", box_mm(20000, 20000, 2000), 1000 * kMm, 0, 0},
    {"stock 1 km tall", "ball:1000", box_mm(2000, 2000, 1000000), 0, 16, 16},
    {"stock 2 um tall (LSB 1 nm)", "vbit:500:90", box_mm(2000, 2000, 0.002), 0, 16, 16},
};

template <class H, size_t N>
void run_corners(const Corner (&corners)[N], CutMode mode, int* ran) {
  for (const Corner& c : corners) {
    uint64_t removed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    if (!cut_corner<H>(c, mode, &removed)) continue;
    if (getenv("RANGES_TIME"))  // each corner's time, for keeping the test fast
      std::printf("  %-40s m=%2d %s %.3f s\n", c.what, int(sizeof(H) * 8), mode == CutMode::kSweep ? "sweep" : "stamp",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ++*ran;
    if (c.far()) continue;  // the program passes far below: nothing to cut
    if (removed == 0) std::printf("  %s (%s, m=%d): nothing removed\n", c.what, mode == CutMode::kSweep ? "sweep" : "stamp",
                                  int(sizeof(H) * 8));
    CHECK_GT(removed, 0u);
  }
}

}  // namespace

TEST(ranges_corners_sweep) {
  int ran = 0;
  run_corners<uint16_t>(kSweepCorners, CutMode::kSweep, &ran);
  run_corners<uint8_t>(kSweepCorners, CutMode::kSweep, &ran);
  run_corners<uint32_t>(kSweepCorners, CutMode::kSweep, &ran);
  std::printf("ranges: %d sweep corners\n", ran);
}

TEST(ranges_corners_stamp) {
  int ran = 0;
  run_corners<uint16_t>(kStampCorners, CutMode::kStamp, &ran);
  run_corners<uint8_t>(kStampCorners, CutMode::kStamp, &ran);
  run_corners<uint32_t>(kStampCorners, CutMode::kStamp, &ran);
  std::printf("ranges: %d stamp corners\n", ran);
}

// Just past each range: refused, with the message that names the range.
TEST(ranges_just_outside_are_refused) {
  struct Spec {
    const char* text;
    bool ok;
  };
  const Spec specs[] = {
      {"flat:1000", true},          {"flat:1000.000001", false},  // diameter
      {"ball:0.001", true},         {"ball:0.000999", false},
      {"bull:6:0.000001", true},    {"bull:6:0.0000001", false},  // corner radius (0 nm)
      {"bull:6:3", true},           {"bull:6:3.000001", false},
      {"vbit:6:1", true},           {"vbit:6:0.999", false},  // angle
      {"vbit:6:179.999", true},     {"vbit:6:180", false},
      {"vbit:174.5:1", true},       {"vbit:174.6:1", false},  // a cone over 10 m tall
      {"flat:6,stick=10000", true}, {"flat:6,stick=10000.000001", false},
      {"flat:6,len=10000", true},   {"flat:6,len=10000.000001", false},
  };
  for (const Spec& s : specs) {
    Tool t;
    const ToolSpecError e = tool_spec_parse(s.text, std::strlen(s.text), &t);
    CHECK_EQ(e == ToolSpecError::kOk, s.ok);
    if (!s.ok) CHECK_EQ(e, ToolSpecError::kOutOfRange);
    if ((e == ToolSpecError::kOk) != s.ok) std::printf("  %s: %s\n", s.text, tool_spec_message(e));
  }
  const std::string msg = tool_spec_message(ToolSpecError::kOutOfRange);
  for (const char* part : {"diameter 0.001..1000 mm", "corner radius 0.000001..D/2", "angle 1..179.999 degrees", "10 m"})
    CHECK(msg.find(part) != std::string::npos);
  // The sweep's radius: 2^28 nm, and 1 nm more.
  Tool flat;
  CHECK(tool_spec_parse("flat:536.870912", 15, &flat) == ToolSpecError::kOk);
  SweepTool st;
  CHECK(ok(sweep_tool_prepare(tool_profile(flat), 1000, &st)));
  flat.diameter_nm += 2;
  CHECK_EQ(sweep_tool_prepare(tool_profile(flat), 1000, &st), Status::kBadArgument);
  // The stamp's cutter: 2047 dexels of reach, and one more.
  ToolProfile ball = tool_profile(sim_tool("ball:1000"));
  CHECK_EQ(cutter_reach_dex(ball, 500 * kMm / 2047), 2047);
  CHECK_GT(cutter_reach_dex(ball, 500 * kMm / 2048), kCutterMaxReach);
  // The grid plan: the pitch, the side, the stock's place and shape.
  GridPlan plan;
  const StockBox box = box_mm(100, 100, 10);
  CHECK(plan_grid(box_mm(20000, 20000, 10), 0, 0, 1000 * kMm, &plan) == PlanError::kOk);
  CHECK(plan_grid(box_mm(20000, 20000, 10), 0, 0, 1000 * kMm + 1, &plan) == PlanError::kBadGeometry);
  CHECK(plan_grid(box_mm(65.532, 0.002, 2), 0, 0, 1000, &plan) == PlanError::kOk);
  CHECK_EQ(plan.geo.nx, 65535);
  PlanRefusal refused;
  CHECK(plan_grid(box_mm(65.533, 0.002, 2), 0, 0, 1000, &plan, GridBudget{}, &refused) == PlanError::kTooManyDexels);
  CHECK_EQ(refused.nx, 65536);
  StockBox far = box;
  far.hi.x_nm = kStockCoordMaxNm;
  CHECK(plan_grid(far, 0, 0, 1000 * kMm, &plan) == PlanError::kOk);
  far.hi.x_nm = kStockCoordMaxNm + 1;
  CHECK(plan_grid(far, 0, 0, 1000 * kMm, &plan) == PlanError::kBadStock);
  StockBox flat_box = box;
  flat_box.hi.z_nm = flat_box.lo.z_nm;
  CHECK(plan_grid(flat_box, 0, 0, kMm, &plan) == PlanError::kBadStock);
  // The command line says which range, and exits 2.
  if (run_cli::skip()) return;
  struct Cli {
    const char* args;
    const char* message;
  };
  const std::string prog = run_cli::write_tmp("ranges.ngc", "G21 G90\nG0 X0 Y0 Z1\nG1 Z-1 F100\nM2\n");
  const Cli clis[] = {
      {" --tool vbit:6:0.5", "angle 1..179.999 degrees"},
      {" --tool flat:1000.001", "diameter 0.001..1000 mm"},
      {" --tool flat:536.871", "too large for --mode sweep (radius above 2^28 nm = 268.435 mm"},
      {" --tool flat:1000 --mode stamp --pitch 0.2", "spans more than 4095 dexels"},
      {" --pitch 100.0001", "--pitch needs a dexel spacing from 0.0001 to 100 mm"},
      {" --stock 0,0,-1,10000.000001,10,0", "--stock needs X0,Y0,Z0,X1,Y1,Z1"},
      {" --grid 65536x4", "--grid needs NXxNY with whole numbers from 4 to 65535"},
  };
  for (const Cli& c : clis) {
    const run_cli::Result r = run_cli::run(prog + " -q" + c.args, nullptr, true);
    CHECK_EQ(r.code, 2);
    CHECK(run_cli::has(r.err, c.message));
  }
  // A 30-degree V-bit of 254 mm along its own flank
  // through a G18 arc (UBSan: w * w overflowed; the normal build said 0).
  const std::string vb = run_cli::write_tmp("vb.ngc", "G21 G90 G94\nG0 X0 Y0 Z0\nG18\nG3 X0 Z0 K0.6345 I14.33 F500\nM2\n");
  const run_cli::Result r = run_cli::run(vb + " -q --tool vbit:254:30", nullptr, true);
  CHECK_EQ(r.code, 0);
}

// The sweep's own input range, past what the interpreter makes: points
// clamped to 2^46 nm (core/cut/sweep.h), so tips 2^54 V from z0 on LSBs of
// 1 nm, through ramps steep and long, every shape at the sweep's largest
// radius and its smallest. (A q16 run of such heights overflowed.)
TEST(ranges_sweep_at_the_clamp) {
  const int64_t big = int64_t{1} << 46;
  const char* tools[] = {"flat:536.87", "ball:536.87", "bull:536.87:100", "vbit:536.87:30", "vbit:0.001:1",
                         "ball:0.001"};
  for (const char* spec : tools) {
    const Tool tool = sim_tool(spec);
    std::vector<uint32_t> top(64 * 64), bottom(64 * 64);
    DexelGrid<uint32_t> g;
    CHECK(ok(grid_init(&g, GridGeometry{64, 64, -32 * 100000, -32 * 100000, 100000, -1000, 1}, top.data(), bottom.data(),
                       top.size())));
    grid_block_stock(&g, 1000);
    SweepTool st;
    CHECK(ok(sweep_tool_prepare(tool_profile(tool), g.lsb_nm, &st)));
    CutStats stats;
    const PointNm lines[][2] = {
        {{-(int64_t{1} << 22), 0, -big}, {int64_t{1} << 22, 0, big}},  // along x, 2^24:1 at most
        {{0, -(int64_t{1} << 22), big}, {0, int64_t{1} << 22, -big}},  // along y
        {{-(int64_t{1} << 30), -(int64_t{1} << 29), -big}, {int64_t{1} << 30, int64_t{1} << 29, big}},  // 3-D diagonal
        {{-(int64_t{1} << 40), 0, 0}, {int64_t{1} << 40, 0, 0}},       // level, 2^41 nm long
        {{0, 0, big}, {0, 0, -big}},                                    // plunge
        {{-(int64_t{1} << 36), -(int64_t{1} << 36), -big}, {int64_t{1} << 36, int64_t{1} << 36, big}},
    };
    SweepChain chain;
    for (const auto& l : lines) {
      sweep_line(&g, st, l[0], l[1], &stats);
      sweep_chain_line(&g, st, l[0], l[1], &stats, &chain);
    }
    sweep_chain_end(&g, st, &stats, &chain);
    CHECK_GT(stats.dexel_updates, 0u);
  }
}
