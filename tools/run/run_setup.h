// The set-up of `dexmill run`: the options into a job for the engine and
// the engine made, ready to cut (what run_job cuts and draws, and what the
// tests reach in process, so that no copy of these steps exists):
//   the demo's defaults, every file checked by the input guard, the demo's
//   program written, the program opened; the tool
//   table; the first pass (tools/run/run_scan.h: the
//   report's program part, the path, the first bad block); the stock and
//   grid (core/sim/stock_plan.h), the design, the materials, the checks the
//   options and the tools ask for; the simulation over its memory, the
//   stock carved to a blank.
#ifndef DEXMILL_TOOLS_RUN_RUN_SETUP_H
#define DEXMILL_TOOLS_RUN_RUN_SETUP_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/scan.h"
#include "core/sim/simulation.h"
#include "core/sim/stock_state.h"
#include "display/overlay/backplot.h"
#include "platform/input/file_guard.h"
#include "platform/input/gcode_file.h"
#include "platform/os/memory.h"
#include "platform/input/program_input.h"
#include "platform/report/run_report.h"
#include "platform/format/stock_io.h"
#include "platform/format/tool_table.h"
#include "tools/run/run_assess.h"
#include "tools/run/run_material.h"
#include "tools/run/run_engage.h"
#include "tools/run/run_machine.h"
#include "tools/run/run_options.h"
#include "tools/run/run_outputs.h"

namespace dexmill {
namespace cli {

struct RunSetup {
  RunMachine machine;            // --machine: the machine and what it gave
  bool print = true;             // the program's diagnostics and messages on stderr (else only kept)
  bool demo = false;
  bool refused = false;          // --strict and an input error: nothing is cut (kExitInput)
  std::string read_path, shown_name;
  // The command's input guard (run_job's caller's), else this set-up's own.
  FileGuard own_guard;
  FileGuard* guard = &own_guard;
  std::vector<std::string> old_frames;  // an earlier run's, in --frames: remove_earlier_frames
  ProgramInput input;
  OutputFormats formats;
  ToolTableFile table;
  bool have_table = false;
  std::unique_ptr<ToolChoice> choice;  // the library and offsets: --tool, --tools, comments, default
  const ToolLibrary* lib = nullptr;
  SimJob job;
  RunReport rep;
  std::unique_ptr<ProgramScan> scan;
  std::unique_ptr<MotionPlanner> planner;  // the scan's look-ahead (the blended time estimate)
  std::unique_ptr<EngageRecorder> engage;  // the engine's sink for each move's load (CSV, plot, each tool's largest)
  // A program that probes: its messages from the cut (where each probe
  // stopped on the stock), and the probe errors only the cut finds.
  std::unique_ptr<GcodeNotes> cut_notes;
  std::vector<ReportDiag> probe_errors;
  // The stock the run leaves and the chain on it (tools/run/run_job.cpp).
  StockMeta chain;
  bool have_chain = false;
  uint32_t scan_errors = 0, scan_warnings = 0;
  std::vector<PathSegment> path;
  bool want_path = false;        // the backplot: for --path-overlay, and a live view (its p key)
  std::vector<Tool> tools;       // the scan's, for the job
  GridPlan plan{};
  std::vector<TriangleNm> blank;
  std::unique_ptr<StockFileReader> stock_in;  // --stock FILE.dxstock, read up to its columns
  StockMeta stock_meta;                       // its header after the --setup turns: the job's resume
  StockMeta stock_file_meta;                  // as the file has it (the columns are read in its layout)
  RunDesign design;
  RunMaterial material;
  ZeroedBlock memory;            // the engine's (sim_required_bytes)
  Simulation* sim = nullptr;
  RunSetup() = default;
  RunSetup(const RunSetup&) = delete;
  RunSetup& operator=(const RunSetup&) = delete;
  ~RunSetup() { sim_destroy(sim); }
};

// Sets s up from the options (the demo's defaults filled into *o). kExitOk,
// or the exit code with the message printed; kExitInput with s->refused when
// --strict refuses a program with an error (the report is still the
// caller's to write).
int run_setup(RunOptions* o, RunSetup* s);

// Removes the frames of an earlier run the set-up found in --frames, once
// everything that can fail before the cut has been tried (the set-up, the
// window or framebuffer opened, the views made): a failed start leaves
// them as they were. kExitOk, or kExitIo with the message printed.
int remove_earlier_frames(const RunOptions& o, RunSetup* s);

}  // namespace cli
}  // namespace dexmill

#endif
