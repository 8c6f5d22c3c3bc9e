// The design part of `dexmill run --design` (paper §2.5): read before the
// cut (a bad file costs no simulation), watched by the simulation while it
// cuts (core/assess/gouge_watch.h), assessed after it into the report.
#ifndef DEXMILL_TOOLS_RUN_RUN_ASSESS_H
#define DEXMILL_TOOLS_RUN_RUN_ASSESS_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/assess/gouge_watch.h"
#include "core/design/design.h"
#include "display/colour/error_colours.h"
#include "platform/report/run_report.h"
#include "tools/run/run_render.h"
#include "tools/run/run_options.h"
#include "tools/run/run_stock.h"

namespace dexmill {
namespace cli {

struct RunDesign {
  std::vector<int32_t> tops;  // the design grid's memory
  DesignGrid grid;
  ReportAssessment report;
  AssessOptions opt;          // tolerance, boxes and the stock's columns
  // --color error: the bands of every dexel, their ramps, and the legend.
  std::vector<uint8_t> bands;
  std::vector<uint32_t> luts;
  ErrorColours<height_t> colours;
  ViewLegend legend;
  std::string file;           // the program, for the warnings
  size_t printed = 0;         // events whose warning is out
  std::vector<PointNm> marks; // where the kept gouges are (deepest column, on the design's surface), for the frames
  std::vector<ToleranceBox> boxes;  // --tolerance-box, in this setup's machine XY
};

// Reads o.design onto the grid of `plan`. Returns kExitOk, or the exit code
// after printing the error (input errors: the file's own message). The
// design, its offset and the tolerance boxes are the part's, as it was
// first set up: `frame` says where a saved stock's setups have put the
// part since (core/math/part_frame.h), and the design is turned with it, so
// that each setup is compared with the design's side it faces.
int load_design(const JobOptions& o, const GridPlan& plan, const std::string& program, RunDesign* d,
                const PartFrame& frame = part_frame_identity());

// The error view (paper §2.5.1, figure 10) of grid g against the design:
// d->colours and d->legend for the outputs to draw with.
void error_view_init(const DexelGrid<height_t>& g, RunDesign* d);

// After a record of `line` was watched (w, the simulation's; `found`: the
// record found a gouge): the marks follow the kept events, and a line's warning (`FILE:LINE:1: warning:
// gouge 0.31 mm at X.. Y.. (design Z.., cut Z..)`, its deepest column) is
// printed once the line is done: when a record of another line has been
// checked, or by print_gouges.
void gouges_after_record(const GougeWatch& w, const DexelGrid<height_t>& g, uint32_t line, bool found, RunDesign* d);
// Prints the warnings not printed yet (the end of the run, or a stop).
void print_gouges(const GougeWatch& w, const DexelGrid<height_t>& g, RunDesign* d);

// --overlay (paper figure 9) for the final image: the design drawn as a
// dexel grid of its own, in a colour of its own, through the view of
// `cut_view` (the cut's final frame), and one of the two blended over the
// other where it is the nearer (display/overlay/overlay.h). *shown is the frame to
// write. False with *err when the frame cannot be drawn.
struct OverlayImage {
  std::vector<height_t> top, bottom;
  DexelGrid<height_t> grid;
  std::vector<uint32_t> pixels;
  std::unique_ptr<RenderOutput> out;
  std::vector<uint8_t> cls;
  std::vector<uint32_t> lut;
  SurfaceColours colours;
};
bool overlay_image(const RunOptions& o, const GridPlan& plan, const RunDesign& d, RenderOutput* cut_view,
                   OverlayImage* ov, const FrameView** shown, std::string* err);

// Compares the cut with the design into d->report (with the watch's gouges).
void assess_design(const GougeWatch& w, const DexelGrid<height_t>& g, RunDesign* d);

}  // namespace cli
}  // namespace dexmill

#endif
