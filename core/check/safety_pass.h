// The cut with the safety checks watching it, as one CanonSink: records go
// to the Mill, then each is checked (core/check/safety.h) with the state it
// ran in: the interpreter's spindle, whether the tool's position is the
// program's yet, the tool in the spindle and its body (a tool change loads
// the library's). What a panel runs to preview a program before the machine
// does; `dexmill run` has the same steps in its own sink, with frames.
#ifndef DEXMILL_CORE_CHECK_SAFETY_PASS_H
#define DEXMILL_CORE_CHECK_SAFETY_PASS_H

#include "core/check/body.h"
#include "core/check/safety.h"
#include "core/cut/mill.h"
#include "core/motion/interp.h"

namespace dexmill {

template <class H>
class SafetyPass final : public CanonSink {
 public:
  // The watch is started (safety_watch_init) and its checks chosen by the
  // caller; `tool` is the Mill's tool before any M6.
  SafetyPass(Mill<H>* mill, DexelGrid<H>* g, SafetyWatch* w, const ToolLibrary* lib, const Tool& tool)
      : mill_(mill), g_(g), w_(w), lib_(lib) {
    load(tool);
  }
  // The interpreter that feeds this sink, for the spindle's state (null:
  // the spindle is taken to turn).
  void set_interp(const Interp* in) { interp_ = in; }

  void emit(const CanonRecord& r) override {
    const bool move = r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
    // Where the line before left the tool: a deferred end cap cut now is its.
    if (move && r.line != last_line_) {
      origin_ = SafetyOrigin{last_, mill_->position(), &profile_};
      have_origin_ = last_line_ != 0;
    }
    g_->dirty = GridRect::none();
    mill_->emit(r);
    SafetyMove m{r.line, r.kind == CanonKind::kTraverse, !interp_ || interp_->state().spindle_dir != 0, moved_};
    m.plunge = safety_is_plunge(r);
    m.end = r.end;
    m.body = &body_;
    safety_watch_record(w_, *g_, g_->dirty, r, m, have_origin_ ? &origin_ : nullptr);
    if (move) {
      last_ = m;
      moved_ = true;
      last_line_ = r.line;
    }
    Tool t;
    if (r.kind == CanonKind::kToolChange && lib_ && lib_->tool(r.tool, &t)) load(t);
  }
  // The end of the program: the last move's deferred end cap, checked.
  void finish() {
    g_->dirty = GridRect::none();
    mill_->finish();
    CanonRecord cap{};
    cap.kind = CanonKind::kDwell;
    cap.line = last_.line;
    safety_watch_record(w_, *g_, g_->dirty, cap, last_, nullptr);
  }

 private:
  void load(const Tool& t) {
    profile_ = tool_profile(t);
    tool_body_build(t, &body_);
    safety_watch_set_tool(w_, profile_);
  }

  Mill<H>* mill_;
  DexelGrid<H>* g_;
  SafetyWatch* w_;
  const ToolLibrary* lib_;
  const Interp* interp_ = nullptr;
  ToolProfile profile_{};
  ToolBody body_{};
  SafetyMove last_{};
  SafetyOrigin origin_{SafetyMove{}, PointNm{0, 0, 0}, nullptr};
  bool have_origin_ = false, moved_ = false;
  uint32_t last_line_ = 0;
};

}  // namespace dexmill

#endif
