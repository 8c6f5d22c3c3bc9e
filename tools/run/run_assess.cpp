// `dexmill run --design`; see run_assess.h.
#include "tools/run/run_assess.h"

#include <cstdio>
#include <string>

#include "core/assess/assess.h"
#include "display/api/run_marks.h"
#include "display/view/colour_legend.h"
#include "platform/format/pgm.h"
#include "platform/format/stl_read.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"
#include "tools/run/demo_program.h"

namespace dexmill {
namespace cli {

namespace {

// A height-field design (the demo's, a built-in part, a PGM) is the part's
// top only: a setup that turned the part over faces its other side, which
// only a mesh describes; a PGM is stretched over the stock's box, which a
// quarter turn would have to turn with it.
int heights_in_frame(const JobOptions& o, const PartFrame& f) {
  if (f.turn[8] < 0)
    return fail(kExitUsage, "--design %s gives the part's top only: this setup has the part upside down; give the "
                "design as an STL mesh", o.design.c_str());
  if (o.design_pgm && (f.turn[0] != 1 || f.turn[4] != 1))
    return fail(kExitUsage, "--design %s is stretched over the stock's box: under a quarter turn give the design as "
                "an STL mesh", o.design.c_str());
  return kExitOk;
}

// The tolerance boxes, the part's XY, in this setup's machine XY.
std::vector<ToleranceBox> boxes_in_frame(const std::vector<ToleranceBox>& given, const PartFrame& f) {
  std::vector<ToleranceBox> out;
  for (const ToleranceBox& b : given) {
    const PointNm p = part_frame_to_machine(f, PointNm{b.x0_nm, b.y0_nm, 0});
    const PointNm q = part_frame_to_machine(f, PointNm{b.x1_nm, b.y1_nm, 0});
    out.push_back(ToleranceBox{min_of(p.x_nm, q.x_nm), min_of(p.y_nm, q.y_nm), max_of(p.x_nm, q.x_nm),
                               max_of(p.y_nm, q.y_nm), b.tol_nm});
  }
  return out;
}

}  // namespace

int load_design(const JobOptions& o, const GridPlan& plan, const std::string& program, RunDesign* d,
                const PartFrame& frame) {
  d->file = program;
  const bool framed = !part_frame_is_identity(frame);
  if (framed && (o.demo_design || o.builtin || o.design_pgm))
    if (const int code = heights_in_frame(o, frame)) return code;
  // A column's axis in the part, and a part height back on the machine's Z.
  auto part_xy = [&frame](int64_t x, int64_t y) { return part_frame_to_part(frame, PointNm{x, y, 0}); };
  auto machine_z = [&frame](const PointNm& part_xy_point, int64_t z_part) {
    return part_frame_to_machine(frame, PointNm{part_xy_point.x_nm, part_xy_point.y_nm, z_part}).z_nm;
  };
  const size_t cells = static_cast<size_t>(plan.geo.nx) * static_cast<size_t>(plan.geo.ny);
  d->tops.assign(cells, kNoDesign);
  if (!ok(design_init(&d->grid, plan.geo, d->tops.data(), cells)))
    return fail(kExitUsage, "the grid is wider than %.2f m: --design needs a smaller stock",
                static_cast<double>(kDesignRangeNm) * 1e-9);
  // Only the stock's columns count (not the grid's ring of holes).
  d->opt.region = GridRect{1, 1, plan.stock_nx + 1, plan.stock_ny + 1};
  d->opt.tol_nm = o.tolerance_nm;
  d->boxes = boxes_in_frame(o.tolerance_boxes, frame);
  d->opt.boxes = d->boxes.data();
  d->opt.nboxes = d->boxes.size();
  d->report.file = o.design;
  d->report.kind = o.demo_design ? "demo" : o.builtin ? "builtin" : o.design_pgm ? "pgm" : "stl";
  d->report.tolerance_nm = o.tolerance_nm;
  d->report.tolerance_boxes = o.tolerance_boxes.size();
  std::string err;
  if (o.demo_design) {
    // The demo's part, sampled on every dexel axis (um).
    for (int32_t j = 0; j < plan.geo.ny; ++j)
      for (int32_t i = 0; i < plan.geo.nx; ++i) {
        const PointNm p = part_xy(plan.geo.x0_nm + i * plan.geo.pitch_nm, plan.geo.y0_nm + j * plan.geo.pitch_nm);
        int32_t z_um;
        if (demo_design_top_um(static_cast<int32_t>(div_round(p.x_nm, 1000)), static_cast<int32_t>(div_round(p.y_nm, 1000)),
                               &z_um))
          d->tops[d->grid.index(i, j)] =
              static_cast<int32_t>(div_round(machine_z(p, z_um * int64_t{1000}) - plan.geo.z0_nm, plan.geo.lsb_nm));
      }
  } else if (o.builtin) {
    // A built-in part (core/design/builtin.h): its height over each axis
    // that lies on the part (x and y from its first dexel's axis; its
    // block's top at Z0, as builtin_setup places it).
    const BuiltinDesign& b = *o.builtin;
    for (int32_t j = 0; j < plan.geo.ny; ++j)
      for (int32_t i = 0; i < plan.geo.nx; ++i) {
        const PointNm p = part_xy(plan.geo.x0_nm + i * plan.geo.pitch_nm, plan.geo.y0_nm + j * plan.geo.pitch_nm);
        const int64_t x = p.x_nm, y = p.y_nm;
        if (x < 0 || y < 0 || x > (b.nx - 1) * b.pitch_nm || y > (b.ny - 1) * b.pitch_nm) continue;
        // Heights from the block's bottom; the block's top is at Z0.
        const int64_t z = machine_z(p, b.height_nm(x, y) - b.stock_height_nm);
        d->tops[d->grid.index(i, j)] = static_cast<int32_t>(div_round(z - plan.geo.z0_nm, plan.geo.lsb_nm));
      }
  } else if (o.design_pgm) {
    PgmImage img;
    const PgmRead r = read_pgm(o.design, &img, &err);
    if (r != PgmRead::kOk) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return r == PgmRead::kIoError ? kExitIo : kExitInput;
    }
    // Stretched over the stock as given (not the grid's rounding up).
    const HeightImage h{img.samples.data(), img.width, img.height, img.maxval};
    const StockBox& s = plan.stock;
    // (A saved stock moved by an offset: the box moved with it; the heights move too.)
    const PointNm at{0, 0, 0};
    if (!ok(design_from_image(&d->grid, h, s.lo.x_nm, s.lo.y_nm, s.hi.x_nm, s.hi.y_nm, machine_z(at, o.design_z_nm[0]),
                              machine_z(at, o.design_z_nm[1]))))
      return fail(kExitUsage, "--design-z lies more than %.2f m from the stock's bottom",
                  static_cast<double>(kDesignRangeNm) * 1e-9);
  } else {
    const PointNm off{o.design_offset_nm[0], o.design_offset_nm[1], o.design_offset_nm[2]};
    StlReadInfo info;
    const StlRead r = stl_read(o.design, off,
                               [d, &frame](const PointNm* v, std::string* m) {
                                 // Turned with the part (exact: a setup's turn permutes and negates axes).
                                 const TriangleNm t{{part_frame_to_machine(frame, v[0]), part_frame_to_machine(frame, v[1]),
                                                     part_frame_to_machine(frame, v[2])}};
                                 if (ok(design_add_triangle(&d->grid, t))) return true;
                                 *m = "vertex more than 1.07 m from the stock's corner (see --design-offset)";
                                 return false;
                               },
                               &info, &err);
    if (r != StlRead::kOk) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return r == StlRead::kIoError ? kExitIo : kExitInput;
    }
    d->report.triangles = info.triangles;
  }
  if (design_columns(d->grid) == 0) {
    std::fprintf(stderr, "%s: error: the design lies entirely outside the stock%s\n", o.design.c_str(),
                 o.design_pgm ? "" : " (units are mm, machine coordinates; see --design-offset)");
    return kExitInput;
  }
  return kExitOk;
}

