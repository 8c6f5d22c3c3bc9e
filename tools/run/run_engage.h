// The engagement's outputs (core/engage/engage_meter.h): --engagement-csv
// FILE, a row a feed move:
//   line,time_s,depth_mm,width_mm,angle_deg,mrr_mm3_per_min,chip_max_mm,chip_mean_mm,force_n,power_w,feed_mm_per_min,torque_n_m,tool,removed_mm3
// time_s: the program's estimated time at the move's end; depth and width
// the largest over the move's samples, the angle its widest sample's; the
// removal rate at its largest cross-section (the cross-section times the
// feed); the chip from the feed per tooth (F over the spindle speed and
// the flutes, 2 unless the tool says); force, power and torque with the
// material's cutting coefficients (core/engage/engage_load.h), else
// empty; removed_mm3 what the record removed (exact at grid precision;
// the cut defers a move's end cap to the next record). The report's
// `engagement`: the program's and each tool's largest, with their lines.
#ifndef DEXMILL_TOOLS_RUN_RUN_ENGAGE_H
#define DEXMILL_TOOLS_RUN_RUN_ENGAGE_H

#include <map>
#include <string>
#include <vector>

#include "core/engage/engage_meter.h"
#include "core/engage/load_watch.h"
#include "core/material/material.h"
#include "platform/os/output_file.h"
#include "platform/report/load_plot.h"
#include "platform/report/run_report.h"

namespace dexmill {
namespace cli {

// The engine's sink for each measured move: the CSV rows as the cut goes,
// each tool's largest (core's engage_summary_add), the plot's series.
class EngageRecorder final : public EngageSink {
 public:
  EngageRecorder(int64_t lsb_nm, int64_t pitch_nm) : lsb_nm_(lsb_nm), pitch_nm_(pitch_nm) {}
  bool open_csv(const std::string& path);
  void keep_plot() { plot_ = true; }
  void move(const EngageMove& m) override;
  bool commit() { return !csv_ || file_.commit(); }
  const char* error() const { return file_.error(); }
  const std::map<int32_t, EngageSummary>& tools() const { return tools_; }

  // The plot's moves and marks: power where the material gave
  // coefficients, else the thickest chip.
  struct PlotMove {
    double end_s, duration_s, chip_mm, power_w, mrr_mm3_per_min, feed_mm_per_min;
    uint32_t line;
    int32_t tool;
  };
  const std::vector<PlotMove>& plot_moves() const { return moves_; }
  bool any_load() const { return any_load_; }

 private:
  OutputFile file_;
  bool csv_ = false, plot_ = false, any_load_ = false;
  int64_t lsb_nm_, pitch_nm_;
  std::map<int32_t, EngageSummary> tools_;
  EngageSummary* last_ = nullptr;  // tools_[last_tool_] (a map's elements stay put)
  int32_t last_tool_ = 0;
  std::vector<PlotMove> moves_;
};

// The report's `engagement`: the program's and each tool's largest.
void engage_to_report(const EngageSummary& s, const std::map<int32_t, EngageSummary>& tools, RunReport* rep);
// The report's `load` findings, and their lines on standard error.
void load_to_report(const LoadWatch& w, const StockComposition& c, RunReport* rep);
void load_print(const LoadWatch& w, const StockComposition& c, const std::string& file);
// "chip 0.0812 mm over aluminium's max_chip of 0.0600 mm a tooth" (without
// the value: the same text for a run of moves, folded on standard error).
std::string load_finding_text(const LoadFinding& f, const StockComposition& c, bool with_value);

// --load-plot FILE.svg|.png (tools/run/run_load_plot.cpp), into its file
// (false: *err says why).
// The same figure as SVG text, width_px x height_px (the sheet's).
std::string load_plot_svg_text(const EngageRecorder& r, const EngageSummary& s, const std::string& file, int64_t limit_mw,
                               int width_px, int height_px);
bool write_load_plot(const std::string& path, const EngageRecorder& r, const EngageSummary& s, const std::string& file,
                     int64_t limit_mw, std::string* err);

}  // namespace cli
}  // namespace dexmill

#endif
