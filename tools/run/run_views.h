// What `dexmill run` draws while the simulation cuts: the frame sequence,
// the final and error images, a live window or framebuffer, each a
// RenderOutput (tools/run/run_render.h) fed the grid's changes; the colour
// mode, the legend, the marks (gouges red, safety findings magenta) and the
// fixtures they share. RunViews is the simulation's observer
// (core/sim/simulation.h SimObserver): it writes a frame every N moves,
// prints gouges as their lines end and keeps the marks up to date.
#ifndef DEXMILL_TOOLS_RUN_RUN_VIEWS_H
#define DEXMILL_TOOLS_RUN_RUN_VIEWS_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/simulation.h"
#include "display/overlay/backplot.h"
#include "display/colour/material_colours.h"
#include "platform/live/frame_files.h"
#include "tools/run/run_assess.h"
#include "tools/run/run_colours.h"
#include "tools/run/run_live.h"
#include "tools/run/run_material.h"
#include "tools/run/run_options.h"
#include "tools/run/run_render.h"
#include "tools/run/run_safety.h"

namespace dexmill {
namespace cli {

class RunViews final : public SimObserver {
 public:
  // What the views draw with, beside the options.
  struct Inputs {
    const ToolLibrary* lib = nullptr;
    RunDesign* design = nullptr;           // null: no design
    const RunMaterial* material = nullptr;  // null: no --material
    const std::vector<PathSegment>* path = nullptr;  // the backplot's (null: none)
    uint64_t motion_moves = 0;             // the program's, for the frames' default cadence
    int64_t total_us = 0;                  // its time, for a live view's pace
    uint32_t top_lsb = 0;                  // the block's top (an STL blank's: 0), for textured tops
    const StockMeta* chain = nullptr;      // a --stock's header: the chain's earlier programs (null: none)
    std::string program_name;              // this program as a saved stock names it
  };
  RunViews() = default;
  RunViews(const RunViews&) = delete;
  RunViews& operator=(const RunViews&) = delete;

  // Sets every output the options ask for up over the simulation's grid
  // (as stocked) and hands them the whole grid. kExitOk, or the exit code
  // with the message printed.
  int open(const RunOptions& o, Simulation* sim, const Inputs& in);

  // SimObserver.
  void tool_loaded(const Tool& t) override;
  void record(const CanonRecord& r) override;
  void changed(const GridRect& r) override;
  void moved(uint64_t moves) override;

  // A frame of the sequence now (the untouched stock, the last); false (and
  // frame_error set) on failure.
  bool write_frame();
  // After the cut: the marks of what the end found, the bad block's place
  // (amber: the cut stopped at an input error) and the finding a stop was
  // at (red; display/api/run_marks.h).
  void after_cut(bool stopped_at_input_error);
  // The final image and error image, with --overlay (--hide-tool: without
  // the cutter). kExitOk or an exit code (printed).
  int write_images(const RunOptions& o, const GridPlan& plan, const ImageFormat& image, const ImageFormat& error);

  bool live() const { return is_live_; }
  LiveView& live_view() { return live_; }
  bool has_frames() const { return frames_ != nullptr; }
  uint32_t frames_written() const { return frames_ ? frames_->written() : 0; }
  LiveStatus status;         // the status line's
  std::string frame_error;
  double render_s = 0, write_s = 0;
  uint64_t last_frame_moves = 0;

 private:
  bool still(const RunOptions& o, std::vector<uint32_t>* pixels, std::unique_ptr<RenderOutput>* out);
  void set_colours(const RunOptions& o, const Inputs& in);

  Simulation* sim_ = nullptr;
  Inputs in_;
  std::vector<RenderOutput*> outputs_;
  CameraChoice cam_;
  std::unique_ptr<FrameFiles> frames_;
  std::unique_ptr<RenderOutput> frames_out_, image_out_, error_out_;
  std::vector<uint32_t> image_pixels_, error_pixels_;
  uint64_t every_ = 0;
  int32_t status_band_h_ = 0;  // --frame-status: the strip under each frame's picture
  bool hide_tool_ = false;
  LiveView live_;
  bool is_live_ = false;
  RenderOutput* image_src_ = nullptr;
  MaterialColours<height_t> material_colours_;
  std::vector<uint8_t> material_cls_;
  std::vector<uint32_t> material_luts_, material_texture_;
  RunColours colours_;
  RunMarks marks_;
  uint64_t gouge_finds_ = 0;
  bool count_path_ = false;
  uint32_t path_done_ = 0;   // the backplot's pieces cut so far
  std::vector<StockProgram> chain_programs_;  // the chain's programs and this one, for a click's measurement
};

}  // namespace cli
}  // namespace dexmill

#endif