namespace {

// Prints the warnings of events [d->printed, end).
void print_events(const GougeWatch& w, const DexelGrid<height_t>& g, RunDesign* d, size_t end) {
  for (; d->printed < end; ++d->printed) {
    const GougeEvent& e = w.events[d->printed];
    const int64_t design_z = g.z0_nm + e.design_lsb * g.lsb_nm;
    std::fprintf(stderr, "%s:%u:1: warning: gouge %s mm at X%s Y%s (design Z%s, cut Z%s)\n", d->file.c_str(), e.line,
                 nm_to_mm_text(e.depth_lsb * g.lsb_nm, 3).c_str(), nm_to_mm_text(g.x0_nm + e.i * g.pitch_nm, 3).c_str(),
                 nm_to_mm_text(g.y0_nm + e.j * g.pitch_nm, 3).c_str(), nm_to_mm_text(design_z, 3).c_str(),
                 nm_to_mm_text(design_z - e.depth_lsb * g.lsb_nm, 3).c_str());
  }
}

}  // namespace

void gouges_after_record(const GougeWatch& w, const DexelGrid<height_t>& g, uint32_t line, bool found, RunDesign* d) {
  if (found) {
    d->marks.clear();
    for (size_t k = 0; k < w.nevents; ++k) {
      const GougeEvent& e = w.events[k];
      d->marks.push_back(gouge_mark_point(e, g));
    }
  }
  // Lines other than this record's are done (the previous line's end cap
  // came with this record).
  size_t done = d->printed;
  while (done < w.nevents && w.events[done].line != line) ++done;
  print_events(w, g, d, done);
}

