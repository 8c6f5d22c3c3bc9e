// The RS274/NGC interpreter: streaming, integer-only, no heap, no I/O.
//
// Feed it one line at a time; it emits canonical records (core/canon/canon.h) to
// a CanonSink and returns an error code for a bad line. Each block is read,
// checked completely, then committed (core/README.md, habit 3): a block with an
// error emits nothing and changes nothing, so the caller may report it and
// go on with the next line (`dexmill check`) or stop (`dexmill path`, `run`).
//
// Frames: positions in records are the controlled point in machine
// coordinates with work offsets (G54..G59.3, G10) and G92 applied, and the
// tool length offset NOT applied (it is carried in every record instead).
// This is LinuxCNC's canonical position plus its G5x and G92 offsets: the
// tool tip when the tool is as long as its offset says, i.e. the machine
// (spindle) position minus the offset. So G53 Z0 puts the tip at Z = -TLO,
// and a change of offset (G43, G49) moves the point without a move. The
// program starts at the machine origin (0, 0, 0), in mm (G21) unless
// InterpOptions says inch, G17, G90, G91.1, G94, G54, G40, G49, G80, G99
// (LinuxCNC's interpreter's own start: its init sets the R-plane retract).
//
// Limits (checked where numbers come in; "number too large" or "position
// beyond the +-10 m range", never wrap-around):
//   every length word and every resulting position: |v| <= 10 m (1e10 nm),
//   except arc centres (I, J, K, absolute or not) and R: <= 100 m;
//   F <= 1e9 units/min and S <= 1e9 rpm (LinuxCNC takes any: above 1e6 mm/min
//   or 1e6 rpm a program gets one warning); G4 P <= 1e6 s; L <= 1e6 repeats;
//   arc P (turns) <= 10000; T, H <= 1e9 (integers >= 0).
#ifndef DEXMILL_CORE_INTERP_INTERP_H
#define DEXMILL_CORE_INTERP_INTERP_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/gcode/params.h"
#include "core/math/decimal.h"
#include "core/gcode/source.h"
#include "core/canon/canon.h"
#include "core/interp/oword_store.h"
#include "core/interp/cutter_comp.h"
#include "core/interp/modal_context.h"
#include "core/interp/nurbs.h"
#include "core/interp/rotation.h"
#include "core/interp/units_guess.h"
#include "core/point.h"

namespace dexmill {

constexpr int64_t kGcodeMaxCoordNm = 10000000000;  // 10 m
// Arc centres (I, J, K) and radii (R) may lie further out: CAM programs
// write nearly straight arcs with centres tens of metres away.
constexpr int64_t kGcodeMaxArcNm = 100000000000;   // 100 m

// Tool lengths for G43 H and radii for G41/G42 D (the consumer's tool
// table; none: every length 0, every radius 0 with a warning).
class ToolTable {
 public:
  // Length offset (Z) of tool `tool`, nm; false if the table has no such tool.
  virtual bool tool_length_nm(int32_t tool, int64_t* z_nm) const = 0;
  // Radius of tool `tool` (half its diameter, LinuxCNC's D column), nm;
  // false if the table has no such tool.
  virtual bool tool_radius_nm(int32_t tool, int64_t* r_nm) const = 0;

 protected:
  ~ToolTable() = default;
};

// Where a probe move (G38.2-G38.5) stops, asked of whoever has the stock
// (core/sim/simulation.h; the interpreter alone has none): the tool from
// `from` towards `to` (record frame: machine, tip), motion 382..385.
enum class ProbeSense : uint8_t { kTripped, kNoContact, kAlreadyTripped };
class ProbeSensor {
 public:
  virtual ProbeSense sense(const PointNm& from, const PointNm& to, int motion, PointNm* stop) = 0;

