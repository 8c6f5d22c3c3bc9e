// The cutting stage (core/README.md "The pipeline": motion -> cut -> grid): a CanonSink
// that cuts every traverse, feed and arc into the dexel grid with the tool in
// the spindle, by instances of motion (stamp, the paper's §2.3) or by exact
// swept envelopes (sweep, core/cut/sweep.h). Tool changes (M6) switch cutters
// through a ToolLibrary the caller provides. No heap: the stamp cutter's
// dexel set lives in caller memory.
//
// Rapid traverses cut too: a simulator must show a crash through the stock,
// not hide it. Arcs: sweep mode cuts them with sweep_arc (exact for level XY
// arcs with ball and flat ends, else 1 um chords); stamp mode places
// instances along chords of sagitta <= kArcChordSagittaNm (1 um), so the path
// stays within 1 um + 7 nm of the exact arc (core/canon/arc_chords.h).
#ifndef DEXMILL_CORE_CUT_MILL_H
#define DEXMILL_CORE_CUT_MILL_H

#include <stddef.h>
#include <stdint.h>

#include "core/cut/stats.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/canon/canon.h"
#include "core/status.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class CutMode : uint8_t { kSweep = 0, kStamp = 1 };

// Maps tool numbers (T words) to shapes.
class ToolLibrary {
 public:
  // The tool numbered `number`; false if there is none.
  virtual bool tool(int32_t number, Tool* out) const = 0;

 protected:
  ~ToolLibrary() = default;
};

template <class H>
class Mill : public CanonSink {
 public:
  // `words` is memory for the stamp cutter (cutter_storage_words of the
  // largest tool's reach); unused in sweep mode (may be null).
  Mill(DexelGrid<H>* grid, CutMode mode, const ToolLibrary* tools, int32_t* words, size_t nwords);

  // Selects the tool to cut with before any M6 (e.g. the --tool default).
  Status set_tool(const Tool& t);

  void emit(const CanonRecord& r) override;

  // Makes the grid show everything cut so far: call it before reading the
  // grid (a frame, a live view, the end). Sweep mode defers the end cap of
  // the last straight move until the next move shows how much of it is
  // needed (core/cut/sweep.h, SweepChain); flush cuts that cap whole.
  //
  // What is finally cut does not depend on when or how often flush is
  // called. The chain cuts only the wedge of the cap that the
  // next move needs, with heights in that move's frame, and leaves out the
  // columns where the moves' bands are lower in exact arithmetic; in
  // integers the whole cap and the bands there round apart by an LSB at a
  // few dexels. So flush cuts the cap over a saved copy of the dexels under
  // it (mill_words of caller memory) and puts them back before the next
  // record that cuts, which then goes on as if there had been no flush.
  // With less memory than that it cuts the cap for good, as finish() does
  // (the final grid may then differ by an LSB at a few dexels). Cheap when
  // nothing is pending.
  void flush();

  // Ends the chain for good, as a program end (M2/M30) and a tool change do
  // by themselves: the pending cap is cut, a shown one again (its dexels
  // marked changed once more, for readers of the grid's changes that skip
  // what flush shows). For a program that ends without M2.
  void finish();

  // First failure (a tool the library lacks, a tool too large for the
  // stamp memory); cutting goes on with the previous tool.
  Status status() const { return status_; }
  int32_t failed_tool() const { return failed_tool_; }
  const CutStats& stats() const { return stats_; }
  const Tool& tool() const { return tool_; }
  // The tool tip after the last record.
  PointNm position() const { return last_; }

  // Off: every move is cut as given, even one that cuts nothing new (the
  // reference the tests compare the skips of cut_line with).
  void set_skip_covered(bool on) { skip_covered_ = on; }

 private:
  void cut_line(PointNm a, PointNm b);
  // Puts back the dexels flush saved (and the counts), if it showed a cap.
  void unshow();
  void end_chain();

  DexelGrid<H>* grid_;
  CutMode mode_;
  const ToolLibrary* tools_;
  int32_t* words_;
  size_t nwords_;
  Tool tool_;
  bool have_tool_ = false;
  CutterDexels cutter_;
  SweepTool sweep_;
  CutStats stats_;
  Status status_ = Status::kOk;
  int32_t failed_tool_ = -1;
  PointNm last_{0, 0, 0};
  bool chained_ = false;  // stamp: the next move starts where the last cut ended
  // The vertical span the tool has swept at last_'s X and Y since it came
  // there (cut_line: a vertical move within it cuts nothing new).
  bool skip_covered_ = true;
  int64_t covered_z_lo_nm_ = 0, covered_z_hi_nm_ = 0;
  SweepChain chain_;      // sweep: the polyline so far
  // flush: the box of dexels (exclusive bounds) saved in words_ before it
  // cut the pending cap, and what else the cut may change.
  bool shown_ = false;
  GridRect shown_box_ = GridRect::none();
  CutStats shown_stats_;
  bool shown_bottoms_zero_ = false;
};

// Words of caller memory a Mill<H> on grid g wants for a tool: in stamp mode
// the cutter's dexel set (core/tool/cutter.h), in sweep mode room to save the
// dexels under the tool standing at one point (Mill::flush).
template <class H>
size_t mill_words(CutMode mode, const ToolProfile& p, const DexelGrid<H>& g);

extern template class Mill<uint8_t>;
extern template class Mill<uint16_t>;
extern template class Mill<uint32_t>;

}  // namespace dexmill

#endif
