// The settings of `dexmill run`, parsed and checked before anything is
// read or written: a bad value is a usage error (exit 2) with a message
// that names the option and what it wants. Three parts:
//   job   what the engine is asked to do: the program, the stock, the grid,
//         the tools, the mode, how the program is read, the design and its
//         tolerances, the material, the checks and the verdict. The files
//         the job is made from are named here too (the program, --tools,
//         --stock FILE.stl, --design, --material): they are inputs, read
//         into the engine's job (tools/run/run_job.cpp). No output is.
//   out   the files written: images, frames, heightmap, STL, report.
//   view  how the run is shown: frame size, camera, colours, overlays,
//         the live window or framebuffer and its pace, the terminal.
// The options themselves are the table of tools/run/run_option_table.h.
#ifndef DEXMILL_TOOLS_RUN_RUN_OPTIONS_H
#define DEXMILL_TOOLS_RUN_RUN_OPTIONS_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/engage/engage_split.h"
#include "core/engage/engage_target.h"
#include "core/stock/stock_transform.h"
#include "core/assess/assess.h"
#include "core/cut/mill.h"
#include "core/design/builtin.h"
#include "core/canon/summary.h"
#include "core/tool/tool.h"
#include "display/raster/camera.h"
#include "platform/format/image_file.h"
#include "platform/input/program_input.h"
#include "platform/report/run_report.h"
#include "tools/run/read_options.h"

