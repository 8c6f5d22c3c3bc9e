// The tools a program's own comments describe (core/tool/tool_comment.h),
// bound to the tools it loads, as the first pass reads it (core/sim/scan.h)
// and before anything is cut (core/sim/tool_choice.h decides whether a
// comment's tool is used):
//
//   - a comment that names its T number (Fusion's tool list, a tool table
//     row, CamBam's, Vectric's "1 = End Mill {6 mm}") describes that T,
//     wherever it stands (its units: those at the T's M6, or for a T no M6
//     loads, whose radius G41/G42 D may ask for, at the first move or
//     where the comment stands after it);
//   - a comment that names none (pcb2gcode's tool change message, Estlcam's
//     "Change tool:", Carbide Create's TOOL/MILL) describes the tool loaded
//     by the M6 it stands beside: on the M6's line, or between the move
//     before it and the M6 (pcb2gcode writes T1, M5, the message, then M6),
//     or, when none stands there, between the M6 and the move after it;
//     a weak one ((1/4 endmill), tool_comment.h) on the M6's line only;
//   - the tool in the spindle before any M6 (a program that never changes
//     tools) is the one the comments before its first cutting move
//     describe: that of the T selected then, or the one tool all those
//     comments describe, or else the last unnumbered one when it stands
//     alone (not in a list of several tools).
// Several comments that describe different tools where one is expected
// bind none (ambiguous); a second comment for a T that describes another
// tool is not used (a conflict). Both are counted, and the first of each
// kept, for a warning. Lengths without units are read in the program's
// units where the tool is loaded (the first cutting move for the tool
// before any M6).
//
// Fixed capacity, no heap: it lives in the scan, which a host runs.
#ifndef DEXMILL_CORE_SIM_COMMENT_TOOLS_H
#define DEXMILL_CORE_SIM_COMMENT_TOOLS_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/line_reader.h"
#include "core/canon/canon.h"
#include "core/tool/tool_comment.h"
#include "core/tool/tool.h"

namespace dexmill {

// The number the tool in the spindle before any M6 is listed under.
constexpr int32_t kSpindleToolNumber = -1;
// Tools comments can describe, by T number; later ones are not bound.
constexpr int kCommentToolsMax = 64;

struct CommentTool {
  int32_t number = kSpindleToolNumber;
  Tool tool{};
  uint32_t line = 0;  // of the comment
  ToolCommentForm form = ToolCommentForm::kNone;
};

class CommentTools {
 public:
  // A line of the program's file, the first time it is read, before the
  // interpreter runs it.
  void line(const char* text, size_t n, uint32_t line_no);
  // A record of that line; inch and selected: the units and T word in force.
  void record(const CanonRecord& r, bool inch, int32_t selected);
  // The end of the program: comments after its last M6 are bound.
  void finish();

  // The tool a comment gave T `number` (kSpindleToolNumber: the tool
  // before any M6); null when none did.
  const CommentTool* find(int32_t number) const;
  int count() const { return ntools_; }
  const CommentTool& at(int k) const { return tools_[k]; }

  // The first T whose comments disagreed (and the two lines), and how many.
  struct Doubt {
    uint32_t count = 0;
    int32_t number = 0;
    uint32_t line_a = 0, line_b = 0;
  };
  const Doubt& ambiguous() const { return ambiguous_; }
  const Doubt& conflicts() const { return conflicts_; }

 private:
  struct Note {
    ToolComment c;
    uint32_t line;
  };
  static constexpr int kPendingMax = 8;
  static constexpr int kLoadsMax = 64;

  void add_note(const Note& n);
  void bind(int32_t number, const Note& n, bool inch);
  void bind_pending(int32_t number, uint32_t change_line, bool inch);
  void decide_initial(bool inch, int32_t selected);
  const Note* numbered(int32_t number) const;
  static void doubt(Doubt* d, int32_t number, uint32_t a, uint32_t b);

  ToolCommentState state_{};
  Note numbered_[kCommentToolsMax];
  int nnumbered_ = 0;
  Note weak_{};                // the last weak one (tool_comment.h), for an M6 on its line
  Note pending_[kPendingMax];  // unnumbered, since the last move or M6 (the last kPendingMax)
  int npending_ = 0;
  bool pending_overflow_ = false;
  // Before the first cutting move, while no M6 has come: for the tool in the spindle.
  Note first_early_{}, last_unnumbered_{};
  int nearly_ = 0;
  bool early_same_ = true, have_unnumbered_ = false, unnumbered_in_list_ = false;
  uint32_t last_early_line_ = 0;
  Note last_early_{};
  bool initial_decided_ = false;
  uint32_t changes_ = 0;
  // The last M6 while its number waits for a comment after it.
  bool open_ = false;
  int32_t open_number_ = 0;
  uint32_t open_line_ = 0;
  bool open_inch_ = false;
  bool inch_ = false;   // the units at the last record
  bool moved_ = false;  // a move was made: numbered comments bind without their M6
  // Numbers loaded, and their units at the first load.
  int32_t load_number_[kLoadsMax];
  bool load_inch_[kLoadsMax];
  int nloads_ = 0;
  CommentTool tools_[kCommentToolsMax];
  int ntools_ = 0;
  Doubt ambiguous_, conflicts_;
};

// The program's lines to a CommentTools as they are first read (a loop
// that reads a line again, and subroutine files, are not shown), the rest
// passed through to the input underneath.
// Lines a tap shows besides the tools' (the scan's (WORKPIECE,...) comments).
class LineWatcher {
 public:
  virtual void line(const char* text, size_t n, uint32_t line_no) = 0;

 protected:
  ~LineWatcher() = default;
};

class CommentTap final : public LineInput {
 public:
  CommentTap(LineInput* in, CommentTools* tools, LineWatcher* also = nullptr) : in_(in), tools_(tools), also_(also) {}
  LineReader::Read next(const char** text, size_t* len, uint32_t* line_no) override;
  uint16_t file_index() const override { return in_->file_index(); }
  const char* name() const override { return in_->name(); }
  const char* program_name() const override { return in_->program_name(); }
  GcodeError not_text(char word[16]) const override { return in_->not_text(word); }
  SourcePos line_start() const override { return in_->line_start(); }
  SourcePos line_next() const override { return in_->line_next(); }
  bool seek(const SourcePos& p) override { return in_->seek(p); }
  bool open_subroutine(const char* name, SourcePos* start) override { return in_->open_subroutine(name, start); }

 private:
  LineInput* in_;
  CommentTools* tools_;
  LineWatcher* also_;
  uint32_t last_line_ = 0;
};

}  // namespace dexmill

#endif
