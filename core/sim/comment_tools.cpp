// Tools from a program's comments, bound to its loads; see comment_tools.h.
#include "core/sim/comment_tools.h"

namespace dexmill {
namespace {

// The same tool described (the number and the form aside).
bool same_description(const ToolComment& a, const ToolComment& b) {
  return a.kind == b.kind && a.unit == b.unit && a.diameter_e9 == b.diameter_e9 && a.corner_e9 == b.corner_e9 &&
         a.tip_angle_mdeg == b.tip_angle_mdeg;
}

bool same_tool(const Tool& a, const Tool& b) {
  return a.kind == b.kind && a.diameter_nm == b.diameter_nm && a.corner_radius_nm == b.corner_radius_nm &&
         a.tip_angle_mdeg == b.tip_angle_mdeg;
}

// A move that goes somewhere (G1 F100 alone makes a feed record of no length).
bool moving(const CanonRecord& r) {
  if (r.kind == CanonKind::kArc) return true;
  if (r.kind != CanonKind::kTraverse && r.kind != CanonKind::kFeed) return false;
  return r.start.x_nm != r.end.x_nm || r.start.y_nm != r.end.y_nm || r.start.z_nm != r.end.z_nm;
}
bool cutting(const CanonRecord& r) { return r.kind != CanonKind::kTraverse && moving(r); }

}  // namespace

void CommentTools::doubt(Doubt* d, int32_t number, uint32_t a, uint32_t b) {
  if (d->count++ == 0) {
    d->number = number;
    d->line_a = a;
    d->line_b = b;
  }
}

const CommentTool* CommentTools::find(int32_t number) const {
  for (int k = 0; k < ntools_; ++k)
    if (tools_[k].number == number) return &tools_[k];
  return nullptr;
}

const CommentTools::Note* CommentTools::numbered(int32_t number) const {
  for (int k = 0; k < nnumbered_; ++k)
    if (numbered_[k].c.number == number) return &numbered_[k];
  return nullptr;
}

void CommentTools::bind(int32_t number, const Note& n, bool inch) {
  Tool t;
  if (!tool_comment_tool(n.c, inch, &t)) return;  // out of range: no tool
  if (const CommentTool* had = find(number)) {
    if (!same_tool(had->tool, t)) doubt(&conflicts_, number, had->line, n.line);
    return;
  }
  if (ntools_ == kCommentToolsMax) return;
  CommentTool& c = tools_[ntools_++];
  c.number = number;
  c.tool = t;
  c.line = n.line;
  c.form = n.c.form;
}

// The comments waiting beside an M6 (or the move after it): the one on
// the M6's line, or the one tool they all describe.
void CommentTools::bind_pending(int32_t number, uint32_t change_line, bool inch) {
  if (npending_ == 0) return;
  for (int k = npending_ - 1; k >= 0; --k)
    if (pending_[k].line == change_line) return bind(number, pending_[k], inch);
  for (int k = 1; k < npending_; ++k)
    if (!same_description(pending_[0].c, pending_[k].c)) return doubt(&ambiguous_, number, pending_[0].line, pending_[k].line);
  if (pending_overflow_) return doubt(&ambiguous_, number, pending_[0].line, pending_[npending_ - 1].line);
  bind(number, pending_[npending_ - 1], inch);
}

void CommentTools::add_note(const Note& n) {
  if (n.c.weak) {  // for an M6 on its line only
    weak_ = n;
    return;
  }
  if (n.c.number >= 0) {
    const Note* had = numbered(n.c.number);
    if (had) {
      if (!same_description(had->c, n.c)) doubt(&conflicts_, n.c.number, had->line, n.line);
    } else if (nnumbered_ < kCommentToolsMax) {
      numbered_[nnumbered_++] = n;
      // After the first move the units are known: a list there is bound
      // now (G41 D may ask for a tool no M6 loads).
      bool loaded = false;
      for (int k = 0; k < nloads_; ++k)
        if (load_number_[k] == n.c.number) loaded = true, bind(n.c.number, n, load_inch_[k]);
      if (!loaded && moved_) bind(n.c.number, n, inch_);
    }
  } else {
    if (npending_ == kPendingMax) {
      for (int k = 1; k < kPendingMax; ++k) pending_[k - 1] = pending_[k];
      --npending_;
      pending_overflow_ = true;
    }
    pending_[npending_++] = n;
  }
  if (changes_ > 0 || initial_decided_) return;
  if (nearly_++ == 0) first_early_ = n;
  else if (!same_description(first_early_.c, n.c)) early_same_ = false;
  if (n.c.number < 0) {
    // In a list: the line before it holds another tool (Estlcam's "Required tools:").
    unnumbered_in_list_ = last_early_line_ + 1 == n.line && !same_description(last_early_.c, n.c);
    last_unnumbered_ = n;
    have_unnumbered_ = true;
  }
  last_early_line_ = n.line;
  last_early_ = n;
}

void CommentTools::line(const char* text, size_t n, uint32_t line_no) {
  for (size_t i = 0; i < n; ++i) {
    size_t b = 0, e = 0;
    if (text[i] == '(') {
      b = i + 1;
      e = b;
      while (e < n && text[e] != ')') ++e;
      i = e;
    } else if (text[i] == ';') {
      b = i + 1;
      e = n;
      i = n;
    } else {
      continue;
    }
    Note note;
    note.line = line_no;
    if (tool_comment_read(text + b, e - b, &state_, &note.c)) add_note(note);
  }
}

void CommentTools::decide_initial(bool inch, int32_t selected) {
  initial_decided_ = true;
  if (selected > 0) {
    if (const Note* n = numbered(selected)) return bind(kSpindleToolNumber, *n, inch);
  }
  if (nearly_ == 0) return;
  if (early_same_) return bind(kSpindleToolNumber, first_early_, inch);
  if (have_unnumbered_ && !unnumbered_in_list_) return bind(kSpindleToolNumber, last_unnumbered_, inch);
  doubt(&ambiguous_, kSpindleToolNumber, first_early_.line, last_early_.line);
}

void CommentTools::record(const CanonRecord& r, bool inch, int32_t selected) {
  inch_ = inch;
  if (r.kind == CanonKind::kToolChange) {
    ++changes_;
    bool known = false;
    for (int k = 0; k < nloads_; ++k) known = known || load_number_[k] == r.tool;
    if (!known && nloads_ < kLoadsMax) {
      load_number_[nloads_] = r.tool;
      load_inch_[nloads_++] = inch;
    }
    if (!find(r.tool)) {
      if (const Note* n = numbered(r.tool)) bind(r.tool, *n, inch);
      else bind_pending(r.tool, r.line, inch);
    }
    if (!find(r.tool) && weak_.line == r.line) bind(r.tool, weak_, inch);
    npending_ = 0;
    pending_overflow_ = false;
    open_ = !find(r.tool);
    open_number_ = r.tool;
    open_line_ = r.line;
    open_inch_ = inch;
    return;
  }
  if (!moving(r)) return;
  if (open_) bind_pending(open_number_, open_line_, open_inch_);
  if (!moved_) {  // the tools a list names that no M6 has loaded yet, for G41/G42 D
    moved_ = true;
    for (int k = 0; k < nnumbered_; ++k)
      if (!find(numbered_[k].c.number)) bind(numbered_[k].c.number, numbered_[k], inch);
  }
  open_ = false;
  npending_ = 0;
  pending_overflow_ = false;
  if (cutting(r) && changes_ == 0 && !initial_decided_) decide_initial(inch, selected);
}

void CommentTools::finish() {
  if (open_) bind_pending(open_number_, open_line_, open_inch_);
  open_ = false;
  npending_ = 0;
}

LineReader::Read CommentTap::next(const char** text, size_t* len, uint32_t* line_no) {
  const LineReader::Read r = in_->next(text, len, line_no);
  if (r == LineReader::Read::kLine && in_->file_index() == 0 && *line_no > last_line_) {
    last_line_ = *line_no;
    if (tools_) tools_->line(*text, *len, *line_no);
    if (also_) also_->line(*text, *len, *line_no);
  }
  return r;
}

}  // namespace dexmill
