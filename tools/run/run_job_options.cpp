// The options of `dexmill run` that make its job (run_options.h
// JobOptions): what is cut, the design it is assessed against, the checks
// and the verdict. Each entry: name, value, help, what it does.
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/design/builtin.h"
#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "display/surface/fixture_draw.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_demo.h"
#include "tools/run/run_option_table.h"
#include "tools/run/setup_text.h"

namespace dexmill {
namespace cli {
namespace {

using Job = JobOptions;

int demo(Job* o, const char* v) {
  if (std::strcmp(v, "list") && std::strcmp(v, kBuiltinDemoName) && !builtin_design_find(v)) {
    std::string names = kBuiltinDemoName;
    for (int32_t k = 0; k < builtin_design_count(); ++k) names += std::string(", ") + builtin_design_at(k).name;
    return fail(kExitUsage, "--demo must be list or one of %s, not '%s'", names.c_str(), v);
  }
  o->demo = v;
  return kExitOk;
}

int stock(Job* o, const char* v) {
  if (has_extension(v, ".stl")) return o->stock_stl = v, kExitOk;
  if (has_extension(v, ".dxstock")) return o->stock_file = v, kExitOk;
  if (!parse_box(v, o->stock_nm))
    return fail(kExitUsage,
                "--stock needs X0,Y0,Z0,X1,Y1,Z1 in mm with X0<X1, Y0<Y1, Z0<Z1 (or a FILE.stl or FILE.dxstock), not '%s'", v);
  o->have_stock = true;
  return kExitOk;
}

// --setup T (tools/run/setup_text.h), for the program after it.
int setup(Job* o, const char* v) {
  StockSetup s;
  std::string why;
  if (!setup_parse(v, &s, &why)) return fail(kExitUsage, "--setup '%s': %s", v, why.c_str());
  o->setups.push_back(s);
  o->setup_program.push_back(o->operands_seen);
  o->setup_texts.push_back(v);
  return kExitOk;
}

int tool(Job* o, const char* v) {
  const ToolSpecError e = tool_spec_parse(v, std::strlen(v), &o->tool);
  if (e != ToolSpecError::kOk) return fail(kExitUsage, "bad --tool '%s': %s", v, tool_spec_message(e));
  o->tool_text = v;
  o->tool_given = true;
  return kExitOk;
}

// A machine rate in mm/min (mm/s2) from 1 to 1000000.
int machine_rate(const char* name, const char* what, const char* v, int64_t* nm) {
  if (!parse_scaled(v, kNmPerMm, nm) || *nm < kNmPerMm || *nm > 1000000 * kNmPerMm)
    return fail(kExitUsage, "%s needs the machine's %s, from 1 to 1000000, not '%s'", name, what, v);
  return kExitOk;
}

int max_input(Job* o, const char* v) {
  char* end = nullptr;
  const unsigned long long mib = std::strtoull(v, &end, 10);
  if (!*v || *end || v[0] == '-' || mib < 1 || mib > (1ULL << 20))
    return fail(kExitUsage, "--max-input needs a size in MiB from 1 to 1048576, not '%s'", v);
  o->max_input_bytes = static_cast<uint64_t>(mib) << 20;
  return kExitOk;
}

int max_memory(Job* o, const char* v) {
  if (!parse_size_bytes(v, &o->max_memory_bytes))
    return fail(kExitUsage, "--max-memory needs a size: a whole number of bytes, or of K, M or G (1024, 1024^2, "
                "1024^3 bytes), from 1 to 2^64 - 1 bytes, not '%s'", v);
  return kExitOk;
}

const Option<Job> kJob[] = {
    {"--demo", "NAME|list",
     "pocket: the built-in demo (what run with no FILE runs on a terminal; writes out/); else one of the "
     "paper's workpieces end to end: its design part, a zig-milling program made from it (dexmill zig), cut "
     "from its material, drawn, assessed; writes out/NAME/ (program, final.png, error.png, frames/, "
     "report.json); list: the demos",
     demo},
    {"--stock", "X0,Y0,Z0,X1,Y1,Z1|FILE.stl|FILE.dxstock",
     "the stock box, mm, machine coordinates (default: from the program), or a pre-machined blank: an STL "
     "mesh's tops over its bounding box, or a stock saved by --save-stock, continued where it was left (its "
     "grid, the tool and where it stood)",
     stock},
    {"--setup", "T",
     "turns a saved stock (--stock FILE.dxstock) into this program's fixturing, exactly: flip-x, flip-y (the "
     "part turned over about its box's X or Y axis), rotate-90|180|270 (about Z, counterclockwise), "
     "offset=X,Y,Z (mm, whole dexels and height steps); joined by '+', repeatable, in order",
     setup},
    {"--setups", "FILE",
     "the programs of a job and their setups, one line a program: the program, then setup=T, tools=FILE, "
     "design=FILE, fixture=BOX, table=Z, g54=X,Y,Z ... g59.3= (the coordinate systems' origins for that "
     "setup); cut in order on one stock, each line's options over the command line's (give no FILE)",
     [](Job* o, const char* v) -> int {
       o->setups_file = v;
       return kExitOk;
     }},
    {"--probe", "DIA",
     "the ball tip, mm across, a probe move (G38.2-G38.5) carries; each stops where it touches (or leaves) the "
     "stock as cut so far, and #5061-#5063, #5070 say where (default: the tool in the spindle)",
     [](Job* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->probe_tip_nm) || o->probe_tip_nm < 1000 || o->probe_tip_nm > 100 * kNmPerMm)
         return fail(kExitUsage, "--probe needs a tip diameter from 0.001 to 100 mm, not '%s'", v);
       return kExitOk;
     }},
    {"--grid", "NXxNY",
     "dexel resolution: the most dexels each way, keeping the stock's shape (default: a 32nd of the smallest "
     "tool, 256 to 1024 dexels across the longer side)",
     [](Job* o, const char* v) -> int {
       if (!parse_pair(v, 4, 65535, &o->grid_nx, &o->grid_ny))
         return fail(kExitUsage, "--grid needs NXxNY with whole numbers from 4 to 65535, not '%s'", v);
       return kExitOk;
     }},
    {"--pitch", "MM", "dexel spacing, instead of --grid",
     [](Job* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->pitch_nm) || o->pitch_nm < 100 || o->pitch_nm > 100 * kNmPerMm)
         return fail(kExitUsage, "--pitch needs a dexel spacing from 0.0001 to 100 mm, not '%s'", v);
       return kExitOk;
     }},
    {"--tool", "SPEC",
     "ball:D flat:D bull:D:R vbit:D:ANGLE, then optionally ,len=L ,stick=S ,shank=D ,holder=DxH[,D1-D2xH...] "
     ",nocentre (mm, degrees); without --tools every T is this tool; with none, each T is the tool the program's "
     "comments describe (Fusion, pcb2gcode, Estlcam, Vectric, Carbide Create... headers), else flat:6 with a warning",
     tool},
    {"--mode", "sweep|stamp", "exact swept envelopes or the paper's instances of motion (default sweep)",
     [](Job* o, const char* v) -> int {
       if (!std::strcmp(v, "sweep")) o->mode = CutMode::kSweep;
       else if (!std::strcmp(v, "stamp")) o->mode = CutMode::kStamp;
       else return fail(kExitUsage, "--mode must be sweep or stamp, not '%s'", v);
       return kExitOk;
     }},
    {"--material", "PRESET|FILE",
     "what the stock is made of (presets: two-layer, marble, wood, bronze, aluminium, wood-on-aluminium, ...): "
     "each material's feed, spindle and coolant limits are checked on what the cut removes; the report's "
     "materials",
     [](Job* o, const char* v) -> int { return o->material = v, kExitOk; }},
    {"--rapid", "MM/MIN", "the machine's rapid rate, for the time estimate (default 5000)",
     [](Job* o, const char* v) -> int {
       o->have_rapid = true;
       return machine_rate("--rapid", "rapid rate in mm/min", v, &o->rapid_nm_per_min);
     }},
    {"--accel", "MM/S2",
     "the machine's acceleration, for the time estimate: corners blended within G64 P, LinuxCNC-style, "
     "between the bounds of no acceleration and every move from rest to rest (default: none)",
     [](Job* o, const char* v) -> int {
       o->have_accel = true;
       return machine_rate("--accel", "acceleration in mm/s2", v, &o->accel_nm_per_s2);
     }},
    {"--max-input", "MIB",
     "the most of a program that cannot be read twice (standard input, a pipe, a FIFO, a device), which is "
     "copied to $TMPDIR first; beyond it the run stops with an error (default 1024; a regular file has no "
     "limit)",
     max_input},
    {"--max-memory", "SIZE",
     "the most memory the grid and the engine that cuts it may take: bytes, or K, M, G (powers of 1024: "
     "--max-memory 2G is 2147483648 bytes); a grid that would need more is refused before anything is "
     "allocated (default: half the machine's physical memory; 4G where it cannot be read)",
     max_memory},
    {"--strict", nullptr,
     "a program with an input error is not cut at all (by default the cut goes up to the bad block, which the "
     "frames mark in amber, and the run exits 1)",
     [](Job* o, const char*) -> int { return o->strict = true, kExitOk; }},
};

