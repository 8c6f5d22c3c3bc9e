// The options of `dexmill run` (../shared/CLI.md), parsed and checked before
// anything is read or written: a bad value is a usage error (exit 2) with a
// message that names the option and what it wants.
#ifndef DEXMILL_TOOLS_RUN_OPTIONS_H
#define DEXMILL_TOOLS_RUN_OPTIONS_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/assess/assess.h"
#include "core/cut/mill.h"
#include "core/motion/summary.h"
#include "core/design/builtin.h"
#include "core/tool/tool.h"
#include "tools/read_options.h"
#include "display/camera.h"
#include "platform/image_file.h"

namespace dexmill {
namespace cli {

// Which safety checks, and their limits (tools/run_safety.h starts them).
struct SafetyChoice {
  bool rapid = false, spindle = false, below = false, shank = false, holder = false, plunge = false;
  bool has_table = false;
  int64_t table_nm = 0;
  std::vector<BoxNm> fixtures;
  bool any() const { return rapid || spindle || below || shank || holder || plunge || has_table || !fixtures.empty(); }
};

struct RunOptions {
  std::string file;              // input; "-" is standard input; empty: the built-in demo
  bool have_stock = false;
  int64_t stock_nm[6] = {};      // X0 Y0 Z0 X1 Y1 Z1, machine mm -> nm, X0 < X1 ...
  std::string stock_stl;         // --stock FILE.stl: a pre-machined blank (have_stock false)
  int32_t grid_nx = 0, grid_ny = 0;  // --grid; 0: from the pitch or the default
  int64_t pitch_nm = 0;          // --pitch; 0: from --grid or 256 across
  Tool tool;                     // --tool (default flat:6)
  std::string tool_text = "flat:6";
  bool tool_given = false;       // --tool was given
  CutMode mode = CutMode::kSweep;
  std::string image;             // --image (demo: out/final.ppm)
  std::string frames_dir;        // --frames
  ImageFormat frame_format = ImageFormat::kPng;  // --frame-format
  int64_t every = 0;             // --every; 0: about 100 frames over the program
  int32_t width = 640, height = 480;  // --size
  ViewPreset view = ViewPreset::kIso;
  bool have_azimuth = false, have_elevation = false;
  int64_t azimuth_mdeg = 0, elevation_mdeg = 0;
  std::string heightmap, stl, report;
  bool window = false;
  std::string fbdev;
  bool quiet = false;
  // `dexmill optimize`: the program's name in messages when `file` is a
  // copy of it (a spooled standard input); empty: from `file`.
  std::string shown_name;
  // `check --simulate` and `optimize` run a job for its findings: no
  // summary on stdout (optimize: no process warnings either, but each
  // line's feed limit kept, tools/run_job.h RunResult).
  bool print_summary = true;
  bool print_material_warnings = true;
  bool feed_limits = false;
  // Live outputs (--window, --fbdev).
  bool exit_when_done = false;   // close the window after the program (fbdev always does)
  int64_t hold_ms = 0;           // --hold S: keep the last frame this long before exiting
  int64_t speed_milli = 0;       // --speed X: simulated seconds per second, x1000; 0: auto
  // The design part to assess against (paper §2.5).
  std::string design;            // --design FILE.stl|FILE.pgm
  bool demo_design = false;      // the built-in demo's own part (tools/demo_program.h), no file
  // --demo NAME: one of the paper's workpieces (core/design/builtin.h) cut
  // end to end; the design of `builtin` is used when it is set.
  std::string demo;
  const BuiltinDesign* builtin = nullptr;
  std::string error_image;       // --error-image FILE.ppm: the final frame in the error view
  bool design_pgm = false;       // by the extension
  bool have_design_z = false;
  int64_t design_z_nm[2] = {};   // --design-z ZLOW,ZHIGH (PGM: black, white)
  int64_t design_offset_nm[3] = {};  // --design-offset X,Y,Z (STL)
  int64_t tolerance_nm = 50000;  // --tolerance MM (0.05)
  std::vector<ToleranceBox> tolerance_boxes;  // --tolerance-box X0,Y0,X1,Y1,TOL (repeatable)
  // --color; with --material and no --color, material; --thin alone, thin.
  enum class Color : uint8_t { kPlain, kError, kMaterial, kTool, kSlope, kThin } color = Color::kPlain;
  bool have_color = false;
  int64_t thin_nm = kNmPerMm;    // --thin MM: --color thin highlights material thinner than this (1 mm)
  bool have_thin = false;
  // --overlay: the design translucent over the cut (shows overcut), or the
  // cut translucent over the design (shows undercut), in --image.
  enum class Overlay : uint8_t { kNone, kDesign, kWorkpiece } overlay = Overlay::kNone;
  bool stop_at_gouge = false;    // --stop-at gouge|any: stop at the first gouge, exit 4
  bool stop_at_collision = false;  // --stop-at collision|any: stop at the first safety finding, exit 4
  bool fail_on_collision = false;  // --fail-on-collision
  // Safety checks (core/check/safety.h): --check rapid,spindle,below,
  // shank,holder,plunge|all, --table Z, --fixture (repeatable). run_job also
  // turns on what a tool describes (a flute length, a holder, nocentre).
  SafetyChoice checks;
  std::string material;          // --material PRESET|FILE: the stock's composition and its process rules
  bool fail_on_gouge = false;    // --fail-on-gouge: run to the end, exit 4 if any
  int64_t rapid_nm_per_min = MotionTimeModel().rapid_nm_per_min;  // --rapid MM/MIN, for the time estimate
  ReadOptions read;  // --units, --default-feed, --subroutine-path, --max-blocks
  int64_t accel_nm_per_s2 = 0;   // --accel MM/S2 (0: none)
  bool strict = false;           // --strict: an input error cuts nothing (else up to the bad block)
  bool path_overlay = false;     // --path-overlay: the toolpath over every frame (display/backplot.h)
};

// Parses argv[1..argc) (argv[0] is "run"). Returns kExitOk, or prints the
// error and returns kExitUsage; *help is set for --help (usage printed).
int parse_run_options(int argc, char** argv, RunOptions* out, bool* help);

void run_usage(std::FILE* f);

// A decimal number as written (exactly, never through floating point),
// times `scale` (1e6 for mm -> nm, 1000 for s -> ms), rounded to nearest;
// false when s[0, n) is anything else.
bool parse_scaled(const char* s, std::size_t n, int64_t scale, int64_t* out);
bool parse_scaled(const char* s, int64_t scale, int64_t* out);

// True for the run options that take a value (the next argument).
bool run_option_takes_value(const char* a);

// True when o asks for a picture or a model (--image, --error-image,
// --frames, --heightmap, --stl) or a live view: what the subcommands that
// only simulate (`check --simulate`, `optimize`) refuse.
bool run_draws(const RunOptions& o);

}  // namespace cli
}  // namespace dexmill

#endif
