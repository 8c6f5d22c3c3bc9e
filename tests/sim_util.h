// Engine tests without the binary: the simulation (core/sim/simulation.h)
// driven in this process, as every front end drives it.
//
// Engine: a simulation over its memory, for a job the test builds itself,
// with text fed in pieces and budgets of any size.
//
// Run: a job set up from options by `dexmill run`'s own set-up
// (tools/run/run_setup.h: its defaults, the first pass's tools, stock, pitch and
// first bad block, the inputs read by the CLI's readers), then the program
// cut to its end. What it found is read
// from the simulation (safety(), gouges(), process(), provenance()), and the
// report's figures of an assessment are the report's own text.
#ifndef DEXMILL_TESTS_SIM_UTIL_H
#define DEXMILL_TESTS_SIM_UTIL_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/scan.h"
#include "core/sim/simulation.h"
#include "platform/format/tool_table.h"
#include "tools/run/run_options.h"
#include "tools/run/run_setup.h"

namespace sim_test {

using dexmill::SimJob;
using dexmill::SimState;
using dexmill::Simulation;

// A length written in mm ("-0.25"), exactly in nm, as the CLI reads it.
int64_t nm(const char* mm);
// "X0,Y0,Z0,X1,Y1,Z1" in mm.
dexmill::StockBox stock_box(const char* mm);
// A tool from its spec ("ball:6,len=20").
dexmill::Tool tool(const char* spec);
// A file of tests/run.
std::string run_file(const char* name);
// 70 rapids on lines of their own, each through fresh stock of a
// 0,0,-30,40,40,0 block: more safety findings than a watch keeps.
std::string seventy_rapids();

// A job on a box stock X0..X1 x Y0..Y1 x Z0..0 at `pitch`, with one tool,
// its program fed in pieces.
SimJob box_job(int64_t x0, int64_t y0, int64_t z0, int64_t x1, int64_t y1, int64_t pitch_nm, const char* tool);

// A simulation with its memory.
struct Engine {
  std::vector<uint64_t> mem;
  Simulation* sim = nullptr;
  explicit Engine(const SimJob& j);
  ~Engine() { dexmill::sim_destroy(sim); }
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  // Feeds text in pieces of `piece` bytes, stepping with `b` between; the
  // final state.
  SimState run(const std::string& text, size_t piece, const dexmill::SimBudget& b = dexmill::SimBudget());
  // Reads lines from `in`, stepping with `b`; with `sync_each_step` the cut
  // so far is shown after every step (as a frame drawn there does). Then
  // the end of the cut (finish). The final state.
  SimState run(dexmill::LineInput* in, const dexmill::SimBudget& b, bool sync_each_step);
  uint64_t grid_hash() const { return dexmill::grid_hash(sim->grid()); }
};

// Reads lines from `in` into sim, stepping with `b` (and showing the cut
// after every step with `sync_each_step`), then finishes; the final state.
SimState run_lines(Simulation* sim, dexmill::LineInput* in, const dexmill::SimBudget& b, bool sync_each_step);

// The same safety findings, to the last field, and the same counts.
bool same_events(const dexmill::SafetyWatch& a, const dexmill::SafetyWatch& b);

class Run {
 public:
  Run();
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  // -- the options (each as `dexmill run`'s of the same name; the rest in o)
  Run& stock(const char* mm);             // --stock X0,Y0,Z0,X1,Y1,Z1
  Run& stock_stl(const std::string& path);  // --stock FILE.stl: a pre-machined blank
  Run& pitch(const char* mm);             // --pitch
  Run& grid(int32_t nx, int32_t ny);      // --grid NXxNY
  Run& tool(const char* spec);            // --tool
  Run& tools(const std::string& path);    // --tools FILE
  Run& inch();                            // --units inch
  Run& material(const std::string& what);  // --material PRESET|FILE
  Run& design(const std::string& what);   // --design FILE.stl|FILE.pgm|PART
  Run& design_z(const char* low_mm, const char* high_mm);  // --design-z
  Run& tolerance_box(const char* x0, const char* y0, const char* x1, const char* y1, const char* tol);
  Run& check_all();                       // --check all
  Run& table(const char* z_mm);           // --table Z
  Run& fixture(const char* mm);           // --fixture X0,Y0,Z0,X1,Y1,Z1
  Run& provenance();                      // --color tool: which tool cut each column
  // The options, as `dexmill run` parses them into (the rest: checks, stops,
  // time model; the tools' own checks are added as the CLI adds them).
  dexmill::cli::RunOptions o;
  // The simulation's hooks, when the test watches the records (or null).
  dexmill::SimObserver* observer = nullptr;
  // Off: the shank and holder's reference look (Simulation::set_body_fast).
  bool body_fast = true;

  // -- the run: the program cut to its end, stepping with `b` (and showing
  // the cut after every step with `sync_each_step`); false when the job
  // could not be set up (CHECKed).
  bool program(const std::string& path, const dexmill::SimBudget& b = dexmill::SimBudget(), bool sync_each_step = false);
  // The same for text, written to the temporary folder as sim-NAME.
  bool text(const char* name, const std::string& text, const dexmill::SimBudget& b = dexmill::SimBudget(),
            bool sync_each_step = false);

  // -- what it gives
  Simulation& sim() { return *setup_->sim; }
  const SimJob& job() const { return setup_->job; }
  const dexmill::ProgramScan& scan() const { return *setup_->scan; }
  const dexmill::GridPlan& plan() const { return setup_->job.plan; }
  uint32_t scan_errors() const { return setup_->scan_errors; }
  uint32_t scan_warnings() const { return setup_->scan_warnings; }
  uint64_t grid_hash() const { return dexmill::grid_hash(setup_->sim->grid()); }
  // The material removed, as the report writes it ("1090.985").
  std::string removed_mm3();
  // Kept safety events of one kind.
  std::vector<dexmill::SafetyEvent> events(dexmill::SafetyKind k);
  // A safety event's message, as the warning and the report give it.
  std::string message(const dexmill::SafetyEvent& e);
  // Kept violations of one rule, and one's message.
  std::vector<dexmill::ProcessViolation> violations(dexmill::ProcessRule r);
  std::string message(const dexmill::ProcessViolation& v);
  // The report's assessment object against the design (its text, from its
  // key to the line before the timing).
  std::string assessment();

 private:
  std::unique_ptr<dexmill::cli::RunSetup> setup_;
};

}  // namespace sim_test

#endif
