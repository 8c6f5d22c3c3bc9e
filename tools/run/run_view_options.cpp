// The options of `dexmill run` for what it writes (run_options.h
// OutputOptions) and how it shows the run (ViewOptions), the live views
// included. Each entry: name, value, help, what it does.
#include <cstring>

#include "core/math/fixed.h"
#include "display/raster/framebuffer.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_option_table.h"

namespace dexmill {
namespace cli {
namespace {

using Out = OutputOptions;
using View = ViewOptions;

const Option<Out> kOutputs[] = {
    {"--image", "FILE.png|FILE.ppm", "the final frame (the extension picks the format; \"-\" writes PNG to standard output)",
     [](Out* o, const char* v) -> int { return o->image = v, kExitOk; }},
    {"--error-image", "FILE.png|FILE.ppm", "the final frame in the error view too (needs --design)",
     [](Out* o, const char* v) -> int { return o->error_image = v, kExitOk; }},
    {"--frames", "DIR",
     "a frame every --every moves: DIR/frame-000001.png ... (earlier frame-* files in DIR are removed when the cut "
     "starts; a run that fails before it leaves them)",
     [](Out* o, const char* v) -> int { return o->frames_dir = v, kExitOk; }},
    {"--every", "N", "the moves between frames (default: about 100 frames over the program)",
     [](Out* o, const char* v) -> int {
       if (!parse_scaled(v, 1, &o->every) || o->every < 1 || std::strchr(v, '.'))
         return fail(kExitUsage, "--every needs a whole number of moves >= 1, not '%s'", v);
       return kExitOk;
     }},
    {"--frame-format", "png|ppm", "the frames' format (default png)",
     [](Out* o, const char* v) -> int {
       if (!std::strcmp(v, "png")) o->frame_format = ImageFormat::kPng;
       else if (!std::strcmp(v, "ppm")) o->frame_format = ImageFormat::kPpm;
       else return fail(kExitUsage, "--frame-format must be png or ppm, not '%s'", v);
       return kExitOk;
     }},
    {"--heightmap", "FILE.pgm|FILE.png", "the final tops as a 16-bit grey image",
     [](Out* o, const char* v) -> int { return o->heightmap = v, kExitOk; }},
    {"--stl", "FILE.stl", "the final surface as a closed binary STL",
     [](Out* o, const char* v) -> int { return o->stl = v, kExitOk; }},
    {"--stl-tolerance", "MM",
     "merge the STL's top cells into larger facets, every top within MM of the surface written over it "
     "(default: the grid's LSB, the exact surface)",
     [](Out* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->stl_tolerance_nm) || o->stl_tolerance_nm < 0 ||
           o->stl_tolerance_nm > kNmPerMm)
         return fail(kExitUsage, "--stl-tolerance needs mm from 0 to 1, not '%s'", v);
       return o->have_stl_tolerance = true, kExitOk;
     }},
    {"--save-stock", "FILE.dxstock",
     "the final stock, its columns exact, with which tool and line cut each one and the chain of programs "
     "that made it: --stock FILE.dxstock continues from it",
     [](Out* o, const char* v) -> int {
       if (!has_extension(v, ".dxstock")) return fail(kExitUsage, "--save-stock needs a FILE.dxstock, not '%s'", v);
       return o->save_stock = v, kExitOk;
     }},
    {"--engagement-csv", "FILE",
     "each feed move's load, measured on the stock before it cuts: line, time, depth, width and angle of "
     "engagement, removal rate, chip thickness, force, power, feed (one row a move; the report gains the "
     "largest of each and their lines)",
     [](Out* o, const char* v) -> int { return o->engagement_csv = v, kExitOk; }},
    {"--load-plot", "FILE.svg|FILE.png",
     "the load (spindle power with the material's cutting coefficients, else the chip), removal rate and feed "
     "against time, the tool changes and the worst moves marked (measures engagement)",
     [](Out* o, const char* v) -> int {
       if (!has_extension(v, ".svg") && !has_extension(v, ".png"))
         return fail(kExitUsage, "--load-plot needs a FILE.svg or FILE.png, not '%s'", v);
       return o->load_plot = v, kExitOk;
     }},
    {"--sheet", "FILE.html",
     "the verification sheet: one self-contained A4 page or two (the part's views, programs, tools with stick-out, "
     "time, gouges with crops, collisions, travel, rule and load findings, a verdict at the top), drawn from the report",
     [](Out* o, const char* v) -> int {
       if (!has_extension(v, ".html") && !has_extension(v, ".htm"))
         return fail(kExitUsage, "--sheet needs a FILE.html, not '%s'", v);
       return o->sheet = v, kExitOk;
     }},
    {"--report", "FILE.json", "summary: program, errors, stock, grid, tools, volume, time",
     [](Out* o, const char* v) -> int { return o->report = v, kExitOk; }},
};

// Degrees from -limit to limit, in millidegrees.
int degrees(const char* name, int64_t limit, const char* v, int64_t* mdeg) {
  if (!parse_scaled(v, 1000, mdeg) || *mdeg < -360000 || *mdeg > 360000)
    return fail(kExitUsage, "%s needs degrees from -360 to 360, not '%s'", name, v);
  if (*mdeg < -limit * 1000 || *mdeg > limit * 1000)
    return fail(kExitUsage, "%s needs degrees from -%lld to %lld, not '%s'", name, static_cast<long long>(limit),
                static_cast<long long>(limit), v);
  return kExitOk;
}

int color(View* o, const char* v) {
  if (!std::strcmp(v, "plain")) o->color = View::Color::kPlain;
  else if (!std::strcmp(v, "error")) o->color = View::Color::kError;
  else if (!std::strcmp(v, "material")) o->color = View::Color::kMaterial;
  else if (!std::strcmp(v, "tool")) o->color = View::Color::kTool;
  else if (!std::strcmp(v, "slope")) o->color = View::Color::kSlope;
  else if (!std::strcmp(v, "thin")) o->color = View::Color::kThin;
  else if (!std::strcmp(v, "engagement")) o->color = View::Color::kEngagement;
  else return fail(kExitUsage, "--color must be plain, error, material, tool, slope, thin or engagement, not '%s'", v);
  o->have_color = true;
  return kExitOk;
}

const Option<View> kView[] = {
    {"--size", "WxH", "frame size (default 640x480)",
     [](View* o, const char* v) -> int {
       if (!parse_pair(v, 16, kFrameMaxSide, &o->width, &o->height))
         return fail(kExitUsage, "--size needs WxH with whole numbers from 16 to %d, not '%s'", static_cast<int>(kFrameMaxSide), v);
       return kExitOk;
     }},
    {"--view", "iso|top|front|right", "the camera (default iso)",
     [](View* o, const char* v) -> int {
       if (!view_preset_from_name(v, &o->preset)) return fail(kExitUsage, "--view must be iso, top, front or right, not '%s'", v);
       o->have_preset = true;
       return kExitOk;
     }},
    {"--azimuth", "DEG", "the camera's direction around Z, instead of --view (the rest as iso)",
     [](View* o, const char* v) -> int { return o->have_azimuth = true, degrees("--azimuth", 360, v, &o->azimuth_mdeg); }},
    {"--elevation", "DEG", "the camera's height above the XY plane, -90 to 90, instead of --view",
     [](View* o, const char* v) -> int { return o->have_elevation = true, degrees("--elevation", 90, v, &o->elevation_mdeg); }},
    {"--color", "MODE",
     "what colours the surface: plain (one colour), error (cut - design in bands: white within tolerance, "
     "greens left, reds gouged), material (the material under each top; the default with --material), tool "
     "(each tool's cut in its own colour, uncut stock grey), slope (flat, 5, 30, 60 degrees and over), thin "
     "(material thinner than --thin MM orange, than half of it red) or engagement (each cut by its move's load: "
     "the engagement angle in 30-degree bands, or with a material's max_chip or --spindle-power the share of "
     "those limits; plunges pale)",
     color},
    {"--thin", "MM", "the thickness --color thin highlights below (default 1); alone, it means --color thin",
     [](View* o, const char* v) -> int {
       if (!parse_scaled(v, kNmPerMm, &o->thin_nm) || o->thin_nm < 1000 || o->thin_nm > 1000 * kNmPerMm)
         return fail(kExitUsage, "--thin needs a thickness in mm from 0.001 to 1000, not '%s'", v);
       o->have_thin = true;
       return kExitOk;
     }},
    {"--overlay", "design|workpiece",
     "--image with the design translucent over the cut (shows gouges), or the cut translucent over the design "
     "(shows material left)",
     [](View* o, const char* v) -> int {
       if (!std::strcmp(v, "design")) o->overlay = View::Overlay::kDesign;
       else if (!std::strcmp(v, "workpiece")) o->overlay = View::Overlay::kWorkpiece;
       else return fail(kExitUsage, "--overlay must be design or workpiece, not '%s'", v);
       return kExitOk;
     }},
    {"--path-overlay", nullptr,
     "the toolpath over the frames: rapids dashed yellow, feeds blue, pale where still to come (live: the p key)",
     [](View* o, const char*) -> int { return o->path_overlay = true, kExitOk; }},
    {"--no-decorations", nullptr,
     "no axis triad and scale bar in the images, frames and live views (they are drawn by default)",
     [](View* o, const char*) -> int { return o->decorations = false, kExitOk; }},
    {"--no-antialias", nullptr,
     "the final --image and --error-image and the --frames with aliased edges (they are drawn 2x2 supersampled by default)",
     [](View* o, const char*) -> int { return o->antialias = View::Antialias::kNone, kExitOk; }},
    {"--antialias", nullptr,
     "the live views (--window, --fbdev) anti-aliased too, as the images and frames are: 4x the pixels per redraw",
     [](View* o, const char*) -> int { return o->antialias = View::Antialias::kAll, kExitOk; }},
    {"--frame-status", nullptr,
     "the live views' status line (line, X Y Z, feed, tool, time) in a strip under every --frames picture",
     [](View* o, const char*) -> int { return o->frame_status = true, kExitOk; }},
    {"--hide-tool", nullptr, "the final --image and --error-image without the cutter (frames and live views keep it)",
     [](View* o, const char*) -> int { return o->hide_tool = true, kExitOk; }},
    {"--quiet", nullptr, "no progress bar", [](View* o, const char*) -> int { return o->quiet = true, kExitOk; }, "-q"},
};

const Option<View> kLive[] = {
    {"--window", nullptr, "show the simulation live (make GLFW=1: build/glfw/dexmill)",
     [](View* o, const char*) -> int { return o->window = true, kExitOk; }},
    {"--fbdev", "DEV", "draw live into a Linux framebuffer (/dev/fb0)",
     [](View* o, const char* v) -> int { return o->fbdev = v, kExitOk; }},
    {"--speed", "X", "simulated seconds per second (default: about 20 s for the job)",
     [](View* o, const char* v) -> int {
       if (!parse_scaled(v, 1000, &o->speed_milli) || o->speed_milli < 1 || o->speed_milli > 1000000000)
         return fail(kExitUsage, "--speed needs simulated seconds per second from 0.001 to 1e6, not '%s'", v);
       return kExitOk;
     }},
    {"--exit-when-done", nullptr, "close the window after the program",
     [](View* o, const char*) -> int { return o->exit_when_done = true, kExitOk; }},
    {"--hold", "S", "keep the last frame S seconds before closing",
     [](View* o, const char* v) -> int {
       if (!parse_scaled(v, 1000, &o->hold_ms) || o->hold_ms < 0 || o->hold_ms > 3600000)
         return fail(kExitUsage, "--hold needs seconds from 0 to 3600, not '%s'", v);
       return kExitOk;
     }},
};

}  // namespace

OptionList<OutputOptions> run_output_options() { return option_list(kOutputs); }
OptionList<ViewOptions> run_view_options() { return option_list(kView); }
OptionList<ViewOptions> run_live_options() { return option_list(kLive); }

}  // namespace cli
}  // namespace dexmill
