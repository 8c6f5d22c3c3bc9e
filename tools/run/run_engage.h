// --engagement-csv FILE: each feed move's load as the engine measured it
// (core/engage/engage_meter.h), a row a move:
//   line,time_s,depth_mm,width_mm,angle_deg,mrr_mm3_per_min,chip_max_mm,chip_mean_mm,force_n,power_w,feed_mm_per_min
// time_s: the program's estimated time at the move's end; depth, width and
// angle at the move's worst sample (the widest arc); the removal rate from
// the move's exact removed volume over its time; the chip from the feed
// per tooth (F over the spindle speed and the flutes, 2 unless the tool
// says: core/engage/engage_meter.h); force and power empty until the material gives its cutting
// coefficients. Written beside the run's other files (committed with them).
#ifndef DEXMILL_TOOLS_RUN_RUN_ENGAGE_H
#define DEXMILL_TOOLS_RUN_RUN_ENGAGE_H

#include <string>

#include "core/engage/engage_meter.h"
#include "platform/os/output_file.h"
#include "platform/report/run_report.h"

namespace dexmill {
namespace cli {

class EngageCsv final : public EngageSink {
 public:
  EngageCsv(int64_t lsb_nm, int64_t pitch_nm) : lsb_nm_(lsb_nm), pitch_nm_(pitch_nm) {}
  bool open(const std::string& path);
  void move(const EngageMove& m) override;
  bool commit() { return file_.commit(); }
  const char* error() const { return file_.error(); }

 private:
  OutputFile file_;
  int64_t lsb_nm_, pitch_nm_;
};

// A move's removal rate, mm^3/min (0 for a move of no time).
double engage_mrr_mm3_per_min(const EngageMove& m, int64_t lsb_nm, int64_t pitch_nm);

// The report's `engagement`: the program's largest and their lines.
void engage_to_report(const EngageSummary& s, int64_t lsb_nm, int64_t pitch_nm, RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
