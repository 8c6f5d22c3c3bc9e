// Golden section "tool": tool checks, profile heights (core/tool/tool.h) and
// cutter dexel sets (core/tool/cutter.h, paper §2.2.2) for every cutter shape at
// a few pitches and LSBs, plus the status messages.
#include <stdint.h>

#include "core/math/hash.h"
#include "core/status.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/golden/golden.h"
#include "tests/golden/golden_programs.h"

using namespace dexmill;

namespace golden {
namespace {

Tool make(ToolKind k, int64_t d, int64_t rc, int32_t mdeg, int64_t len) {
  Tool t;
  t.kind = k;
  t.diameter_nm = d;
  t.corner_radius_nm = rc;
  t.tip_angle_mdeg = mdeg;
  t.flute_length_nm = 0;
  t.length_nm = len;
  return t;
}

const char* kind_name(ToolKind k) {
  switch (k) {
    case ToolKind::kFlat: return "flat";
    case ToolKind::kBall: return "ball";
    case ToolKind::kBullNose: return "bull";
    case ToolKind::kVBit: return "vbit";
  }
  return "?";
}

void cutter_line(Out& out, const ToolProfile& p, int64_t pitch, int64_t lsb) {
  out.str("  cutter").kv("pitch_nm", pitch).kv("lsb_nm", lsb);
  Arena& a = arena();
  a.reset();
  const int32_t k = cutter_reach_dex(p, pitch);
  const size_t words = k <= kCutterMaxReach ? cutter_storage_words(k) : 0;
  int32_t* w = words ? a.take<int32_t>(words) : nullptr;
  CutterDexels c;
  const Status s = cutter_build(p, pitch, lsb, w, words, &c);
  if (!ok(s)) {
    out.str(" status=").str(status_message(s)).end();
    return;
  }
  Hash64 h;
  for (int32_t r = 0; r < c.side; ++r) {
    h.uint_le(static_cast<uint32_t>(c.row_lo[r]), 4);
    h.uint_le(static_cast<uint32_t>(c.row_hi[r]), 4);
  }
  const size_t n = static_cast<size_t>(c.side) * static_cast<size_t>(c.side);
  for (size_t i = 0; i < n; ++i) h.uint_le(static_cast<uint32_t>(c.bottom_lsb[i]), 4);
  for (size_t i = 0; i < n; ++i) h.uint_le(static_cast<uint32_t>(c.top_lsb[i]), 4);
  out.kv("K", c.reach_dex).kv("bottom", c.min_bottom_lsb).str("..").dec(c.max_bottom_lsb).kv("top", c.max_top_lsb);
  out.kx("set", h.value()).end();
}

}  // namespace

void golden_tool(Out& out) {
  const Tool tools[] = {
      make(ToolKind::kFlat, mm(6), 0, 0, mm(40)),
      make(ToolKind::kBall, mm(6), 0, 0, mm(40)),
      make(ToolKind::kBall, um(1001), 0, 0, mm(3)),
      make(ToolKind::kBullNose, mm(8), mm(1), 0, mm(40)),
      make(ToolKind::kBullNose, mm(10), mm(5), 0, mm(40)),  // rc = R: a ball
      make(ToolKind::kVBit, mm(6), 0, 90000, mm(40)),
      make(ToolKind::kVBit, mm(3), 0, 30000, mm(40)),
      make(ToolKind::kVBit, mm(12), 0, 179999, mm(40)),     // nearly flat cone
      make(ToolKind::kVBit, mm(6), 0, 1, mm(40)),           // angle too small: rejected
      make(ToolKind::kBall, mm(6), 0, 0, mm(2)),            // shorter than its ball: rejected
      make(ToolKind::kBullNose, mm(6), mm(4), 0, mm(40)),   // corner > R: rejected
      make(ToolKind::kFlat, mm(2000), 0, 0, mm(4000)),      // diameter > 1 m: rejected
  };
  for (const Tool& t : tools) {
    out.str("tool ").str(kind_name(t.kind)).kv("d_nm", t.diameter_nm).kv("rc_nm", t.corner_radius_nm);
    out.kv("mdeg", t.tip_angle_mdeg).str(" check=").str(status_message(tool_check(t))).end();
    if (!ok(tool_check(t))) continue;
    const ToolProfile p = tool_profile(t);
    const int64_t r = p.radius_nm;
    out.str("  profile").kv("full", profile_full_height_nm(p)).kv("cos", p.cone_cos_q30).kv("sin", p.cone_sin_q30);
    const int64_t radii[] = {0, r / 4, r / 2, 3 * r / 4, r - 1000, r - 1, r, r + 1, -r / 3};
    for (int64_t x : radii) out.str(" ").dec(profile_height_nm(p, x));
    out.end();
    cutter_line(out, p, um(500), 100000);
    cutter_line(out, p, um(130), 1000);
    cutter_line(out, p, um(170), 1);
  }
  // Set-up errors are reported, not crashed on.
  const ToolProfile ball = tool_profile(tools[1]);
  int32_t few[4];
  CutterDexels c;
  out.str("cutter_errors");
  out.str(" small=").str(status_message(cutter_build(ball, um(500), 1000, few, 4, &c)));
  out.str(" pitch0=").str(status_message(cutter_build(ball, 0, 1000, few, 4, &c)));
  out.str(" huge=").str(status_message(cutter_build(ball, 1, 1000, few, 4, &c)));
  out.str(" null=").str(status_message(cutter_build(ball, mm(1), 1000, nullptr, 0, &c))).end();
  out.str("status");
  for (int s = 0; s <= 5; ++s) out.str(" ").dec(s).str("=").str(status_message(static_cast<Status>(s)));
  out.end();
}

}  // namespace golden