 protected:
  ~ProbeSensor() = default;
};

struct InterpOptions {
  bool inch = false;                  // units before any G20/G21
  // The caller chose `inch` (a --units option): a program that sets no
  // units before its first move is not warned of. Otherwise it is, once at
  // that move, and again at the end when it never sets them, the default
  // is mm and its numbers look like inches (core/interp/units_guess.h).
  bool units_given = false;
  // F on a line that also says G20/G21 is read in the line's units, as
  // grbl reads it; otherwise in the units before the line, as RS274/NGC and
  // LinuxCNC do (core/interp/interp_modes.cpp), with a warning.
  bool feed_in_line_units = false;
  const ToolTable* tools = nullptr;   // for G43 H; null: lengths are 0
  GcodeDiagSink* warnings = nullptr;  // null: warnings are dropped
  // Parameters and expressions: caller memory (about 57 KB,
  // core/gcode/params.h), cleared at reset. Null: a program that uses them
  // is refused as not supported (a panel without the memory).
  ParamStore* params = nullptr;
  GcodeMessageSink* messages = nullptr;  // DEBUG/PRINT/MSG comments; null: dropped
  // A controller's default feed (nm/min) for feed moves made while no F is
  // in force (before the first F, after G93/G94 cleared it); 0: none, such a
  // move is an error as in LinuxCNC. One warning, at the first such move.
  int64_t default_feed_nm_per_min = 0;
  // O-word control flow: caller memory (oword_store.h, about
  // 11 KB; needs `params` too), cleared at reset. Null: o-words are refused
  // as not supported.
  OwordStore* control = nullptr;
  // The program, for loops and calls to read again (core/gcode/source.h):
  // the lines given to execute_line are this source's. Null: if/else and
  // definitions still work; a loop or a call is an error.
  GcodeSource* source = nullptr;
  // Blocks a program may run once a loop or call went back (an endless
  // loop stops with an error naming it); 0: no limit.
  uint64_t max_blocks = kDefaultMaxBlocks;
  // Sagitta of the chords G5/G5.1 splines become (core/interp/spline.h).
  int64_t spline_sagitta_nm = 1000;
  // Where the machine is when the program starts: the tool tip (machine,
  // nm) and the tool in the spindle, as a previous program on the same
  // stock left them (core/stock/stock_file.h). Otherwise the program
  // starts at the origin with tool 0, as LinuxCNC's interpreter does.
  // Probe moves stop where this says (null: at their end point, with a
  // warning, as a preview that has no stock must).
  ProbeSensor* probe = nullptr;
  // The origins of G54..G59.3 (9 of them, machine nm) at the start, as a
  // controller's parameter file (#5221...) gives them. Null: all 0.
  const PointNm* work_offsets = nullptr;
  // And what else a controller holds when the program starts (LinuxCNC's
  // #5220 and #5211-#5213 in its parameter file, grbl's $# TLO): the
  // coordinate system in force (0 = G54), the G92 offset, a G43.1 tool
  // length offset. Zero: none, as LinuxCNC's interpreter starts.
  uint8_t start_coord_system = 0;
  PointNm start_g92{0, 0, 0};
  int64_t start_tlo_nm = 0;
  bool start_given = false;
  PointNm start_pos{0, 0, 0};
  int32_t start_tool = 0;
};

// The modal machine state; plain data, copied whole to make a block atomic.
struct InterpState {
  PointNm pos;              // controlled point, path frame (see above), nm
  // Where the tool really is, minus pos: zero except after a cycle that
  // leaves it elsewhere than LinuxCNC's interpreter reckons (G88 at the
  // bottom, G74/G84 in G18/G19; cycles.h). The next move starts there.
  PointNm stray;
  int16_t motion;           // modal motion code in tenths (G0 = 0 ... G89 = 890; G80 = 800)
  Plane plane;
  bool inch;                // G20
  bool incremental;         // G91
  bool diameter_x;          // G7 (lathe diameter mode): LinuxCNC halves every X word, on a mill too
  bool arc_absolute;        // G90.1
  bool inverse_time;        // G93
  bool per_rev;             // G95: feed_nm_per_min is per spindle revolution
  bool retract_to_r;        // G99
  uint8_t coord_system;     // 0..8 = G54, G55, ..., G59, G59.1, G59.2, G59.3
  int16_t path_mode;        // G61 = 610, G61.1 = 611, G64 = 640
  int32_t path_tolerance_nm;  // G64 P, nm (0: none given; G61 and G61.1 set 0; held to 2^31 - 1)
  int64_t feed_nm_per_min;  // F in G94 (0 = never set)
  int32_t spindle_rpm;      // S, >= 0
  int8_t spindle_dir;       // M3 +1, M4 -1, M5 0
  uint8_t coolant;          // bit 0 mist (M7), bit 1 flood (M8)
  int32_t tool;             // in the spindle (after M6)
  int32_t selected_tool;    // T
  int64_t tlo_nm;           // G43/G43.1 Z offset in force (0 after G49)
  PointNm work_offset[9];   // G54..G59.3, machine frame, nm
  int64_t rotation_deg_e9[9];  // G10 L2 R: each system's XY rotation about its origin (rotation.h)
  PointNm g92;              // G92 offset in force
  PointNm g92_saved;        // G92 offset kept by G92.2 for G92.3
  PointNm g28_home, g30_home;  // machine positions stored by G28.1/G30.1
  // Canned cycles (RS274/NGC: R and Z are sticky while the cycle repeats).
  bool cycle_level_set;     // the initial level (G98) is remembered
  int64_t cycle_level_nm;   // that level on the plane's axis, program frame (LinuxCNC's cycle_il)
  int64_t cycle_level_path_nm;  // the same in the path frame when last used (to tell when offsets moved it)
  int64_t cycle_r_nm, cycle_z_nm, cycle_q_nm;  // last R, Z, Q as written (nm)
  int64_t cycle_p_ms;       // last P (dwell) of G74/G82/G84/G86/G88/G89
  int64_t cycle_ijk_nm[3];  // last I, J, K of G87 as written (nm)
  PointNm probe_prog;       // the last probe move's end, program frame at the time (#5061-#5063)
  bool probed;              // a probe move tripped (#5070)
  CompState comp;           // cutter radius compensation (cutter_comp.h); pos is the compensated point
  bool ended;               // after M2/M30 or a closing %
  bool percent_open;        // a first % line was seen
};

class Interp {
 public:
  Interp(CanonSink* sink, const InterpOptions& options);

