// The result of one run (`dexmill run`, the jobs of `check --simulate`,
// `optimize` and `zig`): what the run glue fills (tools/run/) and the
// writers print, the JSON report (platform/report/report_json.h, whose
// comment gives each key) and the summary on standard output
// (platform/report/report_summary.h). Plain values; lengths in nm, volumes in
// LSB x dexels, times in microseconds, as the engine counts them: the
// writers turn them into text.
#ifndef DEXMILL_PLATFORM_REPORT_RUN_REPORT_H
#define DEXMILL_PLATFORM_REPORT_RUN_REPORT_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/assess/assess.h"
#include "core/safety/safety.h"
#include "core/point.h"

namespace dexmill {

struct ReportDiag {
  uint32_t line = 0, column = 0;
  std::string message;
  // A warning that came more than once (platform/input/warning_fold.h): how
  // often, and the line it last came on; line and column are the first's.
  uint64_t count = 1;
  uint32_t last_line = 0;
};

struct ReportToolUse {
  int32_t number;      // -1: the tool in the spindle before any M6
  std::string spec;
  std::string source;  // "option", "table", "comment", "default" (empty: not known)
  uint32_t line = 0;   // source "comment": the comment's line, and its form (core/tool/tool_comment.h)
  std::string form;
  // For the sheet (report key `tool_use`): the stick-out (Tool::length_nm)
  // and the lines it cut on, the M6 that first loaded it (its first cut
  // for the tool before any M6) to its last feed or arc move (0: none).
  int64_t stick_out_nm = 0;
  uint32_t first_line = 0, last_line = 0;
};

// An output of the run beside the report: a file and its bytes, or the
// frame folder and its frames (bytes -1).
struct ReportOutput {
  std::string option;  // "--image", "--frames", ...
  std::string path;    // as given
  int64_t bytes = -1;
  uint32_t files = 0;
};

// A gouge charged to the line that made it.
struct ReportGouge {
  uint32_t line = 0;
  PointNm at{0, 0, 0};     // the deepest column's x, y and its design z
  int64_t depth_nm = 0;
  PointNm tool{0, 0, 0};   // the tool tip at the end of that line's move
  uint64_t columns = 0;    // columns it gouged first
};

// The assessment against a design part (report key `assessment`).
struct ReportAssessment {
  std::string file, kind;      // the design file, "stl" or "pgm"
  uint64_t triangles = 0;      // STL: facets read
  int64_t tolerance_nm = 0;
  uint64_t tolerance_boxes = 0;
  AssessResult result;
  PointNm max_gouge_at{0, 0, 0}, max_leftover_at{0, 0, 0};  // machine x, y of those columns
  std::vector<ReportGouge> gouges;  // the first kept (core/assess/gouge_watch.h)
  uint64_t gouges_total = 0;        // all of them
};

// A material of the stock (--material): what the cut took of it.
struct ReportMaterial {
  std::string name;
  std::string removed_mm3;  // exact text
  double mass_g = 0;
  double cut_time_s = 0;
  uint64_t violations = 0;
};
struct ReportViolation {
  std::string rule;  // "feed", "spindle", "coolant"
  uint32_t line = 0;
  std::string material, message;
};

// A finding of a program of the chain: "error", "warning", "gouge",
// "collision" (a safety check's kind in message) or "violation" (a
// material's process rule), at its line.
struct ReportFinding {
  std::string kind;
  uint32_t line = 0;
  std::string message;
};
constexpr size_t kChainFindingsKept = 100;
// A program's findings: the first kChainFindingsKept, and the count of all.
struct ProgramFindings {
  std::vector<ReportFinding> kept;
  uint64_t total = 0;
};

// What the engagement measured (--engagement-csv, --load-plot, --check
// load): the largest of each quantity, with the line of the first move
// that reached it, for the program and for each tool.
struct ReportEngageMax {
  std::string name;   // "max_angle", "max_power", ...
  std::string unit;   // its value's key: "deg", "w", ...
  std::string value;  // as JSON writes it (fixed decimals)
  uint32_t line = 0;
};
struct ReportEngageSet {
  uint64_t moves = 0, engaged = 0;  // feed moves measured, and those that met material
  uint64_t no_spindle_speed = 0;    // engaged with no spindle speed: no chip, force or power
  std::vector<ReportEngageMax> maxima;
};
struct ReportEngagement {
  ReportEngageSet program;
  std::vector<std::pair<int32_t, ReportEngageSet>> tools;  // by tool number
};
struct ReportMachine {  // --machine: the machine, what it gave, and --check travel's findings
  std::string file, kind;  // "linuxcnc", "grbl"
  bool limited[3] = {false, false, false};
  std::string min_mm[3], max_mm[3];  // as JSON writes them
  std::vector<std::string> said;     // the defaults it gave, and the options that won
  bool have_travel = false;
  uint64_t travel_total = 0;
  struct Finding {
    uint32_t line;
    std::string axis, side, by_mm, message;
  };
  std::vector<Finding> findings;  // the first 100
};
struct ReportLoad {  // --check load's findings
  int64_t spindle_power_mw = 0;  // 0: no power limit
  uint64_t total = 0;
  struct Finding {
    uint32_t line;
    std::string rule, message;
  };
  std::vector<Finding> kept;  // the first 100
};

// The estimate's share of one tool (the tool in the spindle; -1 before
// any M6): report key `time_by_tool`.
struct ReportToolTime {
  int32_t tool = -1;
  int64_t estimated_us = 0, feed_us = 0, rapid_us = 0;
  uint64_t moves = 0;
};

struct RunReport {
  std::string file;
  uint32_t lines = 0;
  const char* units = "mm";  // "mm", "inch" or "mixed"
  uint64_t rapid = 0, feed = 0, arc = 0, dwell = 0, tool_change = 0;
  std::vector<ReportDiag> errors, warnings;
  uint64_t warnings_total = 0;
  struct Message {
    uint32_t line;
    std::string kind, text;
  };
  std::vector<Message> messages;
  bool have_stock = false;
  PointNm stock_lo{0, 0, 0}, stock_hi{0, 0, 0};
  std::string stock_source;
  int32_t nx = 0, ny = 0;
  int64_t pitch_nm = 0, lsb_nm = 0;
  int height_bits = 16;
  std::string mode;
  std::string default_tool, tool_table;
  std::string tool_table_units;  // "mm" or "inch" (tools/run/run_tool_table.h); empty: no table file
  std::vector<ReportToolUse> tools_used;
  uint64_t removed_lsb_dexels = 0;  // sum over dexels of height removed, LSB
  // The chain of programs the stock has been through (--stock FILE.dxstock,
  // --save-stock), this run's last; totals over all of them.
  struct ChainProgram {
    std::string file;
    uint64_t removed_lsb_dexels = 0;
    int64_t estimated_us = 0;
    uint64_t moves = 0;
    std::string setup;  // the setup before it, as --setup spells it ("none": as the stock was)
    // What the run of this program found, at its lines (a chain run in one
    // `dexmill run`; a program of an earlier run keeps none: have_findings false).
    bool have_findings = false;
    std::vector<ReportFinding> findings;  // the first kChainFindingsKept
    uint64_t findings_total = 0;
  };
  bool have_chain = false;
  std::vector<ChainProgram> chain;
  uint64_t chain_removed_lsb_dexels = 0;
  int64_t chain_us = 0;
  uint64_t chain_moves = 0;
  int64_t estimated_us = 0, feed_us = 0, rapid_us = 0, dwell_us = 0;
  int64_t rapid_nm_per_min = 0;
  int64_t accel_nm_per_s2 = 0;  // --accel; 0: none
  // The three estimates (core/canon/summary.h): no acceleration, every move
  // from rest to rest, and blended within the path tolerance; the
  // tolerance in force where the program gives none (-1: none).
  int64_t no_accel_us = 0, stop_us = 0, blended_us = 0;
  bool blended = false;  // the planner ran (an acceleration known): blended_us is its figure
  int64_t path_tolerance_nm = -1;  // the largest G64 P of a move (-1: none)
  std::vector<ReportToolTime> time_by_tool;
  bool have_bounds = false;
  PointNm bounds_lo{0, 0, 0}, bounds_hi{0, 0, 0};
  uint64_t instances = 0, dexel_updates = 0;
  std::string stopped_reason;  // empty: ran to the end
  uint32_t stopped_line = 0;
  bool have_assessment = false;
  ReportAssessment assessment;
  // The safety checks (core/safety/safety.h) when any ran: their events as
  // kept, the count of all, and what rapids removed.
  bool have_collisions = false;
  std::vector<SafetyEvent> collisions;
  uint64_t collisions_total = 0;
  uint64_t rapid_removed_lsb = 0;
  // The stock's materials and the process rules (--material), when given.
  bool have_materials = false;
  std::string material_source;
  std::vector<ReportMaterial> materials;
  std::vector<ReportViolation> material_violations;  // as kept
  uint64_t material_violations_total = 0;
  bool have_engagement = false;
  ReportEngagement engagement;
  bool have_load = false;
  ReportLoad load;
  bool have_machine = false;
  ReportMachine machine;
  std::vector<std::pair<std::string, double>> timing;  // stage name, seconds
  // The run that wrote the report and what else it wrote (platform/os/output_set.h:
  // the report is published last).
  std::string run_started;       // UTC, ISO 8601 to the millisecond
  long run_pid = 0;
  std::vector<ReportOutput> outputs;
};

}  // namespace dexmill

#endif
