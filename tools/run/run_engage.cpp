// tools/run/run_engage.h: the engagement's rows and the report's maxima.
#include "tools/run/run_engage.h"

#include "core/math/fixed.h"

#include <cstdio>
#include <string>

namespace dexmill {
namespace cli {
namespace {

double mm(int64_t nm) { return static_cast<double>(nm) * 1e-6; }
double deg(uint32_t bam) { return static_cast<double>(bam) * (360.0 / 4294967296.0); }

// v / 10^decimals as text with that many decimals, then a comma: the rows
// are written with integers only (printf's %f cost more than the
// measuring).
// v / 10^decimals with that many decimals, then a comma, at row[*n]
// (a row is under 256 bytes: eleven fields of at most 22): the rows are
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
int64_t scaled(double v, double scale) { return static_cast<int64_t>(v * scale + (v < 0 ? -0.5 : 0.5)); }

}  // namespace

double engage_mrr_mm3_per_min(const EngageMove& m, int64_t lsb_nm, int64_t pitch_nm) {
  if (m.time_us <= 0) return 0;
  const double mm3 = static_cast<double>(m.removed_lsb) * mm(lsb_nm) * mm(pitch_nm) * mm(pitch_nm);
  return mm3 * 60e6 / static_cast<double>(m.time_us);
}

bool EngageCsv::open(const std::string& path) {
  if (!file_.open(path.c_str())) return false;
  file_.printf("line,time_s,depth_mm,width_mm,angle_deg,mrr_mm3_per_min,chip_max_mm,chip_mean_mm,force_n,power_w,"
               "feed_mm_per_min\n");
  return true;
}

void EngageCsv::move(const EngageMove& m) {
  const EngageChip& chip = m.chip;
  char row[256];
  size_t n = static_cast<size_t>(std::snprintf(row, sizeof row, "%u,", m.line));
  put_fixed(row, &n, div_round(m.end_us, 1000), 3);              // s
  put_fixed(row, &n, div_round(m.ap_max_nm, 100), 4);            // mm
  put_fixed(row, &n, div_round(m.ae_max_nm, 100), 4);
  put_fixed(row, &n, scaled(deg(m.worst.angle_bam()), 100), 2);  // degrees
  put_fixed(row, &n, scaled(engage_mrr_mm3_per_min(m, lsb_nm_, pitch_nm_), 10), 1);
  put_fixed(row, &n, div_round(chip.max_nm, 10), 5);
  put_fixed(row, &n, div_round(chip.mean_nm, 10), 5);
  row[n++] = ',';  // force, power: with the material's cutting coefficients
  row[n++] = ',';
  put_fixed(row, &n, div_round(m.feed_nm_per_min, 100000), 1);
  row[n - 1] = '\n';
  file_.write(row, n);
}

void engage_to_report(const EngageSummary& s, int64_t lsb_nm, int64_t pitch_nm, RunReport* rep) {
  ReportEngagement& e = rep->engagement;
  rep->have_engagement = true;
  e.moves = s.moves;
  e.engaged = s.engaged;
  e.angle_deg = deg(s.angle.worst.angle_bam());
  e.angle_line = s.angle.line;
  e.width_nm = s.ae.ae_max_nm;
  e.width_line = s.ae.line;
  e.depth_nm = s.ap.ap_max_nm;
  e.depth_line = s.ap.line;
  e.mrr_mm3_per_min = engage_mrr_mm3_per_min(s.rate, lsb_nm, pitch_nm);
  e.mrr_line = s.rate.line;
  e.chip_nm = s.chip.chip.max_nm;
  e.chip_line = s.chip.line;
}

}  // namespace cli
}  // namespace dexmill