  // Back to the start-of-program state (machine origin, defaults).
  void reset();

  // Interprets one line (no line end; a trailing '\r' is fine). `line` is
  // 1-based. Returns kOk, or an error with *diag filled in (code, line, col
  // of the offending word, follow_on); then nothing was emitted and no state
  // changed. diag->follow_on marks an error that may be only a consequence
  // of an earlier bad block (the rule: core/interp/interp_follow_on.cpp);
  // the first error of a program never is one.
  // Warnings go to options.warnings. After the program ended (M2, M30, %),
  // further lines are ignored (one warning if they hold words).
  [[nodiscard]] GcodeError execute_line(const char* text, size_t len, uint32_t line, GcodeDiag* diag);

  // The reader could not give the next line (it was over-long): what it
  // held is unknown, so every later error that reads the state may be its
  // consequence (interp_follow_on.cpp).
  void line_not_read();

  // The input has no more lines; `last_line` is the number of the last one
  // (0 for none). Warns where LinuxCNC would refuse the file ("File ended
  // with no percent sign or program end": a half-uploaded file ends like
  // that), and when the program is empty or makes no move. The last two
  // only when no block failed (a failed block's moves are unknown).
  // An error when the input ended in the middle of o-word control flow (an
  // if with no endif, a call of a subroutine never found), *diag filled in
  // (when not null).
  GcodeError end_of_input(uint32_t last_line, GcodeDiag* diag = nullptr);
  // Probe moves (G38.2-G38.5) read so far.
  uint32_t probe_moves() const { return probe_moves_; }

  // The source the lines come from (InterpOptions::source), for a driver
  // that opens it after the interpreter was made.
  void set_source(GcodeSource* src) { options_.source = src; }

  bool ended() const { return state_.ended; }
  const InterpState& state() const { return state_; }
  PointNm position() const { return state_.pos; }
  // Records emitted so far (moves and others).
  uint64_t records_emitted() const { return records_; }
  // Whether a G20/G21 has run; what can be said of the units so far (the
  // end of the input gives the verdict on the whole program).
  bool units_set() const { return units_set_; }
  UnitsVerdict units_verdict() const;
  const UnitsEvidence& units_evidence() const { return units_ev_; }
  // After the first T word: whether a G20/G21 ran before it (or in its
  // block), and the units then in force.
  bool tool_named() const { return tool_named_; }
  bool units_set_at_tool() const { return units_at_tool_; }
  bool inch_at_tool() const { return inch_at_tool_; }