namespace dexmill {
namespace cli {

// Which safety checks, and their limits (tools/run/run_safety.h starts them).
struct SafetyChoice {
  bool rapid = false, spindle = false, below = false, shank = false, holder = false, plunge = false;
  bool has_table = false;
  int64_t table_nm = 0;
  std::vector<BoxNm> fixtures;
  bool any() const { return rapid || spindle || below || shank || holder || plunge || has_table || !fixtures.empty(); }
  void all() { rapid = spindle = below = shank = holder = plunge = true; }
};

struct JobOptions {
  JobOptions();                  // the default tool parsed from tool_text
  std::string file;              // the program; "-" is standard input; empty: the built-in demo
  // No FILE was given and standard input is not a terminal: `file` is "-"
  // for the user (choose_program), and nothing there is a usage error.
  bool stdin_implied = false;
  // `dexmill optimize`: the program's name in messages when `file` is a
  // copy of it (a spooled standard input); empty: from `file`.
  std::string shown_name;
  // The demos: the program's text, written to its path (`file`, or the
  // built-in demo's) once the input guard has checked every file the run
  // reads, writes and removes (tools/run/run_setup.cpp).
  std::string made_program;
  bool have_stock = false;
  int64_t stock_nm[6] = {};      // X0 Y0 Z0 X1 Y1 Z1, machine mm -> nm, X0 < X1 ...
  std::string stock_stl;         // --stock FILE.stl: a pre-machined blank (have_stock false)
  std::string stock_file;        // --stock FILE.dxstock: a saved stock, continued (core/stock/stock_file.h)
  int64_t probe_tip_nm = 0;      // --probe DIA: a G38 move's ball tip (0: the tool in the spindle)
  std::vector<StockSetup> setups;  // --setup T (repeatable): turned into this program's fixturing, in order
  std::vector<std::string> setup_texts;  // as given, for messages
  // `dexmill run A.nc [--setup T] B.nc ...`: the programs after the first,
  // run in order on one stock (tools/run/run_chain.h); each --setup is
  // for the program after it (setup_program: how many came before it).
  std::vector<std::string> chain;
  std::vector<int> setup_program;
  int operands_seen = 0;
  // --setups FILE (tools/run/setups_file.h): the programs, their setups
  // and, per program, the options its line gives (steps[k] for program k;
  // empty when none).
  std::string setups_file;
  struct Step {
    std::string place;  // the line's FILE:LINE, for messages
    std::vector<std::pair<std::string, std::string>> options;  // "--tools", FILE: applied over the command line's
    bool have_work_offsets = false;
    PointNm work_offsets[9] = {};  // G54..G59.3 origins, machine nm (unset ones 0)
  };
  std::vector<Step> steps;
  // This program's work offsets (a step's): the coordinate systems' origins
  // when it starts (core/sim/job.h SimJob::work_offsets).
  bool have_work_offsets = false;
  PointNm work_offsets[9] = {};
  // The machine's coordinate system in force, G92 and G43.1 offset at the
  // start (tools/run/run_machine.h).
  uint8_t start_coord_system = 0;
  PointNm start_g92{0, 0, 0};
  int64_t start_tlo_nm = 0;
  // A chain run in one `dexmill run`: what each program before this one
  // found (its report's findings), for this one's report.
  std::vector<ProgramFindings> chain_findings;
  int32_t grid_nx = 0, grid_ny = 0;  // --grid; 0: from the pitch or the default
  int64_t pitch_nm = 0;          // --pitch; 0: from --grid or 256 across
  std::string tool_text = "flat:6";
  Tool tool;                     // --tool, parsed from tool_text
  bool tool_given = false;       // --tool was given
  CutMode mode = CutMode::kSweep;
  ReadOptions read;              // --units, --default-feed, --subroutine-path, --max-blocks, --tools
  int64_t rapid_nm_per_min = MotionTimeModel().rapid_nm_per_min;  // --rapid MM/MIN, for the time estimate
  int64_t accel_nm_per_s2 = 0;   // --accel MM/S2 (0: none)
  // Each axis's velocity and acceleration from --machine, where no --rapid
  // or --accel overrides them (the blended estimate's, core/canon/motion_plan.h).
  PlanLimits axes;
  bool strict = false;           // --strict: an input error cuts nothing (else up to the bad block)
  // --max-input MIB: the most bytes of a program copied because it cannot
  // be read twice (standard input, a pipe, a FIFO, a device).
  uint64_t max_input_bytes = kDefaultMaxCopyBytes;
  // --max-memory SIZE: the most the grid and the engine that cuts it may
  // take (tools/run/run_stock.h run_grid_budget); 0: a share of the machine's.
  uint64_t max_memory_bytes = 0;
  std::string material;          // --material PRESET|FILE: the stock's composition and its process rules
  // --demo NAME: one of the paper's workpieces (core/design/builtin.h) cut
  // end to end; the design of `builtin` is used when it is set.
  std::string demo;
  // The design part to assess against (paper §2.5).
  std::string design;            // --design FILE.stl|FILE.pgm (a built-in part: its name in brackets)
  bool demo_design = false;      // the built-in demo's own part (tools/run/demo_program.h), no file
  const BuiltinDesign* builtin = nullptr;
  bool design_pgm = false;       // by the extension
  bool have_design_z = false;
  int64_t design_z_nm[2] = {};   // --design-z ZLOW,ZHIGH (PGM: black, white)
  int64_t design_offset_nm[3] = {};  // --design-offset X,Y,Z (STL)
  int64_t tolerance_nm = 50000;  // --tolerance MM (0.05)
  std::vector<ToleranceBox> tolerance_boxes;  // --tolerance-box X0,Y0,X1,Y1,TOL (repeatable)
  // Safety checks (core/safety/safety.h): --check rapid,spindle,below,
  // shank,holder,plunge|all, --table Z, --fixture (repeatable). run_job also
  // turns on what a tool describes (a flute length, a holder, nocentre).
  SafetyChoice checks;
  // The verdict: stop at the first gouge or safety finding (exit 4), or
  // run to the end and exit 4 if there was one. --stop-at any is resolved
  // by finish_run_options into the other two.
  bool stop_at_gouge = false, stop_at_collision = false, stop_at_any = false;
  bool fail_on_gouge = false, fail_on_collision = false;
  // Load limits (core/engage/load_watch.h): --check load, --spindle-power
  // W (mW here; implies the check), --fail-on-load (exit 4; implies it).
  bool check_load = false, fail_on_load = false;
  // --machine FILE (tools/run/run_machine.h) and its travel check
  // (--check travel: on with a machine), --fail-on-travel (exit 4).
  std::string machine_file;
  bool check_travel = false, fail_on_travel = false;
  bool have_rapid = false, have_accel = false;  // --rapid, --accel given (a machine's do not override them)
  int64_t spindle_power_mw = 0;
  int32_t default_spindle_rpm = 0;  // --default-spindle (0: none)
  // `dexmill optimize`: each line's feed limit kept (tools/run/run_job.h RunResult).
  bool feed_limits = false;
  // `dexmill optimize --target`: each line's feed for it (core/engage/engage_target.h).
  const EngageTarget* engage_target = nullptr;
  // And its splits of long moves (core/engage/engage_split.h; max_segments
  // 0: none), at most split_pieces pieces in all.
  EngageSplitRule split_rule;
  size_t split_pieces = 0;
  // `dexmill optimize`'s check of its output: the final tops kept in the
  // result (RunResult::tops), and no diagnostic printed.
  bool keep_tops = false, silent = false;
};

struct OutputOptions {
  std::string image;             // --image (demo: out/final.ppm)
  std::string error_image;       // --error-image FILE.ppm: the final frame in the error view
  std::string frames_dir;        // --frames
  ImageFormat frame_format = ImageFormat::kPng;  // --frame-format
  int64_t every = 0;             // --every; 0: about 100 frames over the program
  std::string heightmap, stl, report;
  int64_t stl_tolerance_nm = 0;  // --stl-tolerance MM: the STL's tops within it (0: exact, as one LSB)
  bool have_stl_tolerance = false;
  std::string save_stock;        // --save-stock FILE.dxstock: the final stock, to continue from
  std::string engagement_csv;    // --engagement-csv FILE: each feed move's load (tools/run/run_engage.h)
  std::string load_plot;         // --load-plot FILE.svg|FILE.png: load, removal rate and feed against time
  std::string sheet;             // --sheet FILE.html: the one-page verification sheet (tools/run/run_sheet.h)
  // With none of the files above: the summary on stdout (`check
  // --simulate` and `optimize` run a job for its findings, without it).
  bool print_summary = true;
};

struct ViewOptions {
  int32_t width = 640, height = 480;  // --size
  ViewPreset preset = ViewPreset::kIso;  // --view
  bool have_preset = false;
  bool have_azimuth = false, have_elevation = false;
  int64_t azimuth_mdeg = 0, elevation_mdeg = 0;
  // --color; with --material and no --color, material; --thin alone, thin.
  enum class Color : uint8_t { kPlain, kError, kMaterial, kTool, kSlope, kThin, kEngagement } color = Color::kPlain;
  bool have_color = false;
  int64_t thin_nm = kNmPerMm;    // --thin MM: --color thin highlights material thinner than this (1 mm)
  bool have_thin = false;
  // --overlay: the design translucent over the cut (shows overcut), or the
  // cut translucent over the design (shows undercut), in --image.
  enum class Overlay : uint8_t { kNone, kDesign, kWorkpiece } overlay = Overlay::kNone;
  bool path_overlay = false;     // --path-overlay: the toolpath over every frame (display/overlay/backplot.h)
  bool decorations = true;       // the axis triad and scale bar in images and frames; --no-decorations
  // Edge anti-aliasing (2x2 supersampled, display/view/supersample.h): the
  // stills and saved frames unless --no-antialias; the live views only
  // with --antialias (a panel redraws 4x the pixels). The last one given wins.
  enum class Antialias : uint8_t { kStills, kAll, kNone } antialias = Antialias::kStills;
  bool stills_antialiased() const { return antialias != Antialias::kNone; }
  bool live_antialiased() const { return antialias == Antialias::kAll; }
  bool frame_status = false;     // --frame-status: the live views' status line under every saved frame
  bool hide_tool = false;        // --hide-tool: the final image without the cutter
  // Live outputs (--window, --fbdev).
  bool window = false;
  std::string fbdev;
  bool exit_when_done = false;   // close the window after the program (fbdev always does)
  int64_t hold_ms = 0;           // --hold S: keep the last frame this long before exiting
  int64_t speed_milli = 0;       // --speed X: simulated seconds per second, x1000; 0: auto
  // The terminal: -q, no progress bar and notes; `optimize` prints no
  // process warnings (its rewrite acts on them).
  bool quiet = false;
  bool material_warnings = true;
};

struct RunOptions {
  JobOptions job;
  OutputOptions out;
  ViewOptions view;
};

// What `run` with no FILE cuts, before finish_run_options: `--demo pocket`,
// or no FILE with standard input a terminal (`stdin_terminal`), is the
// built-in demo (`file` left empty, `demo` cleared); no FILE with standard
// input a file or a pipe reads it ("-", stdin_implied), so that `dexmill
// run < prog.nc` cuts prog.nc. Returns kExitOk, or prints the usage error
// (a FILE with --demo pocket) and returns kExitUsage.
int choose_program(RunOptions* o, bool stdin_terminal);

// The checks of the options against each other, once all are in, and what
// follows from them: --stop-at any, the checks a verdict on collisions runs
// when none are named (all), the colour --thin and --material imply.
// Returns kExitOk, or prints the usage error and returns kExitUsage.
int finish_run_options(RunOptions* o);

// True when o asks for a picture or a model (--image, --error-image,
// --frames, --heightmap, --stl) or a live view: what the subcommands that
// only simulate (`check --simulate`, `optimize`) refuse.
bool run_draws(const RunOptions& o);

// True when the run prints its summary on standard output: it writes none
// of the files above, nor a report, and print_summary is on.
bool run_prints_summary(const RunOptions& o);

}  // namespace cli
}  // namespace dexmill

#endif
