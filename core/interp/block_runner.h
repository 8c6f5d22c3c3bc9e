// The interpreter's block runner, shared by the files that implement it
// (not a public header: embedders read core/interp/interp.h). A block is
// checked against a copy of the state (BlockRunner::run and the run_*
// steps), then committed (BlockRunner::commit), so a bad block changes
// nothing (core/README.md, habit 3). The steps live by phase, after LinuxCNC's
// interp_convert: interp.cpp (order of execution, unused words, commit),
// interp_modes.cpp (modal groups, G4, G10/G28/G30/G92), interp_moves.cpp
// (G0/G1, G2/G3, G38.x), interp_cycles.cpp (canned cycles).
//
// Its parts by concept: block_limits.h (the numbers' bounds), block_axes.h
// (axes, planes, rotated frames), warn_once.h, follow_on.h (facets of the
// state, for follow-on errors), block_plan.h (Plan, CompOps), cycle_words.h.
#ifndef DEXMILL_CORE_INTERP_BLOCK_RUNNER_H
#define DEXMILL_CORE_INTERP_BLOCK_RUNNER_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/interp/block_axes.h"
#include "core/interp/block_limits.h"
#include "core/interp/block_plan.h"
#include "core/interp/cutter_comp.h"
#include "core/interp/cycle_words.h"
#include "core/interp/cycles.h"
#include "core/interp/follow_on.h"
#include "core/interp/interp.h"
#include "core/interp/polar.h"
#include "core/interp/spline.h"
#include "core/interp/warn_once.h"
#include "core/point.h"

namespace dexmill {
// Only the interpreter's own files include this header.
using namespace interp_detail;

// Checks one block against a copy of the state; commit() applies it.
struct BlockRunner {
  Interp& in;
  const InterpState& cur;
  const GcodeBlock& b;
  GcodeDiag* d;
  InterpState nx;
  Plan plan;

  BlockRunner(Interp& interp, const GcodeBlock& block, GcodeDiag* diag)
      : in(interp), cur(interp.state_), b(block), d(diag), nx(interp.state_) {}

  GcodeError fail(GcodeError e, uint16_t col, const char* word) {
    d->code = e;
    d->col = col ? col : 1;
    int i = 0;
    for (; i < 15 && word[i]; ++i) d->word[i] = word[i];
    d->word[i] = 0;
    return e;
  }
  GcodeError fail_letter(GcodeError e, char letter) {
    const char w[2] = {letter, 0};
    return fail(e, b.col_of(letter), w);
  }
  GcodeError fail_code(GcodeError e, char letter, int16_t tenths, uint16_t col) {
    char w[16];
    gcode_code_text(letter, tenths, w);
    return fail(e, col, w);
  }

  // A length word in the block's units, range-checked against `limit`
  // (an X word halved in G7, as LinuxCNC reads it).
  GcodeError length(char letter, int64_t* nm, int64_t limit = kGcodeMaxCoordNm) {
    const Decimal& v = b.val(letter);
    *nm = decimal_to_nm(v, nx.inch);
    if (letter == 'X' && nx.diameter_x) *nm = div_round(*nm, 2);  // G7: a diameter
    if (abs64(*nm) > limit) return fail_letter(GcodeError::kNumberTooLarge, letter);
    return GcodeError::kOk;
  }
  GcodeError integer(char letter, int64_t lo, int64_t hi, int64_t* out) {
    if (!decimal_to_int(b.val(letter), out)) return fail_letter(GcodeError::kNotInteger, letter);
    if (*out < lo) return fail_letter(lo >= 0 ? GcodeError::kNegativeValue : GcodeError::kNumberTooLarge, letter);
    if (*out > hi) return fail_letter(GcodeError::kNumberTooLarge, letter);
    return GcodeError::kOk;
  }
  GcodeError check_pos(const PointNm& p, uint16_t col, const char* word) {
    for (int ax = 0; ax < 3; ++ax) {
      int64_t v = axis_val(p, ax);
      if (abs64(v) > kGcodeMaxCoordNm) {
        d->a_nm = v;
        return fail(GcodeError::kPositionOutOfRange, col, word);
      }
    }
    return GcodeError::kOk;
  }
  // Offsets from program to path frame after this block's modal changes.
  int64_t offset(int axis) const {
    return axis_val(nx.work_offset[nx.coord_system], axis) + axis_val(nx.g92, axis);
  }
  uint16_t motion_col() const { return b.g[kGMotion] >= 0 ? b.g_col[kGMotion] : b.first_col; }
  // A warning the program gets once (WarnOnce), quoting `word` and a length.
  void warn_once(uint16_t bit, GcodeError e, uint16_t col, const char* word, int64_t a_nm = 0);
  // Whether the block sets the units, names the first T, or makes the first
  // move before any G20/G21 (interp.cpp; at commit, the tool at `start`).
  void note_units(const PointNm& start);