void print_gouges(const GougeWatch& w, const DexelGrid<height_t>& g, RunDesign* d) { print_events(w, g, d, w.nevents); }

void assess_design(const GougeWatch& w, const DexelGrid<height_t>& g, RunDesign* d) {
  AssessResult& r = d->report.result;
  (void)assess(g, d->grid, d->opt, &r);  // same geometry by construction
  auto at = [&g](int32_t i, int32_t j) { return PointNm{g.x0_nm + i * g.pitch_nm, g.y0_nm + j * g.pitch_nm, 0}; };
  if (r.max_gouge_lsb > 0) d->report.max_gouge_at = at(r.max_gouge_i, r.max_gouge_j);
  if (r.max_leftover_lsb > 0) d->report.max_leftover_at = at(r.max_leftover_i, r.max_leftover_j);
  d->report.gouges_total = w.total;
  d->report.gouges.clear();
  for (size_t k = 0; k < w.nevents; ++k) {
    const GougeEvent& e = w.events[k];
    ReportGouge rg;
    rg.line = e.line;
    rg.at = PointNm{g.x0_nm + e.i * g.pitch_nm, g.y0_nm + e.j * g.pitch_nm, g.z0_nm + e.design_lsb * g.lsb_nm};
    rg.depth_nm = e.depth_lsb * g.lsb_nm;
    rg.tool = e.tool;
    rg.columns = e.columns;
    d->report.gouges.push_back(rg);
  }
}

bool overlay_image(const RunOptions& o, const GridPlan& plan, const RunDesign& d, RenderOutput* cut_view,
                   OverlayImage* ov, const FrameView** shown, std::string* err) {
  const size_t cells = static_cast<size_t>(plan.geo.nx) * static_cast<size_t>(plan.geo.ny);
  ov->top.assign(cells, 0);
  ov->bottom.assign(cells, 0);
  (void)grid_init(&ov->grid, plan.geo, ov->top.data(), ov->bottom.data(), cells);
  design_to_grid(d.grid, d.opt.region, &ov->grid);
  FrameView fb = cut_view->view();
  ov->pixels.assign(static_cast<size_t>(fb.height) * static_cast<size_t>(fb.stride_bytes / 4 + 1), 0);
  fb.pixels = ov->pixels.data();
  ov->out.reset(new RenderOutput());
  ov->out->set_antialias(cut_view->antialias());  // both scenes at one size
  if (!ov->out->init(ov->grid, fb, CameraChoice{}, err)) return false;
  // The design in a colour of its own: a one-class colour mode.
  ov->cls.assign(cells, 0);
  ov->lut.assign(kShadeLevels, 0);
  ov->colours.cls = ov->cls.data();
  ov->colours.luts = ov->lut.data();
  ov->colours.nclasses = 1;
  ov->colours.colour[0] = Rgb{80, 140, 230};
  ov->out->set_colours(&ov->colours);
  ov->out->share_view_of(*cut_view);
  ov->out->draw(&ov->grid, CutterPose{});
  if (o.view.overlay == ViewOptions::Overlay::kDesign) {
    (void)cut_view->blend(*ov->out);  // the same size and depth format by construction
    *shown = &cut_view->view();
  } else {
    (void)ov->out->blend(*cut_view);
    *shown = &ov->out->view();
  }
  return true;
}

void error_view_init(const DexelGrid<height_t>& g, RunDesign* d) {
  d->bands.assign(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny), kBandNone);
  d->luts.assign(static_cast<size_t>(kErrorBands) * kShadeLevels, 0);
  error_colours_init(&d->colours, g, d->grid, d->opt, d->bands.data(), d->luts.data());
  colour_legend_error(&d->legend, d->opt.tol_nm);
}

}  // namespace cli
}  // namespace dexmill
