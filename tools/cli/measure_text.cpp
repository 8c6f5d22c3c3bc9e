// One point's measurement in words (see measure_text.h).
#include "tools/cli/measure_text.h"

#include "core/design/design.h"
#include "core/measure/measure_at.h"
#include "platform/report/report_json.h"

namespace dexmill {
namespace cli {
namespace {

std::string mm(int64_t nm, int decimals = 4) { return nm_to_mm_text(nm, decimals); }

// "design Z-1.0000, cut - design -1.0000 mm (within 0.0004 mm)" at the
// column of r, or that the design misses it.
std::string design_text(const DexelGrid<height_t>& g, const int32_t* design, const MeasureAt& r) {
  const int32_t d = design[g.index(r.i, r.j)];
  if (d == kNoDesign) return "no design there";
  const int64_t z = g.z0_nm + static_cast<int64_t>(d) * g.lsb_nm;
  std::string o = "design Z" + mm(z);
  // The design's column is rounded to an LSB (core/design/design.cpp), the
  // cut's within one: the difference within two.
  if (r.material)
    o += ", cut - design " + std::string(r.top_nm >= z ? "+" : "") + mm(r.top_nm - z) + " mm (within " +
         mm(2 * g.lsb_nm) + " mm)";
  else
    o += ", cut through";
  return o;
}

}  // namespace

bool measure_at_text(const MeasureSource& s, int64_t x, int64_t y, std::string* out, MeasureAt* got) {
  const MeasureAt r = measure_at(*s.grid, s.lines, s.programs, x, y);
  if (!r.on_grid) return false;
  if (got) *got = r;
  std::string o = "X" + mm(x, 3) + " Y" + mm(y, 3) + ": ";
  if (r.material)
    o += "top Z" + mm(r.top_nm) + ", bottom Z" + mm(r.bottom_nm) + " mm";
  else
    o += "no material (cut through)";
  o += " (the column at X" + mm(r.column_x_nm, 3) + " Y" + mm(r.column_y_nm, 3) + ", " + mm(r.distance_nm, 3) +
       " mm away; heights within " + mm(r.height_error_nm) + " mm)";
  if (!s.lines) {
    o += std::string("; ") + s.no_lines;
  } else if (r.line == 0) {
    o += "; uncut";
  } else {
    o += "; last cut by line " + std::to_string(r.line);
    if (s.programs && s.program_list && r.program < s.nprograms) o += std::string(" of ") + s.program_list[r.program].name;
  }
  if (s.design_top_lsb) o += "; " + design_text(*s.grid, s.design_top_lsb, r);
  *out = o;
  return true;
}

bool measure_dexel_text(const MeasureSource& s, int32_t i, int32_t j, std::string* out, MeasureAt* got) {
  const DexelGrid<height_t>& g = *s.grid;
  if (!g.contains(i, j)) return false;
  return measure_at_text(s, g.x0_nm + static_cast<int64_t>(i) * g.pitch_nm, g.y0_nm + static_cast<int64_t>(j) * g.pitch_nm,
                         out, got);
}

}  // namespace cli
}  // namespace dexmill