int design(Job* o, const char* v) {
  const bool file = has_extension(v, ".stl") || has_extension(v, ".pgm");
  o->builtin = file ? nullptr : builtin_design_find(v);
  if (!file && !o->builtin)
    return fail(kExitUsage, "--design needs an .stl mesh, a .pgm height image or a built-in part's name, not '%s'", v);
  o->design = o->builtin ? std::string("(built-in part ") + v + ")" : v;
  o->design_pgm = has_extension(v, ".pgm");
  return kExitOk;
}

int tolerance_box(Job* o, const char* v) {
  int64_t b[5];
  if (!parse_mm_list(v, 5, b) || b[0] > b[2] || b[1] > b[3] || b[4] < 0 || b[4] > 100 * kNmPerMm)
    return fail(kExitUsage,
                "--tolerance-box needs X0,Y0,X1,Y1,TOL in mm with X0 <= X1, Y0 <= Y1, 0 <= TOL <= 100, not '%s'", v);
  o->tolerance_boxes.push_back(ToleranceBox{b[0], b[1], b[2], b[3], b[4]});
  return kExitOk;
}

const Option<Job> kDesign[] = {
    {"--design", "FILE.stl|FILE.pgm|NAME",
     "the design part (an STL mesh, a PGM height image or a built-in part): the report gains an assessment "
     "(paper 2.5)",
     design},
    {"--design-offset", "X,Y,Z", "mm added to every vertex of an STL design",
     [](Job* o, const char* v) -> int {
       if (!parse_mm_list(v, 3, o->design_offset_nm)) return fail(kExitUsage, "--design-offset needs X,Y,Z in mm, not '%s'", v);
       return kExitOk;
     }},
    {"--design-z", "ZLOW,ZHIGH", "a PGM design's black and white, mm (it spans the stock's XY)",
     [](Job* o, const char* v) -> int {
       if (!parse_mm_list(v, 2, o->design_z_nm) || o->design_z_nm[0] >= o->design_z_nm[1])
         return fail(kExitUsage, "--design-z needs ZLOW,ZHIGH in mm with ZLOW < ZHIGH, not '%s'", v);
       o->have_design_z = true;
       return kExitOk;
     }},
    {"--tolerance", "MM", "|cut - design| within it is not an error (default 0.05)",
     [](Job* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->tolerance_nm) || o->tolerance_nm < 0 || o->tolerance_nm > 100 * kNmPerMm)
         return fail(kExitUsage, "--tolerance needs mm from 0 to 100, not '%s'", v);
       return kExitOk;
     }},
    {"--tolerance-box", "X0,Y0,X1,Y1,TOL", "another tolerance inside a box (repeatable; the last box holding a column wins)",
     tolerance_box},
};