  GcodeError run();
  GcodeError run_modes();
  GcodeError run_context(int m);
  bool context_rest_follows() const;
  GcodeError run_group0(int g0);
  GcodeError run_motion(int motion);
  GcodeError run_straight(int motion, bool g53);
  GcodeError run_sync(int motion);
  GcodeError run_nurbs(int motion);
  void commit_nurbs(CanonRecord* r);
  GcodeError run_arc(int motion);
  GcodeError run_cycle(int motion);
  GcodeError cycle_words(int motion, const char* w, CycleWords* out);
  GcodeError cycle_spindle(int motion, const char* w);
  GcodeError cycle_check_range(const char* w);
  void cycle_warnings(int motion, const char* w);
  GcodeError run_probe(int motion);
  // Polar coordinates (@, ^; interp_polar.cpp): LinuxCNC's checks of the
  // block, the words, a move's end point, a canned cycle's holes.
  GcodeError check_polar(bool axis_user0);
  char polar_letter() const;
  GcodeError polar_words(PolarWords* w);
  GcodeError polar_target(PointNm* to);
  GcodeError end_point(PointNm* to);
  GcodeError cycle_polar(const char* w);
  // G5, G5.1 (interp_spline.cpp).
  GcodeError run_spline(int motion);
  void commit_spline(CanonRecord* r);
  // A feed move needs a feed rate: F in force, else --default-feed (one
  // warning, at the first such move), else kFeedZero.
  GcodeError need_feed(uint16_t col, const char* word);
  GcodeError run_home(int g0);
  GcodeError check_unused(int g0, int motion);
  // Cutter radius compensation (interp_comp.cpp).
  GcodeError comp_mode();                         // G40, G41, G42, G41.1, G42.1
  GcodeError comp_forbid_m();                     // M codes LinuxCNC refuses while it is on
  GcodeError comp_forbid_modes();                 // G43/G49, G54.., G61/G64, G98/G99
  GcodeError comp_forbid_group0(int g0);          // G10 L2/L20, G28/G30, G28.1/G30.1, G92..
  // LinuxCNC's find_ends: while compensation is on and past its entry
  // move, incremental and unwritten axes count from the programmed point,
  // not from the compensated one (which is where the tool is).
  const PointNm& comp_base() const { return cur.comp.side && !cur.comp.first_move ? cur.comp.prog : cur.pos; }
  CompOps& comp_ops(CanonKind kind);
  GcodeError comp_straight(int motion, bool g53, const PointNm& to);
  GcodeError comp_arc_entry(int motion, const PointNm& to, bool has_r, int64_t r_abs);
  GcodeError comp_arc(int motion, const PointNm& to, int64_t ca, int64_t cb);
  GcodeError comp_check_queue();                  // the held records, this block applied
  bool comp_acts() const { return cur.comp.side || plan.comp.motion || in.comp_q_.n; }
  GcodeError comp_apply(CompQueue* q, const CanonRecord& r, PointNm at, const CompEmit* out) const;
  void comp_commit_motion(CanonRecord* r, const PointNm& start);
  void comp_commit_flush(const PointNm& tool);
  static void emit_now(void* interp, CanonRecord* r);  // CompEmit to the sink
  void commit();
};

}  // namespace dexmill

#endif
