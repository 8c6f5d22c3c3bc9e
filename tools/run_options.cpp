// `dexmill run` option parsing; see run_options.h.
#include "tools/run_options.h"

#include <strings.h>

#include <cstdio>
#include <cstring>

#include "core/math/decimal.h"
#include "core/math/fixed.h"
#include "core/motion/interp.h"
#include "core/tool/spec.h"
#include "display/fixture_draw.h"
#include "display/framebuffer.h"
#include "tools/cli.h"

namespace dexmill {
namespace cli {
bool parse_scaled(const char* s, std::size_t n, int64_t scale, int64_t* out) {
  Decimal d;
  std::size_t pos = 0;
  if (n == 0 || decimal_parse(s, n, &pos, &d) != DecimalParse::kOk || pos != n) return false;
  *out = decimal_scale(d, scale);
  return true;
}
bool parse_scaled(const char* s, int64_t scale, int64_t* out) { return parse_scaled(s, std::strlen(s), scale, out); }

namespace {

// "AxB" with both whole numbers in [lo, hi].
bool parse_pair(const char* s, int64_t lo, int64_t hi, int32_t* a, int32_t* b) {
  const char* x = std::strchr(s, 'x');
  if (!x) x = std::strchr(s, 'X');
  if (!x) return false;
  int64_t va, vb;
  if (!parse_scaled(s, static_cast<std::size_t>(x - s), 1, &va) || !parse_scaled(x + 1, 1, &vb)) return false;
  for (const char* p = s; *p; ++p)
    if (*p == '.' || *p == '-' || *p == '+' || *p == ' ') return false;
  if (va < lo || va > hi || vb < lo || vb > hi) return false;
  *a = static_cast<int32_t>(va);
  *b = static_cast<int32_t>(vb);
  return true;
}

// "A,B,C..." with exactly n numbers in mm (each within the G-code range).
bool parse_mm_list(const char* s, int n, int64_t* v) {
  int k = 0;
  const char* p = s;
  for (;;) {
    const char* c = std::strchr(p, ',');
    const std::size_t len = c ? static_cast<std::size_t>(c - p) : std::strlen(p);
    if (k == n || !parse_scaled(p, len, kNmPerMm, &v[k])) return false;
    if (v[k] > kGcodeMaxCoordNm || v[k] < -kGcodeMaxCoordNm) return false;
    ++k;
    if (!c) break;
    p = c + 1;
  }
  return k == n;
}

bool parse_stock(const char* s, int64_t* v) {
  return parse_mm_list(s, 6, v) && v[0] < v[3] && v[1] < v[4] && v[2] < v[5];
}

bool ends_with(const char* s, const char* ext) {
  const std::size_t n = std::strlen(s), e = std::strlen(ext);
  return n > e && strcasecmp(s + n - e, ext) == 0;
}

}  // namespace

void run_usage(std::FILE* f) {
  std::fprintf(f,
               "usage: dexmill run [FILE|-] [options]\n\n"
               "Simulates milling a G-code program into a block of stock and writes what you ask\n"
               "for. With no FILE it runs the built-in demo (writes out/demo.ngc, out/final.ppm\n"
               "and out/frames/).\n\n"
               "  --demo NAME|list           one of the paper's workpieces end to end: its design part,\n"
               "                             a zig-milling program made from it (dexmill zig), cut from\n"
               "                             its material, drawn, assessed; writes out/NAME/ (program,\n"
               "                             final.png, error.png, frames/, report.json)\n"
               "  --stock X0,Y0,Z0,X1,Y1,Z1  stock box, mm, machine coordinates (default: from the program)\n"
               "  --stock FILE.stl           a pre-machined blank: its mesh's tops over its bounding box\n"
               "  --grid NXxNY | --pitch MM  dexel resolution (default: a 32nd of the smallest tool,\n"
               "                             256 to 1024 dexels across the longer side)\n"
               "  --tool SPEC                ball:D flat:D bull:D:R vbit:D:ANGLE [,len=L] (default flat:6)\n"
               "  --tools FILE               LinuxCNC tool table; T/M6 pick from it\n"
               "  --units mm|inch            units of programs that never say G20/G21 (default mm)\n"
               "  --mode sweep|stamp         exact swept envelopes or instances of motion (default sweep)\n"
               "  --rapid MM/MIN             rapid rate for the time estimate (default 5000)\n"
               "  --default-feed MM/MIN      the controller's feed for moves made with no F in force\n"
               "                             (warned once; default: none, such a move is an error)\n"
               "  --subroutine-path DIR[:DIR] where `o<name> call` finds NAME.ngc (LinuxCNC's\n"
               "                             SUBROUTINE_PATH)\n"
               "  --max-blocks N             blocks a looping program may run (default 10000000;\n"
               "                             0: no limit); an endless loop stops with an error\n"
               "  --accel MM/S2              time estimate with every move speeding up from rest and\n"
               "                             slowing to rest at this acceleration (default: none)\n"
               "  --image FILE.png|FILE.ppm  final frame (the extension picks the format; - is stdout)\n"
               "  --frames DIR [--every N]   a frame every N moves: DIR/frame-000001.png ... (earlier\n"
               "                             frame-* files in DIR are removed first)\n"
               "  --frame-format png|ppm     the frames' format (default png)\n"
               "  --size WxH                 frame size (default 640x480)\n"
               "  --view iso|top|front|right or --azimuth DEG --elevation DEG   camera (default iso)\n"
               "  --heightmap FILE.pgm|.png  final tops as a 16-bit grey image\n"
               "  --stl FILE.stl             final surface as a closed binary STL\n"
               "  --report FILE.json         summary: program, errors, stock, grid, tools, volume, time\n"
               "  --window                   show the simulation live (make GLFW=1: build/glfw/dexmill)\n"
               "  --fbdev DEV                draw live into a Linux framebuffer (/dev/fb0)\n"
               "  --speed X                  live: simulated seconds per second (default: ~20 s per job)\n"
               "  --exit-when-done [--hold S]  live: close after the program (after S seconds)\n"
               "  --design FILE.stl|FILE.pgm the design part: the report gains an assessment (paper 2.5)\n"
               "  --design-offset X,Y,Z      mm added to every vertex of an STL design\n"
               "  --design-z ZLOW,ZHIGH      a PGM design's black and white, mm (it spans the stock's XY)\n"
               "  --tolerance MM             |cut - design| within it is not an error (default 0.05)\n"
               "  --tolerance-box X0,Y0,X1,Y1,TOL  another tolerance inside a box (repeatable)\n"
               "  --color MODE               what colours the surface: plain (one colour), error (cut -\n"
               "                             design in bands: white within tolerance, greens left, reds\n"
               "                             gouged), material (the material under each top; the default\n"
               "                             with --material), tool (each tool's cut in its own colour,\n"
               "                             uncut stock grey), slope (flat, 5, 30, 60 degrees and over)\n"
               "                             or thin (material thinner than --thin MM orange, than half\n"
               "                             of it red)\n"
               "  --thin MM                  the thickness --color thin highlights below (default 1);\n"
               "                             alone, it means --color thin\n"
               "  --error-image FILE.png     the final frame in the error view too (needs --design)\n"
               "  --overlay design|workpiece --image with the design translucent over the cut (shows\n"
               "                             gouges), or the cut translucent over the design (shows\n"
               "                             material left)\n"
               "  --stop-at gouge|collision|any  stop at the first gouge or safety finding (outputs\n"
               "                             show that state), exit 4\n"
               "  --fail-on-gouge            run to the end, exit 4 if the cut gouged the design\n"
               "  --check rapid,spindle,below,shank,holder,plunge|all  safety checks: rapids that\n"
               "                             remove material, cutting with the spindle stopped, the\n"
               "                             tool below the stock, the shank above the flutes (len=)\n"
               "                             or the holder (holder=) touching material, a nocentre\n"
               "                             tool plunging; a tool that gives len=, holder= or\n"
               "                             nocentre has its check on without asking\n"
               "  --material PRESET|FILE     what the stock is made of (presets: two-layer, marble,\n"
               "                             wood, bronze, aluminium, wood-on-aluminium, ...): each\n"
               "                             material's feed, spindle and coolant limits are checked\n"
               "                             on what the cut removes; the report's materials\n"
               "  --table Z                  the table's Z (mm): the tool going below it is a finding\n"
               "  --fixture X0,Y0,Z0,X1,Y1,Z1  a box (mm) the tool and holder must never enter, drawn\n"
               "                             in steel blue (repeatable, up to 8)\n"
               "  --fail-on-collision        run to the end, exit 4 if a safety check found something\n"
               "  --path-overlay             the toolpath over the frames: rapids dashed yellow, feeds\n"
               "                             blue, pale where still to come (live: the p key)\n"
               "  --strict                   a program with an input error is not cut at all (by\n"
               "                             default the cut goes up to the bad block, which the\n"
               "                             frames mark in amber, and the run exits 1)\n"
               "  -q                         no progress bar\n\n"
               "Window keys: drag orbits, wheel zooms, space pauses, + and - change speed, p shows\n"
               "the toolpath, r resets the view, q quits. Exit status: 0 ok, 1 input errors (the cut\n"
               "goes up to the first), 2 usage, 3 I/O, 4 a check asked for failed (--stop-at,\n"
               "--fail-on-gouge).\n");
}

bool run_draws(const RunOptions& o) {
  return !o.image.empty() || !o.error_image.empty() || !o.frames_dir.empty() || !o.heightmap.empty() ||
         !o.stl.empty() || o.window || !o.fbdev.empty();
}

bool run_option_takes_value(const char* a) {
  static const char* const kWithValue[] = {"--stock", "--grid", "--pitch", "--tool", "--tools", "--units",
                                           "--mode", "--rapid", "--default-feed", "--subroutine-path", "--max-blocks", "--accel", "--image", "--frames", "--frame-format", "--every", "--size", "--view",
                                           "--azimuth", "--elevation", "--heightmap", "--stl", "--report",
                                           "--fbdev", "--hold", "--speed", "--design", "--design-z",
                                           "--design-offset", "--tolerance", "--tolerance-box", "--color", "--thin", "--stop-at", "--error-image", "--overlay", "--check", "--table", "--fixture", "--material", "--demo"};
  for (const char* k : kWithValue)
    if (!std::strcmp(a, k)) return true;
  return false;
}

int parse_run_options(int argc, char** argv, RunOptions* o, bool* help) {
  *help = false;
  {
    const ToolSpecError e = tool_spec_parse("flat:6", 6, &o->tool);
    if (e != ToolSpecError::kOk) return fail(kExitUsage, "internal: default tool");
  }
  bool stop_any = false;
  bool have_file = false, have_grid = false, have_pitch = false, have_view = false, have_every = false;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      run_usage(stdout);
      *help = true;
      return kExitOk;
    }
    if (!std::strcmp(a, "-q") || !std::strcmp(a, "--quiet")) { o->quiet = true; continue; }
    if (!std::strcmp(a, "--window")) { o->window = true; continue; }
    if (!std::strcmp(a, "--exit-when-done")) { o->exit_when_done = true; continue; }
    if (!std::strcmp(a, "--fail-on-gouge")) { o->fail_on_gouge = true; continue; }
    if (!std::strcmp(a, "--strict")) { o->strict = true; continue; }
    if (!std::strcmp(a, "--fail-on-collision")) { o->fail_on_collision = true; continue; }
    if (!std::strcmp(a, "--path-overlay")) { o->path_overlay = true; continue; }
    if (a[0] != '-' || !a[1]) {
      if (have_file) return fail(kExitUsage, "more than one input file ('%s' and '%s')", o->file.c_str(), a);
      o->file = a;
      have_file = true;
      continue;
    }
    if (const int taken = take_read_option(argc, argv, &i, &o->read)) {
      if (taken < 0) return kExitUsage;
      continue;
    }
    if (!run_option_takes_value(a)) return fail(kExitUsage, "unknown option '%s' (try 'dexmill %s --help')", a, argv[0]);
    if (i + 1 >= argc) return fail(kExitUsage, "%s needs a value", a);
    const char* v = argv[++i];
    const std::string name = a;
    if (name == "--stock" && ends_with(v, ".stl")) {
      o->stock_stl = v;
    } else if (name == "--stock") {
      if (!parse_stock(v, o->stock_nm))
        return fail(kExitUsage, "--stock needs X0,Y0,Z0,X1,Y1,Z1 in mm with X0<X1, Y0<Y1, Z0<Z1 (or a FILE.stl), not '%s'", v);
      o->have_stock = true;
    } else if (name == "--grid") {
      if (!parse_pair(v, 4, 65535, &o->grid_nx, &o->grid_ny))
        return fail(kExitUsage, "--grid needs NXxNY with whole numbers from 4 to 65535, not '%s'", v);
      have_grid = true;
    } else if (name == "--pitch") {
      if (!parse_scaled(v, kNmPerMm, &o->pitch_nm) || o->pitch_nm < 100 || o->pitch_nm > 100 * kNmPerMm)
        return fail(kExitUsage, "--pitch needs a dexel spacing from 0.0001 to 100 mm, not '%s'", v);
      have_pitch = true;
    } else if (name == "--tool") {
      const ToolSpecError e = tool_spec_parse(v, std::strlen(v), &o->tool);
      if (e != ToolSpecError::kOk) return fail(kExitUsage, "bad --tool '%s': %s", v, tool_spec_message(e));
      o->tool_text = v;
      o->tool_given = true;
    } else if (name == "--mode") {
      if (!std::strcmp(v, "sweep")) o->mode = CutMode::kSweep;
      else if (!std::strcmp(v, "stamp")) o->mode = CutMode::kStamp;
      else return fail(kExitUsage, "--mode must be sweep or stamp, not '%s'", v);
    } else if (name == "--rapid") {
      if (!parse_scaled(v, kNmPerMm, &o->rapid_nm_per_min) || o->rapid_nm_per_min < kNmPerMm ||
          o->rapid_nm_per_min > 1000000 * kNmPerMm)
        return fail(kExitUsage, "--rapid needs the machine's rapid rate in mm/min, from 1 to 1000000, not '%s'", v);
    } else if (name == "--accel") {
      if (!parse_scaled(v, kNmPerMm, &o->accel_nm_per_s2) || o->accel_nm_per_s2 < kNmPerMm ||
          o->accel_nm_per_s2 > 1000000 * kNmPerMm)
        return fail(kExitUsage, "--accel needs the machine's acceleration in mm/s2, from 1 to 1000000, not '%s'", v);
    } else if (name == "--image") {
      o->image = v;
    } else if (name == "--frames") {
      o->frames_dir = v;
    } else if (name == "--frame-format") {
      if (!std::strcmp(v, "png")) o->frame_format = ImageFormat::kPng;
      else if (!std::strcmp(v, "ppm")) o->frame_format = ImageFormat::kPpm;
      else return fail(kExitUsage, "--frame-format must be png or ppm, not '%s'", v);
    } else if (name == "--every") {
      if (!parse_scaled(v, 1, &o->every) || o->every < 1 || std::strchr(v, '.'))
        return fail(kExitUsage, "--every needs a whole number of moves >= 1, not '%s'", v);
      have_every = true;
    } else if (name == "--size") {
      if (!parse_pair(v, 16, kFrameMaxSide, &o->width, &o->height))
        return fail(kExitUsage, "--size needs WxH with whole numbers from 16 to %d, not '%s'",
                    static_cast<int>(kFrameMaxSide), v);
    } else if (name == "--view") {
      if (!view_preset_from_name(v, &o->view))
        return fail(kExitUsage, "--view must be iso, top, front or right, not '%s'", v);
      have_view = true;
    } else if (name == "--azimuth" || name == "--elevation") {
      int64_t mdeg = 0;
      if (!parse_scaled(v, 1000, &mdeg) || mdeg < -360000 || mdeg > 360000)
        return fail(kExitUsage, "%s needs degrees from -360 to 360, not '%s'", a, v);
      if (name == "--azimuth") { o->azimuth_mdeg = mdeg; o->have_azimuth = true; }
      else {
        if (mdeg < -90000 || mdeg > 90000) return fail(kExitUsage, "--elevation needs degrees from -90 to 90, not '%s'", v);
        o->elevation_mdeg = mdeg;
        o->have_elevation = true;
      }
    } else if (name == "--heightmap") {
      o->heightmap = v;
    } else if (name == "--stl") {
      o->stl = v;
    } else if (name == "--report") {
      o->report = v;
    } else if (name == "--fbdev") {
      o->fbdev = v;
    } else if (name == "--hold") {
      if (!parse_scaled(v, 1000, &o->hold_ms) || o->hold_ms < 0 || o->hold_ms > 3600000)
        return fail(kExitUsage, "--hold needs seconds from 0 to 3600, not '%s'", v);
    } else if (name == "--design") {
      o->builtin = ends_with(v, ".stl") || ends_with(v, ".pgm") ? nullptr : builtin_design_find(v);
      if (!ends_with(v, ".stl") && !ends_with(v, ".pgm") && !o->builtin)
        return fail(kExitUsage, "--design needs an .stl mesh, a .pgm height image or a built-in part's name, not '%s'", v);
      o->design = o->builtin ? std::string("(built-in part ") + v + ")" : v;
      o->design_pgm = ends_with(v, ".pgm");
    } else if (name == "--design-z") {
      if (!parse_mm_list(v, 2, o->design_z_nm) || o->design_z_nm[0] >= o->design_z_nm[1])
        return fail(kExitUsage, "--design-z needs ZLOW,ZHIGH in mm with ZLOW < ZHIGH, not '%s'", v);
      o->have_design_z = true;
    } else if (name == "--design-offset") {
      if (!parse_mm_list(v, 3, o->design_offset_nm))
        return fail(kExitUsage, "--design-offset needs X,Y,Z in mm, not '%s'", v);
    } else if (name == "--tolerance") {
      if (!parse_scaled(v, kNmPerMm, &o->tolerance_nm) || o->tolerance_nm < 0 || o->tolerance_nm > 100 * kNmPerMm)
        return fail(kExitUsage, "--tolerance needs mm from 0 to 100, not '%s'", v);
    } else if (name == "--tolerance-box") {
      int64_t b[5];
      if (!parse_mm_list(v, 5, b) || b[0] > b[2] || b[1] > b[3] || b[4] < 0 || b[4] > 100 * kNmPerMm)
        return fail(kExitUsage, "--tolerance-box needs X0,Y0,X1,Y1,TOL in mm with X0 <= X1, Y0 <= Y1, 0 <= TOL <= 100, not '%s'", v);
      o->tolerance_boxes.push_back(ToleranceBox{b[0], b[1], b[2], b[3], b[4]});
    } else if (name == "--color") {
      if (!std::strcmp(v, "plain")) o->color = RunOptions::Color::kPlain;
      else if (!std::strcmp(v, "error")) o->color = RunOptions::Color::kError;
      else if (!std::strcmp(v, "material")) o->color = RunOptions::Color::kMaterial;
      else if (!std::strcmp(v, "tool")) o->color = RunOptions::Color::kTool;
      else if (!std::strcmp(v, "slope")) o->color = RunOptions::Color::kSlope;
      else if (!std::strcmp(v, "thin")) o->color = RunOptions::Color::kThin;
      else return fail(kExitUsage, "--color must be plain, error, material, tool, slope or thin, not '%s'", v);
      o->have_color = true;
    } else if (name == "--thin") {
      if (!parse_scaled(v, kNmPerMm, &o->thin_nm) || o->thin_nm < 1000 || o->thin_nm > 1000 * kNmPerMm)
        return fail(kExitUsage, "--thin needs a thickness in mm from 0.001 to 1000, not '%s'", v);
      o->have_thin = true;
    } else if (name == "--overlay") {
      if (!std::strcmp(v, "design")) o->overlay = RunOptions::Overlay::kDesign;
      else if (!std::strcmp(v, "workpiece")) o->overlay = RunOptions::Overlay::kWorkpiece;
      else return fail(kExitUsage, "--overlay must be design or workpiece, not '%s'", v);
    } else if (name == "--error-image") {
      o->error_image = v;
    } else if (name == "--stop-at") {
      if (!std::strcmp(v, "any")) stop_any = true;
      else if (!std::strcmp(v, "gouge")) o->stop_at_gouge = true;
      else if (!std::strcmp(v, "collision")) o->stop_at_collision = true;
      else return fail(kExitUsage, "--stop-at must be gouge, collision or any, not '%s'", v);
    } else if (name == "--check") {
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
        else if (word == "all") c.rapid = c.spindle = c.below = c.shank = c.holder = c.plunge = true;
        else
          return fail(kExitUsage, "--check takes rapid, spindle, below, shank, holder, plunge or all (comma-separated), not '%s'",
                      word.c_str());
        p = end ? end + 1 : p + word.size();
      }
    } else if (name == "--material") {
      o->material = v;
    } else if (name == "--demo") {
      if (std::strcmp(v, "list") && !builtin_design_find(v)) {
        std::string names;
        for (int32_t k = 0; k < builtin_design_count(); ++k) names += std::string(k ? ", " : "") + builtin_design_at(k).name;
        return fail(kExitUsage, "--demo must be list or one of %s, not '%s'", names.c_str(), v);
      }
      o->demo = v;
    } else if (name == "--fixture") {
      int64_t b[6];
      if (!parse_stock(v, b))
        return fail(kExitUsage, "--fixture needs X0,Y0,Z0,X1,Y1,Z1 in mm with X0<X1, Y0<Y1, Z0<Z1, not '%s'", v);
      if (o->checks.fixtures.size() >= static_cast<size_t>(kFixturesMax))
        return fail(kExitUsage, "at most %d --fixture boxes", kFixturesMax);
      o->checks.fixtures.push_back(BoxNm{PointNm{b[0], b[1], b[2]}, PointNm{b[3], b[4], b[5]}});
    } else if (name == "--table") {
      if (!parse_scaled(v, kNmPerMm, &o->checks.table_nm))
        return fail(kExitUsage, "--table needs the table's Z in mm, not '%s'", v);
      o->checks.has_table = true;
    } else if (name == "--speed") {
      if (!parse_scaled(v, 1000, &o->speed_milli) || o->speed_milli < 1 || o->speed_milli > 1000000000)
        return fail(kExitUsage, "--speed needs simulated seconds per second from 0.001 to 1e6, not '%s'", v);
    }
  }
  if (have_grid && have_pitch) return fail(kExitUsage, "give --grid or --pitch, not both");
  if (have_view && (o->have_azimuth || o->have_elevation))
    return fail(kExitUsage, "give --view or --azimuth/--elevation, not both");
  if (have_every && o->frames_dir.empty()) return fail(kExitUsage, "--every needs --frames DIR");
  if (o->window && !o->fbdev.empty()) return fail(kExitUsage, "give --window or --fbdev, not both");
  if (!o->demo.empty() && (!o->file.empty() || !o->design.empty()))
    return fail(kExitUsage, "--demo cuts its own program from its own design: give no FILE and no --design");
  if (o->design.empty() && (o->have_design_z || !o->tolerance_boxes.empty()))
    return fail(kExitUsage, "%s needs --design", o->have_design_z ? "--design-z" : "--tolerance-box");
  if (!o->error_image.empty() && o->design.empty() && !o->file.empty())
    return fail(kExitUsage, "--error-image needs --design (the part to compare the cut with)");
  if (o->overlay != RunOptions::Overlay::kNone && o->design.empty())
    return fail(kExitUsage, "--overlay needs --design (the part to draw with the cut)");
  // Asking to stop or fail on a collision without naming checks runs them all.
  // --stop-at any: at a safety finding, and at a gouge when there is a design.
  if (stop_any) {
    o->stop_at_collision = true;
    o->stop_at_gouge = o->stop_at_gouge || !o->design.empty();
  }
  if ((o->stop_at_collision || o->fail_on_collision) && !o->checks.any()) {
    SafetyChoice& c = o->checks;
    c.rapid = c.spindle = c.below = c.shank = c.holder = c.plunge = true;
  }
  if ((o->stop_at_gouge || o->fail_on_gouge) && o->design.empty())
    return fail(kExitUsage, "%s needs --design (the part a gouge goes into)", o->stop_at_gouge ? "--stop-at gouge" : "--fail-on-gouge");
  // --thin says which mode it is for: alone it is that mode, with another an error.
  if (o->have_thin && o->have_color && o->color != RunOptions::Color::kThin)
    return fail(kExitUsage, "--thin is the limit of --color thin; it does not go with another --color");
  if (o->have_thin && !o->have_color) {
    o->color = RunOptions::Color::kThin;
    o->have_color = true;
  }
  if (!o->material.empty() && !o->have_color) o->color = RunOptions::Color::kMaterial;
  if (o->color == RunOptions::Color::kMaterial && o->material.empty())
    return fail(kExitUsage, "--color material needs --material (what the stock is made of)");
  if (o->color == RunOptions::Color::kError && o->design.empty())
    return fail(kExitUsage, "--color error needs --design (the part to compare the cut with)");
  if (o->design_pgm && !o->have_design_z)
    return fail(kExitUsage, "a PGM design needs --design-z ZLOW,ZHIGH (the heights of black and white)");
  if (!o->design.empty() && !o->design_pgm && o->have_design_z)
    return fail(kExitUsage, "--design-z is for PGM designs; place an STL design with --design-offset");
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