 private:
  // Emits a record, or holds it behind the moves cutter compensation holds.
  void emit(CanonRecord* r) {
    if (comp_q_.n) {
      (void)comp_q_.push(*r, r->start, 0, 0, 0);  // room was checked with the block
      return;
    }
    emit_now(r);
  }
  void emit_now(CanonRecord* r);
  void warn(GcodeError code, uint32_t line, uint16_t col, const char* word, int64_t a_nm = 0, int64_t b_nm = 0);
  // The interpreter's own parameters (core/interp/interp_params.cpp).
  static bool read_param(const void* ctx, int32_t n, const char* name, GValue* out);
  // O-word control flow (core/interp/interp_oword.cpp).
  bool oword_skipping() const {
    const OwordStore* c = options_.control;
    return c && (c->skip_label >= 0 || c->skip_sub[0]);
  }
  GcodeError run_oword(const char* text, size_t len, uint32_t line, GcodeDiag* d);
  GcodeError oword_unclosed(GcodeDiag* d) const;

  CanonSink* sink_;
  InterpOptions options_;
  InterpState state_;
  uint64_t records_ = 0;
  uint64_t moves_ = 0;        // moves that go somewhere (for the no-motion warning)
  uint32_t probe_moves_ = 0;  // G38.2-G38.5 blocks read (a front end without a stock says so)
  bool any_code_ = false;     // a line held code (an error counts)
  bool any_failed_ = false;   // a block failed
  uint16_t suspect_ = 0;      // facets of the state that may not be what the program meant (Facet)
  bool warned_after_end_ = false;
  bool sub_after_end_ = false;  // in a subroutine defined after the end (for calls made before it)
  uint16_t warned_once_ = 0;   // WarnOnce bits: warnings given once a program
  // Units (units_guess.h): set by the program; its first move made before
  // they were (0: none), and what its moves until then look like.
  bool units_set_ = false;
  uint32_t unset_move_line_ = 0;
  uint16_t unset_move_col_ = 0;
  UnitsEvidence units_ev_;
  bool tool_named_ = false, units_at_tool_ = false, inch_at_tool_ = false;
  bool feed_written_ = false;  // the F in force is the program's (not InterpOptions::default_feed's)
  // Records cutter compensation holds (LinuxCNC's interp_queue), and a
  // scratch copy a block is checked against before it commits.
  CompQueue comp_q_;
  CompQueue comp_scratch_;
  // G5.2's control points (nurbs.h), kept from block to block until G5.3.
  NurbsCurve nurbs_;
  // M70/M73's saved modal state, one per call level (modal_context.h).
  ModalContext contexts_[kOwordLevels];
  int context_level() const { return options_.control ? options_.control->level : 0; }
  // The point p of state `from`'s frame in state `to`'s (rotation.h): the
  // same machine point when the rotation or the origin in force changed.
  static PointNm reframe(const InterpState& from, const InterpState& to, const PointNm& p);
  // reframe for the tool standing in s (pos and stray) into coordinate system cs.
  static void reframe_tool(InterpState* s, const InterpState& from);
  // Whether any work system is turned (a G54-G59.3 switch may then move the point).
  bool rotation_any() const {
    for (int64_t r : state_.rotation_deg_e9)
      if (r != 0) return true;
    return false;
  }
  // A subroutine returns from `level` (endsub, return, M99): M73's state
  // comes back, and the level's context is forgotten.
  GcodeError context_return(int level, uint32_t line, uint16_t col, GcodeDiag* d);

  friend struct BlockRunner;
};

// Runs a whole program held in memory (a panel keeps it in flash): the
// lines of `src` (core/gcode/source.h), numbered from 1, which becomes the
// interpreter's source (for loops and calls). Returns the number of
// lines in error, follow-ons included (each skipped, as `dexmill check`
// does); *first gets the first error when not null. Ends with end_of_input.
uint32_t interp_run_source(Interp* in, MemorySource* src, GcodeDiag* first);
// The same over text[0, len).
uint32_t interp_run_text(Interp* in, const char* text, size_t len, GcodeDiag* first);

}  // namespace dexmill

#endif
