// tools/run/run_engage.h: the engagement's rows, plot, maxima and load findings.
#include "tools/run/run_engage.h"

#include <cstdio>
#include <string>

#include "core/math/fixed.h"
#include "platform/input/warning_fold.h"
#include "platform/report/report_json.h"

namespace dexmill {
namespace cli {
namespace {

double deg(uint32_t bam) { return static_cast<double>(bam) * (360.0 / 4294967296.0); }

// v / 10^decimals with that many decimals, then a comma, at row[*n]
// (a row is under 320 bytes: fourteen fields of at most 22): the rows are
// written with integers only (printf's %f cost more than the measuring).
void put_fixed(char* row, size_t* n, int64_t v, int decimals) {
  char d[24];
  int k = 0;
  uint64_t u = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  do {
    d[k++] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u > 0 || k <= decimals);
  if (v < 0) row[(*n)++] = '-';
  while (k > 0) {
    if (k == decimals) row[(*n)++] = '.';
    row[(*n)++] = d[--k];
  }
  row[(*n)++] = ',';
}

// The record's removed volume in mm^3 x 1000 (LSB x pitch^2, nm^3 / 10^15).
int64_t removed_um3k(const EngageMove& m, int64_t lsb_nm, int64_t pitch_nm) {
  return muldiv_round(static_cast<int64_t>(m.removed_lsb) * lsb_nm, pitch_nm * pitch_nm, 1000000000000000LL);
}

}  // namespace

bool EngageRecorder::open_csv(const std::string& path) {
  if (!file_.open(path.c_str())) return false;
  csv_ = true;
  file_.printf("line,time_s,depth_mm,width_mm,angle_deg,mrr_mm3_per_min,chip_max_mm,chip_mean_mm,force_n,power_w,"
               "feed_mm_per_min,torque_n_m,tool,removed_mm3\n");
  return true;
}

void EngageRecorder::move(const EngageMove& m) {
  if (!last_ || m.tool != last_tool_) {  // one map look-up a tool change, not a move
    last_ = &tools_[m.tool];
    last_tool_ = m.tool;
  }
  engage_summary_add(last_, m);
  any_load_ = any_load_ || m.has_load;
  if (plot_)
    moves_.push_back(PlotMove{static_cast<double>(m.end_us) * 1e-6, static_cast<double>(m.time_us) * 1e-6,
                              static_cast<double>(m.chip.max_nm) * 1e-6, static_cast<double>(m.power_mw) * 1e-3,
                              static_cast<double>(m.mrr_um3_per_min) * 1e-9, static_cast<double>(m.feed_nm_per_min) * 1e-6,
                              m.line, m.tool});
  if (!csv_) return;
  char row[320];
  size_t n = static_cast<size_t>(std::snprintf(row, sizeof row, "%u,", m.line));
  put_fixed(row, &n, div_round(m.end_us, 1000), 3);              // s
  put_fixed(row, &n, div_round(m.ap_max_nm, 100), 4);            // mm
  put_fixed(row, &n, div_round(m.ae_max_nm, 100), 4);
  put_fixed(row, &n, div_round(static_cast<int64_t>(m.worst.angle_bam()) * 36000, int64_t{1} << 32), 2);  // degrees
  put_fixed(row, &n, div_round(m.mrr_um3_per_min, 100000000), 1);  // mm^3/min
  put_fixed(row, &n, div_round(m.chip.max_nm, 10), 5);
  put_fixed(row, &n, div_round(m.chip.mean_nm, 10), 5);
  if (m.has_load) {
    put_fixed(row, &n, div_round(m.force_mn, 100), 1);           // N
    put_fixed(row, &n, div_round(m.power_mw, 100), 1);           // W
  } else {
    row[n++] = ',';
    row[n++] = ',';
  }
  put_fixed(row, &n, div_round(m.feed_nm_per_min, 100000), 1);
  if (m.has_load) put_fixed(row, &n, m.torque_mn_m, 3);          // N m
  else row[n++] = ',';
  n += static_cast<size_t>(std::snprintf(row + n, sizeof row - n, "%d,", static_cast<int>(m.tool)));
  put_fixed(row, &n, removed_um3k(m, lsb_nm_, pitch_nm_), 3);
  row[n - 1] = '\n';
  file_.write(row, n);
}

namespace {

ReportEngageSet engage_set(const EngageSummary& s) {
  ReportEngageSet e;
  e.moves = s.moves;
  e.engaged = s.engaged;
  e.no_spindle_speed = s.no_speed;
  auto add = [&e](const char* name, const char* unit, const std::string& v, uint32_t line) {
    e.maxima.push_back(ReportEngageMax{name, unit, v, line});
  };
  char b[48];
  std::snprintf(b, sizeof b, "%.2f", deg(s.angle.worst.angle_bam()));
  add("max_angle", "deg", b, s.angle.line);
  add("max_width", "mm", nm_to_mm_text(s.ae.ae_max_nm, 4), s.ae.line);
  add("max_depth", "mm", nm_to_mm_text(s.ap.ap_max_nm, 4), s.ap.line);
  add("max_mrr", "mm3_per_min", nm_to_mm_text(div_round(s.rate.mrr_um3_per_min, 1000), 1), s.rate.line);
  add("max_chip", "mm", nm_to_mm_text(s.chip.chip.max_nm, 5), s.chip.line);
  if (s.force.has_load) add("max_force", "n", nm_to_mm_text(s.force.force_mn * 1000, 1), s.force.line);
  if (s.power.has_load) {
    add("max_power", "w", nm_to_mm_text(s.power.power_mw * 1000, 1), s.power.line);
    add("max_power_torque", "n_m", nm_to_mm_text(s.power.torque_mn_m * 1000, 3), s.power.line);
  }
  return e;
}

}  // namespace

void engage_to_report(const EngageSummary& s, const std::map<int32_t, EngageSummary>& tools, RunReport* rep) {
  rep->have_engagement = true;
  rep->engagement.program = engage_set(s);
  rep->engagement.tools.clear();
  for (const auto& t : tools) rep->engagement.tools.emplace_back(t.first, engage_set(t.second));
}

std::string load_finding_text(const LoadFinding& f, const StockComposition& c, bool with_value) {
  char b[200], v[48] = "";
  if (f.rule == LoadRule::kChip) {
    const char* name = f.material < c.material_count ? c.materials[f.material].name : "the stock";
    if (with_value) std::snprintf(v, sizeof v, " %.4f mm", static_cast<double>(f.value) * 1e-6);
    std::snprintf(b, sizeof b, "chip%s over %s's max_chip of %.4f mm a tooth", v, name, static_cast<double>(f.limit) * 1e-6);
  } else {
    if (with_value) std::snprintf(v, sizeof v, " %.0f W", static_cast<double>(f.value) * 1e-3);
    std::snprintf(b, sizeof b, "power%s over the spindle's %.0f W", v, static_cast<double>(f.limit) * 1e-3);
  }
  return b;
}

void load_to_report(const LoadWatch& w, const StockComposition& c, RunReport* rep) {
  rep->have_load = true;
  rep->load.spindle_power_mw = w.spindle_power_mw;
  rep->load.total = w.total;
  rep->load.kept.clear();
  for (int32_t k = 0; k < w.nkept; ++k)
    rep->load.kept.push_back(ReportLoad::Finding{w.kept[k].line, load_rule_name(w.kept[k].rule),
                                                 load_finding_text(w.kept[k], c, true)});
}

void load_print(const LoadWatch& w, const StockComposition& c, const std::string& file) {
  {
    WarningFold fold;  // a pass over its limit is one line with its count, not one a move
    for (int32_t k = 0; k < w.nkept; ++k) fold.add(file, w.kept[k].line, 1, load_finding_text(w.kept[k], c, false));
  }
  if (w.total > static_cast<uint64_t>(w.nkept))
    std::fprintf(stderr, "%s: warning: %llu more load findings not listed\n", file.c_str(),
                 static_cast<unsigned long long>(w.total - static_cast<uint64_t>(w.nkept)));
}

}  // namespace cli
}  // namespace dexmill
