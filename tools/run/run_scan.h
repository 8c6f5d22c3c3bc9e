// The first pass of `dexmill run` (core/sim/scan.h): the program read once,
// its diagnostics printed and kept for the report, the report's program
// part, and the backplot's path when a view wants it.
#ifndef DEXMILL_TOOLS_RUN_RUN_SCAN_H
#define DEXMILL_TOOLS_RUN_RUN_SCAN_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/gcode/messages.h"
#include "core/sim/job.h"
#include "core/sim/scan.h"
#include "display/overlay/backplot.h"
#include "platform/input/gcode_file.h"
#include "platform/input/warning_fold.h"
#include "platform/report/run_report.h"
#include "platform/format/tool_table.h"
#include "tools/run/read_options.h"

namespace dexmill {
namespace cli {

// Prints diagnostics (when asked) and keeps them for the report. Warnings
// are folded (platform/input/warning_fold.h): on stderr until an error comes
// between, in the report over the whole program (its first 100 distinct
// ones, each with its count and last line); warnings() counts every one.
class RunMessages final : public GcodeMessages {
 public:
  RunMessages(const std::string& file, bool print) : file_(file), print_(print) {}
  void set_file(const char* name) override { file_ = name; }
  void error(const GcodeDiag& d) override;
  void warning(const GcodeDiag& d) override {
    // `run` stops probes on the stock (the cut, core/sim/simulation.h):
    // the interpreter's word that it cannot is not the run's.
    if (d.code == GcodeError::kWarnProbe) return;
    warning_text(d.line, d.col, gcode_diag_message(d));
  }
  // An error found outside the interpreter (a tool the table lacks).
  void error_text(uint32_t line, uint32_t col, const std::string& msg);
  // A warning found outside it (a tool guessed), counted with the rest.
  void warning_text(uint32_t line, uint32_t col, const std::string& msg);
  // Prints the warnings held.
  void finish() { fold_.flush(); }
  std::vector<ReportDiag> error_list;
  // The report's warnings, folded.
  std::vector<ReportDiag> warning_list() const;
  bool printing() const { return print_; }

 private:
  std::string file_;
  bool print_;
  WarningFold fold_;
  WarningList kept_{100};
};

// What the scan pass reads: the program's path and its name in messages,
// its subroutine path, the table (for the message of a T it lacks), and
// the run's tool choice the scan was given (its tools' sources reported).
struct ScanInput {
  std::string read_path, shown_name;
  const ReadOptions* read = nullptr;
  const ToolTableFile* table = nullptr;
  FileGuard* guard = nullptr;  // the subroutine files are registered with it as they are opened
  const ToolChoice* choice = nullptr;
};

// Runs the scan into *scan, made with job.notes = notes (the path too, when
// not null), and the report's program part: lines, units, counts, errors and
// warnings (printed), the program's messages (printed as they come), the
// tools used, the time and bounds. kExitOk, or kExitIo (printed).
int scan_pass(const ScanInput& in, ProgramScan* scan, const GcodeNotes& notes, std::vector<PathSegment>* path,
              RunMessages* msgs, RunReport* rep);

// The report's motion counts, time estimate and bounds from a summary:
// the scan's, or, for a program that probes, the cut's (where each probe
// stopped on the stock).
void motion_to_report(const MotionSummary& sum, RunReport* rep);
// The estimate by tool (the report's time_by_tool) and the largest G64 P.
void tool_times_to_report(const ProgramScan& s, RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
