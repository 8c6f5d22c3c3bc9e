// The sheet's pictures and its file; see run_sheet.h.
#include "tools/run/run_sheet.h"

#include <string>
#include <vector>

#include "core/math/fixed.h"
#include "display/raster/camera.h"
#include "platform/format/image_file.h"
#include "platform/os/output_file.h"
#include "platform/report/sheet_html.h"
#include "tools/cli/cli.h"
#include "tools/run/run_engage.h"
#include "tools/run/run_render.h"

namespace dexmill {
namespace cli {
namespace {

constexpr int32_t kViewW = 640, kViewH = 480;  // the views: a third of the page's width each, at about 260 dpi
constexpr int32_t kCropSide = 240;             // a crop: 30 mm square at about 200 dpi
constexpr int64_t kCropViewNm = 10 * kNmPerMm; // the height of world a crop shows (more with a larger tool)

// One picture of the final grid: a camera preset (or `c` when given),
// colours (null: plain), the legend and marks; the cutter not drawn.
struct Shot {
  ViewPreset preset = ViewPreset::kIso;
  const Camera* camera = nullptr;
  const SurfaceColours* colours = nullptr;
  const RenderOutput::Legend* legend = nullptr;
  const std::vector<PointNm>* marks = nullptr;
  int32_t width = kViewW, height = kViewH;
};

bool shoot(const RunOptions& o, Simulation* sim, const Shot& s, std::vector<uint8_t>* png, std::string* err) {
  std::vector<uint32_t> pixels(static_cast<size_t>(s.width) * static_cast<size_t>(s.height), 0);
  FrameView fb;
  fb.pixels = pixels.data();
  fb.width = s.width;
  fb.height = s.height;
  fb.stride_bytes = s.width * 4;
  fb.format = PixelFormat::kXrgb8888;
  RenderOutput out;
  out.set_antialias(true);
  CameraChoice cam;
  cam.preset = s.preset;
  DexelGrid<height_t>& g = sim->grid();
  const GridRect dirty = g.dirty;  // the run's own outputs keep theirs
  if (!out.init(g, fb, cam, err)) return false;
  out.set_decorations(o.view.decorations);
  out.set_colours(s.colours);
  out.set_legend(s.legend);
  if (s.camera) out.set_camera(*s.camera);  // last: the decorations reframe the preset's camera
  if (s.marks) out.add_marks(s.marks, Rgb{255, 32, 24});
  out.draw(&g, CutterPose{false, sim->mill().position()});
  g.dirty = dirty;
  frame_png(fb, png);
  return true;
}

// The camera of a crop: iso, aimed at the gouge's deepest column on the
// design's surface, showing kCropViewNm (or four diameters of the largest
// tool, when more) of world.
Camera crop_camera(const RunSetup& su, const ReportGouge& g) {
  Camera c = camera_preset(ViewPreset::kIso);
  int64_t d_nm = 0;
  for (const Tool& t : su.tools) d_nm = max_of(d_nm, t.diameter_nm);
  c.target = g.at;
  c.view_height_nm = max_of(kCropViewNm, 4 * d_nm);
  return c;
}

int pictures(const RunOptions& o, RunSetup* su, const RunReport& rep, SheetImages* im) {
  Simulation* sim = su->sim;
  std::string err;
  Shot iso, top;
  top.preset = ViewPreset::kTop;
  if (!shoot(o, sim, iso, &im->iso.png, &err) || !shoot(o, sim, top, &im->top.png, &err))
    return fail(kExitUsage, "--sheet: %s", err.c_str());
  im->iso.caption = "iso view";
  im->top.caption = "top view";
  if (!rep.have_assessment) return kExitOk;
  RunDesign& d = su->design;
  error_view_init(sim->grid(), &d);
  Shot e;
  e.colours = &d.colours.colours;
  e.legend = &d.legend;
  e.marks = &d.marks;
  if (!shoot(o, sim, e, &im->error.png, &err)) return fail(kExitUsage, "--sheet: %s", err.c_str());
  im->error.caption = "error view: cut - design, gouges marked red";
  for (size_t k : sheet_worst_gouges(rep.assessment)) {
    const ReportGouge& g = rep.assessment.gouges[k];
    const Camera c = crop_camera(*su, g);
    Shot s = e;
    s.legend = nullptr;
    s.camera = &c;
    s.width = s.height = kCropSide;
    SheetPicture p;
    p.caption = "line " + std::to_string(g.line) + ", iso close-up";
    if (!shoot(o, sim, s, &p.png, &err)) return fail(kExitUsage, "--sheet: %s", err.c_str());
    im->crops.push_back(p);
  }
  return kExitOk;
}

}  // namespace

int write_sheet(const RunOptions& o, RunSetup* su, const RunReport& rep) {
  SheetImages im;
  if (const int code = pictures(o, su, rep, &im)) return code;
  if (su->engage && su->sim->engagement())
    im.load_plot_svg = load_plot_svg_text(*su->engage, *su->sim->engagement(), su->shown_name, o.job.spindle_power_mw, 1000, 400);
  const std::string page = sheet_html_text(rep, im);
  char err[512];
  if (!write_output(o.out.sheet.c_str(), page.data(), page.size(), err, sizeof err)) return fail(kExitIo, "%s", err);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