int check(Job* o, const char* v) {
  for (const char* p = v; *p;) {
    const char* end = std::strchr(p, ',');
    const std::string word(p, end ? static_cast<size_t>(end - p) : std::strlen(p));
    SafetyChoice& c = o->checks;
    if (word == "rapid") c.rapid = true;
    else if (word == "spindle") c.spindle = true;
    else if (word == "below") c.below = true;
    else if (word == "shank") c.shank = true;
    else if (word == "holder") c.holder = true;
    else if (word == "plunge") c.plunge = true;
    else if (word == "all") c.all();
    else if (word == "load") o->check_load = true;
    else if (word == "travel") o->check_travel = true;
    else
      return fail(kExitUsage,
                  "--check takes rapid, spindle, below, shank, holder, plunge, all, load or travel (comma-separated), "
                  "not '%s'", word.c_str());
    p = end ? end + 1 : p + word.size();
  }
  return kExitOk;
}

int fixture(Job* o, const char* v) {
  int64_t b[6];
  if (!parse_box(v, b)) return fail(kExitUsage, "--fixture needs X0,Y0,Z0,X1,Y1,Z1 in mm with X0<X1, Y0<Y1, Z0<Z1, not '%s'", v);
  if (o->checks.fixtures.size() >= static_cast<size_t>(kFixturesMax))
    return fail(kExitUsage, "at most %d --fixture boxes", kFixturesMax);
  o->checks.fixtures.push_back(BoxNm{PointNm{b[0], b[1], b[2]}, PointNm{b[3], b[4], b[5]}});
  return kExitOk;
}

