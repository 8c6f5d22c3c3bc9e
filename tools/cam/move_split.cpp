// tools/cam/move_split.h: a long move's pieces as G-code lines.
#include "tools/cam/move_split.h"

#include <cstring>

#include "core/math/fixed.h"
#include "core/math/wide.h"
#include "tools/cam/feed_word.h"

namespace dexmill {
namespace cli {
namespace {

// A difference in nm as the program's units write it exactly: mm at 6
// decimals; inch at 8, whose 0.254 nm steps read back (rounded to the
// nearest nm, core/math/decimal.h) to the same nm.
std::string units_text(int64_t nm, bool inch) {
  const int decimals = inch ? 8 : 6;
  const int64_t u = inch ? div_round(nm * 500, 127) : nm;
  const int64_t scale = inch ? 100000000 : 1000000;
  const int64_t a = u < 0 ? -u : u;
  std::string frac = std::to_string(a % scale);
  frac.insert(0, static_cast<std::size_t>(decimals) - frac.size(), '0');
  while (!frac.empty() && frac.back() == '0') frac.pop_back();
  return std::string(u < 0 ? "-" : "") + std::to_string(a / scale) + (frac.empty() ? "" : "." + frac);
}

bool same_offsets(const InterpState& a, const InterpState& b) {
  return a.coord_system == b.coord_system && a.work_offset[a.coord_system] == b.work_offset[b.coord_system] &&
         a.g92 == b.g92 && a.tlo_nm == b.tlo_nm;
}

}  // namespace

bool move_splittable(const GcodeBlock& b, const char* text, std::size_t len, const InterpState& before,
                     const InterpState& after, const std::vector<CanonRecord>& records) {
  if (records.size() != 1 || records[0].kind != CanonKind::kFeed) return false;
  // Only the move's words: a G1 (or none, modal), X Y Z, F, N.
  const uint32_t allowed = (1u << gcode_word_index('X')) | (1u << gcode_word_index('Y')) |
                           (1u << gcode_word_index('Z')) | (1u << gcode_word_index('F')) | (1u << gcode_word_index('N'));
  if ((b.has & ~allowed) != 0 || b.m_count != 0 || b.block_delete) return false;
  for (int g = 0; g < kGGroupCount; ++g)
    if (b.g[g] >= 0 && !(g == kGMotion && b.g[g] == 10)) return false;
  if (std::memchr(text, '#', len) || std::memchr(text, '[', len)) return false;  // parameters: kept whole
  for (const InterpState* s : {&before, &after})
    if (s->incremental || s->diameter_x || s->inverse_time || s->per_rev || s->comp.side != 0 ||
        !(s->stray == PointNm{0, 0, 0}) ||
        s->rotation_deg_e9[s->coord_system] != 0 || s->motion != 10)
      return false;
  return same_offsets(before, after);
}

MoveSplit move_split(const CanonRecord& r, const EngageSegment* seg, int32_t count, bool inch, const char* eol) {
  MoveSplit out;
  PointNm at = r.start;
  for (int32_t k = 0; k + 1 < count; ++k) {
    const PointNm& p = seg[k].end_at;  // on the move exactly (engage_split_snap)
    const FeedNumber f = feed_number(seg[k].feed_nm_per_min, inch, inch ? 2 : 0);
    std::string line = k == 0 ? "G91 G1" : "G1";
    if (p.x_nm != at.x_nm) line += " X" + units_text(p.x_nm - at.x_nm, inch);
    if (p.y_nm != at.y_nm) line += " Y" + units_text(p.y_nm - at.y_nm, inch);
    if (p.z_nm != at.z_nm) line += " Z" + units_text(p.z_nm - at.z_nm, inch);
    line += " F" + f.text;
    out.text += line + eol;
    CanonRecord piece = r;
    piece.start = at;
    piece.end = p;
    piece.feed_nm_per_min = f.nm_per_min;
    out.pieces.push_back(piece);
    out.last_inserted_nm_per_min = f.nm_per_min;
    at = p;
  }
  out.text += std::string("G90") + eol;
  out.last_feed_nm_per_min = seg[count - 1].feed_nm_per_min;
  CanonRecord last = r;
  last.start = at;
  out.pieces.push_back(last);
  return out;
}

}  // namespace cli
}  // namespace dexmill
