// What `dexmill run` draws while it cuts; see run_views.h.
#include "tools/run/run_views.h"

#include "core/math/trig.h"
#include "core/tool/spec.h"
#include "platform/os/clock.h"
#include "platform/format/image_file.h"
#include "tools/cli/cli.h"
#include "tools/run/run_path.h"

namespace dexmill {
namespace cli {

bool RunViews::still(const RunOptions& o, std::vector<uint32_t>* pixels, std::unique_ptr<RenderOutput>* out) {
  // A still frame of its own at --size.
  pixels->assign(static_cast<size_t>(o.view.width) * static_cast<size_t>(o.view.height), 0);
  FrameView fb;
  fb.pixels = pixels->data();
  fb.width = o.view.width;
  fb.height = o.view.height;
  fb.stride_bytes = o.view.width * 4;
  fb.format = PixelFormat::kXrgb8888;
  out->reset(new RenderOutput());
  (*out)->set_antialias(o.view.stills_antialiased());
  std::string err;
  if ((*out)->init(sim_->grid(), fb, cam_, &err)) return true;
  fail(kExitUsage, "%s", err.c_str());
  return false;
}

// The colour mode of every output but the error view, and the error view's.
void RunViews::set_colours(const RunOptions& o, const Inputs& in) {
  const DexelGrid<height_t>& grid = sim_->grid();
  if (o.view.color == ViewOptions::Color::kError || error_out_) {
    error_view_init(grid, in.design);
    for (RenderOutput* out : outputs_) {
      if (out != error_out_.get() && o.view.color != ViewOptions::Color::kError) continue;
      out->set_colours(&in.design->colours.colours);
      out->set_legend(&in.design->legend);
    }
  }
  if (o.view.color == ViewOptions::Color::kMaterial) {
    material_cls_.assign(static_cast<size_t>(grid.nx) * static_cast<size_t>(grid.ny), 0);
    material_luts_.assign(static_cast<size_t>(kMaxColourClasses) * kShadeLevels, 0);
    material_colours_init(&material_colours_, grid, *in.material->comp, material_cls_.data(), material_luts_.data());
    // Textured; uncut tops tinted on a block stock (an STL blank's tops vary).
    material_texture_.assign((material_texture_bytes(grid) + 3) / 4, 0);
    material_colours_texture(&material_colours_, material_texture_.data(), in.top_lsb);
    for (RenderOutput* out : outputs_)
      if (out != error_out_.get()) out->set_colours(&material_colours_.colours);
  }
  // --color tool|slope|thin|engagement.
  run_colours_start(&colours_, o, grid, in.lib, sim_->provenance(), sim_->engage_classes(),
                    sim_->engage_by_limits());
  if (const SurfaceColours* c = colours_.colours())
    for (RenderOutput* out : outputs_)
      if (out != error_out_.get()) {
        out->set_colours(c);
        out->set_legend(&colours_.legend);
      }
}

namespace {

// What a click in the live window measures: the engine's grid, the lines
// (and programs: the chain's, then this one) the run keeps (a window's run
// keeps the lines: tools/run/run_setup.cpp), the design when given.
MeasureSource live_measure(Simulation* sim, const RunViews::Inputs& in, std::vector<StockProgram>* programs) {
  MeasureSource m;
  m.grid = &sim->grid();
  const StockColumns c = sim->stock_columns(kStockLayerLine | kStockLayerProgram);
  m.lines = c.line;
  m.programs = c.program;
  programs->clear();
  for (int32_t k = 0; in.chain && k < in.chain->nprograms; ++k) programs->push_back(in.chain->programs[k]);
  programs->push_back(StockProgram{});
  stock_name_set(programs->back().name, in.program_name.c_str());
  m.program_list = programs->data();
  m.nprograms = static_cast<int32_t>(programs->size());
  m.no_lines = "the run keeps no lines";
  if (in.design) m.design_top_lsb = in.design->grid.top_lsb;
  return m;
}

}  // namespace

int RunViews::open(const RunOptions& o, Simulation* sim, const Inputs& in) {
  sim_ = sim;
  in_ = in;
  DexelGrid<height_t>& grid = sim->grid();
  cam_.preset = o.view.preset;
  if (o.view.have_azimuth || o.view.have_elevation) {
    const Camera iso = camera_preset(ViewPreset::kIso);
    cam_.angles = true;
    cam_.azimuth_bam = o.view.have_azimuth ? bam_from_mdeg(o.view.azimuth_mdeg) : iso.azimuth_bam;
    cam_.elevation_bam = o.view.have_elevation ? static_cast<int32_t>(bam_from_mdeg(o.view.elevation_mdeg)) : iso.elevation_bam;
  }
  std::string err;
  is_live_ = o.view.window || !o.view.fbdev.empty();
  if (is_live_) {
    const int code = live_.open(o, grid, cam_, in.total_us, &err);
    if (code != kExitOk) return fail(code, "%s", err.c_str());
    live_.set_measure(live_measure(sim, in, &chain_programs_));
    outputs_.push_back(live_.output());
  }
  if (!o.out.frames_dir.empty()) {
    // With --frame-status the live views' status strip goes under the
    // picture, which keeps --size (as in the window).
    status_band_h_ = o.view.frame_status ? status_band_height(o.view.width) : 0;
    frames_.reset(new FrameFiles(o.out.frames_dir, o.out.frame_format, o.view.width, o.view.height + status_band_h_));
    FrameView picture = frames_->frame();
    picture.height = o.view.height;
    frames_out_.reset(new RenderOutput());
    // Each frame redraws what changed at twice the size and resolves those
    // rectangles on the renderer's tiles (display/view/stock_view.h), so a
    // partial redraw equals a full one.
    frames_out_->set_antialias(o.view.stills_antialiased());
    if (!frames_out_->init(grid, picture, cam_, &err)) return fail(kExitUsage, "%s", err.c_str());
    every_ = o.out.every ? static_cast<uint64_t>(o.out.every) : max_of<uint64_t>(1, (in.motion_moves + 99) / 100);
    outputs_.push_back(frames_out_.get());
  }
  // The final image is the frame of the live view or of the sequence when
  // there is one drawn as the still would be (the same pixels); else (an
  // aliased live view, or an --overlay that would change the live view's
  // picture) a frame of its own.
  image_src_ = is_live_ ? live_.output() : frames_out_.get();
  const bool own_still = image_src_ && (image_src_->antialias() != o.view.stills_antialiased() ||
                                        (is_live_ && o.view.overlay != ViewOptions::Overlay::kNone));
  if (!o.out.image.empty() && (!image_src_ || own_still)) {
    if (!still(o, &image_pixels_, &image_out_)) return kExitUsage;
    outputs_.push_back(image_out_.get());
    image_src_ = image_out_.get();
  }
  if (!o.out.error_image.empty()) {
    if (!still(o, &error_pixels_, &error_out_)) return kExitUsage;
    outputs_.push_back(error_out_.get());
  }
  for (RenderOutput* out : outputs_) {
    out->set_tool(o.job.tool);
    out->set_decorations(o.view.decorations);
  }
  hide_tool_ = o.view.hide_tool;
  set_colours(o, in);
  // The gouges and safety findings found so far, marked in every frame and
  // live view (display/api/run_marks.h); the fixtures in every frame.
  for (RenderOutput* out : outputs_) out->set_run_marks(&marks_, sim);
  if (!o.job.checks.fixtures.empty())
    for (RenderOutput* out : outputs_) out->set_fixtures(&o.job.checks.fixtures);
  grid.dirty = grid.bounds();
  changed(grid.dirty);
  grid.dirty = GridRect::none();
  count_path_ = in.path != nullptr;
  if (in.path)
    for (RenderOutput* out : outputs_) {
      out->set_path(in.path, &path_done_);
      out->set_path_visible(o.view.path_overlay);
    }
  if (is_live_) live_.set_before_draw([sim] { sim->sync(); });
  status.inch = o.job.read.inch;
  status.tool_spec = o.job.tool_text;
  sim->set_observer(this);
  return kExitOk;
}

void RunViews::tool_loaded(const Tool& t) {
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  status.tool_spec = spec;
  for (RenderOutput* o : outputs_) o->set_tool(t);
}

void RunViews::record(const CanonRecord& r) {
  run_colours_record(&colours_);
  if (count_path_) path_done_ += path_pieces(r);
  if (const GougeWatch* w = sim_->gouges()) {
    const bool found = sim_->gouge_finds() != gouge_finds_;
    gouge_finds_ = sim_->gouge_finds();
    gouges_after_record(*w, sim_->grid(), r.line, found, in_.design);
  }
  run_marks_record(&marks_, *sim_);
  const SimStatus& s = sim_->status();
  status.line = s.line;
  status.pos = s.pos;
  status.feed_nm_per_min = s.feed_nm_per_min;
  status.tool = s.tool;
  status.sim_us = s.sim_us;
}

void RunViews::changed(const GridRect& r) {
  for (RenderOutput* o : outputs_) o->note_dirty(r);
}

void RunViews::moved(uint64_t moves) {
  if (frames_ && moves % every_ == 0) write_frame();
}

bool RunViews::write_frame() {
  if (!frame_error.empty()) return false;
  sim_->sync();
  const double t0 = clock_now_s();
  const RenderResult res = frames_out_->draw(&sim_->grid(), CutterPose{true, sim_->mill().position()});
  if (status_band_h_ > 0) status_band_draw(frames_->frame(), status_band_h_, status_text(status, 0, false, false));
  const double t1 = clock_now_s();
  if (!frames_->present(res.rects, res.nrects)) frame_error = frames_->error();
  render_s += t1 - t0;
  write_s += clock_now_s() - t1;
  last_frame_moves = sim_->status().moves;
  return frame_error.empty();
}

void RunViews::after_cut(bool stopped_at_input_error) {
  if (const GougeWatch* w = sim_->gouges())  // what the finish found, and its warnings
    if (sim_->gouge_finds() != gouge_finds_) {
      gouge_finds_ = sim_->gouge_finds();
      gouges_after_record(*w, sim_->grid(), sim_->status().line, true, in_.design);
    }
  run_marks_after_cut(&marks_, *sim_, stopped_at_input_error);
}

int RunViews::write_images(const RunOptions& o, const GridPlan& plan, const ImageFormat& image, const ImageFormat& error) {
  char e[1300];
  // --hide-tool: the final stills without the cutter (a live view's
  // next frame shows it again).
  const CutterPose pose{!hide_tool_, sim_->mill().position()};
  DexelGrid<height_t>* grid = &sim_->grid();
  if (!o.out.image.empty()) {
    const double t0 = clock_now_s();
    RenderOutput* live_out = is_live_ ? live_.output() : nullptr;
    if (image_src_ != live_out || hide_tool_) image_src_->draw(grid, pose);
    const FrameView* shown = &image_src_->view();
    OverlayImage overlay;
    std::string err;
    if (o.view.overlay != ViewOptions::Overlay::kNone &&
        !overlay_image(o, plan, *in_.design, image_src_, &overlay, &shown, &err))
      return fail(kExitUsage, "%s", err.c_str());
    const double t1 = clock_now_s();
    render_s += t1 - t0;
    if (!write_frame_image(o.out.image.c_str(), image, *shown, e, sizeof e)) return fail(kExitIo, "%s", e);
    write_s += clock_now_s() - t1;
  }
  if (error_out_) {
    const double t0 = clock_now_s();
    error_out_->draw(grid, pose);
    const double t1 = clock_now_s();
    render_s += t1 - t0;
    if (!write_frame_image(o.out.error_image.c_str(), error, error_out_->view(), e, sizeof e)) return fail(kExitIo, "%s", e);
    write_s += clock_now_s() - t1;
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