int stop_at(Job* o, const char* v) {
  if (!std::strcmp(v, "any")) o->stop_at_any = true;
  else if (!std::strcmp(v, "gouge")) o->stop_at_gouge = true;
  else if (!std::strcmp(v, "collision")) o->stop_at_collision = true;
  else return fail(kExitUsage, "--stop-at must be gouge, collision or any, not '%s'", v);
  return kExitOk;
}

const Option<Job> kChecks[] = {
    {"--check", "CHECK[,CHECK...]",
     "safety checks: rapid (rapids that remove material), spindle (cutting with the spindle stopped), below "
     "(the tool below the stock), shank (the shank above the flutes touching material; len=), holder (the "
     "holder touching it; holder=), plunge (a nocentre tool plunging), or all; a tool that gives len=, holder= "
     "or nocentre has its check on without asking; load (not in all: needs --material) the chip against the "
     "material's max_chip and the power against --spindle-power",
     check},
    {"--spindle-power", "W",
     "the spindle's power (watts): a move that needs more (Kienzle, the material's kc1.1 and mc) is a load "
     "finding at its line (turns on --check load)",
     [](Job* o, const char* v) -> int {
       int64_t mw = 0;
       if (!parse_scaled(v, 1000, &mw) || mw <= 0 || mw > int64_t{1} << 50)
         return fail(kExitUsage, "--spindle-power needs the spindle's power in watts above 0, not '%s'", v);
       o->spindle_power_mw = mw;
       o->check_load = true;
       return kExitOk;
     }},
    {"--default-spindle", "RPM",
     "the spindle speed where the program gives none (no S word, or no M3: a router's spindle switched by "
     "hand): the chip per tooth, force and power of engagement rest on it (default none: not measured there)",
     [](Job* o, const char* v) -> int {
       int64_t rpm = 0;
       if (!parse_scaled(v, 1, &rpm) || rpm <= 0 || rpm > 1000000)
         return fail(kExitUsage, "--default-spindle needs a speed in rpm from 1 to 1000000, not '%s'", v);
       o->default_spindle_rpm = static_cast<int32_t>(rpm);
       return kExitOk;
     }},
    {"--machine", "FILE",
     "the machine: a LinuxCNC INI file or a grbl settings dump ($$, and what $# prints), told apart by content: "
     "its soft limits (--check travel, on with it), its tool table, subroutine path, units, rapid rate and "
     "acceleration where the options do not say, and its work offsets",
     [](Job* o, const char* v) -> int { return o->machine_file = v, kExitOk; }},
    {"--fail-on-travel", nullptr, "run to the end, exit 4 if a move left the machine's travel (needs --machine)",
     [](Job* o, const char*) -> int { return o->fail_on_travel = o->check_travel = true, kExitOk; }},
    {"--fail-on-load", nullptr, "run to the end, exit 4 if a move broke a load limit (turns on --check load)",
     [](Job* o, const char*) -> int { return o->fail_on_load = o->check_load = true, kExitOk; }},
    {"--table", "Z", "the table's Z (mm): the tool going below it is a finding",
     [](Job* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->checks.table_nm)) return fail(kExitUsage, "--table needs the table's Z in mm, not '%s'", v);
       o->checks.has_table = true;
       return kExitOk;
     }},
    {"--fixture", "X0,Y0,Z0,X1,Y1,Z1",
     "a box (mm) the tool and holder must never enter, drawn in steel blue (repeatable, up to 8)", fixture},
    {"--stop-at", "gouge|collision|any",
     "stop at the first gouge, safety finding or either (outputs show that state), exit 4", stop_at},
    {"--fail-on-gouge", nullptr, "run to the end, exit 4 if the cut gouged the design",
     [](Job* o, const char*) -> int { return o->fail_on_gouge = true, kExitOk; }},
    {"--fail-on-collision", nullptr,
     "run to the end, exit 4 if a safety check found something (all checks run unless --check names some)",
     [](Job* o, const char*) -> int { return o->fail_on_collision = true, kExitOk; }},
};

}  // namespace

OptionList<JobOptions> run_job_options() { return option_list(kJob); }
OptionList<JobOptions> run_design_options() { return option_list(kDesign); }
OptionList<JobOptions> run_check_options() { return option_list(kChecks); }

}  // namespace cli
}  // namespace dexmill
