// O-word control flow, as LinuxCNC 2.9's interp_o_word.cc runs it
// (convert_control_functions, control_back_to, execute_call/return):
// statements are checked completely before any state changes, so a bad one
// changes nothing; LinuxCNC's quirks are kept where a program could tell
// (one executed_if flag for all ifs, a do's closing while evaluated after a
// break, definitions met again in the flow are errors). See oword_store.h
// for the model.
#include <string.h>

#include "core/gcode/lex.h"
#include "core/interp/interp.h"

namespace dexmill {
namespace {

bool global_op(OwordOp op) {
  return op == OwordOp::kSub || op == OwordOp::kEndsub || op == OwordOp::kCall || op == OwordOp::kReturn ||
         op == OwordOp::kProgramNumber || op == OwordOp::kM98 || op == OwordOp::kM99;
}

// The label recorded under (scope, name), or -1.
int32_t find_label(const OwordStore& c, int16_t scope, const char* name) {
  for (int32_t k = 0; k < c.nlabels; ++k)
    if (c.labels[k].scope == scope && !strcmp(c.labels[k].name, name)) return k;
  return -1;
}

// LinuxCNC's round_to_int (nearbyint: halves to even) of an e9 value.
int64_t round_half_even(int64_t e9) {
  int64_t q = e9 / kGValueOne, r = e9 % kGValueOne;
  if (r < 0) {
    r += kGValueOne;
    --q;
  }
  if (r > kGValueOne / 2 || (r == kGValueOne / 2 && (q & 1))) ++q;
  return q;
}

GcodeError fail(GcodeDiag* d, GcodeError e, const OwordHead& h, int64_t n = 0, int64_t m = 0) {
  d->code = e;
  d->col = h.col;
  d->a_nm = n;
  d->b_nm = m;
  size_t len = strlen(h.name);
  if (h.name[0] >= '0' && h.name[0] <= '9') {
    gcode_set_word(d, h.name, len);
  } else {
    char w[kOwordNameMax + 3];
    w[0] = '<';
    memcpy(w + 1, h.name, len);
    w[len + 1] = '>';
    gcode_set_word(d, w, len + 2);
  }
  return e;
}

}  // namespace

void oword_store_clear(OwordStore* c) {
  c->nlabels = 0;
  c->level = 0;
  for (int64_t& k : c->m98_left) k = -1;
  c->skip_label = -1;
  c->skip_sub[0] = 0;
  c->skip_from_line = 0;
  c->defining = -1;
  c->executed_if = c->doing_break = c->doing_continue = false;
  c->return_value = GValue{0};
  c->value_returned = false;
  c->blocks = 0;
  c->looped = false;
  c->loop_line = 0;
}

GcodeError Interp::run_oword(const char* text, size_t len, uint32_t line, GcodeDiag* d) {
  OwordStore& c = *options_.control;
  ParamStore& p = *options_.params;
  GcodeSource* src = options_.source;
  OwordHead h;
  GcodeError e = oword_read_head(text, len, p, &h, d);
  if (e != GcodeError::kOk) return e;
  // M99 returns from the subprogram running (LinuxCNC names it so).
  if (h.op == OwordOp::kM99 && c.level > 0 && c.frames[c.level].sub >= 0)
    memcpy(h.name, c.labels[c.frames[c.level].sub].name, sizeof h.name);
  const bool fanuc_frame = c.level > 0 && c.frames[c.level].fanuc;
  // LinuxCNC refuses a definition inside a definition even while skipping.
  if (h.op == OwordOp::kSub && c.defining >= 0) return fail(d, GcodeError::kOwordNestedSub, h);
  const int16_t scope = global_op(h.op) ? kOwordGlobal
                        : c.level > 0   ? c.frames[c.level].sub
                        : c.defining >= 0 ? c.defining
                                          : kOwordMain;
  const int32_t found = find_label(c, scope, h.name);
  if (c.skip_sub[0]) {
    // Looking for a sub called before it was met: only its sub line (or,
    // for M98, its O line) counts.
    if ((h.op != OwordOp::kSub && h.op != OwordOp::kProgramNumber) || strcmp(h.name, c.skip_sub))
      return GcodeError::kOk;
  } else if (c.skip_label >= 0 && found != c.skip_label) {
    return GcodeError::kOk;
  }
  if ((c.skip_sub[0] || c.skip_label >= 0) && h.op == OwordOp::kM98) return GcodeError::kOk;
  // While skipping no call is made (LinuxCNC reads it as no statement);
  // inside a definition passed over, only its endsub (and return) count.
  if ((c.skip_sub[0] || c.skip_label >= 0) && h.op == OwordOp::kCall) return GcodeError::kOk;
  if (c.defining >= 0 && !global_op(h.op)) return GcodeError::kOk;

  GValue v[kOwordArgsMax];
  int nv = 0;
  // A definition passed over reads its endsub's value as no value: its
  // locals are not set then (rs274 reads such a program without error).
  if (c.defining < 0) {
    e = oword_read_rest(text, len, h, p, v, &nv, d);
    if (e != GcodeError::kOk) return e;
  }
  const bool truth = nv > 0 && v[0].e9 != 0;
  const SourcePos here = src ? src->line_start() : SourcePos{0, line, 0};
  const bool same_line = found >= 0 && c.labels[found].at.line == here.line && c.labels[found].at.file == here.file;
  const uint32_t found_line = found >= 0 ? c.labels[found].at.line : 0;

  // Records the label of this statement (LinuxCNC's control_save_offset).
  auto record = [&](int32_t* idx) -> GcodeError {
    if (c.nlabels >= kOwordLabelsMax) return fail(d, GcodeError::kOwordTooManyLabels, h, kOwordLabelsMax);
    OwordLabel& l = c.labels[c.nlabels];
    memcpy(l.name, h.name, sizeof l.name);
    l.scope = scope;
    l.op = h.op;
    l.at = here;
    l.repeat_left = -1;
    *idx = c.nlabels++;
    return GcodeError::kOk;
  };
  // Reads on from the statement's recorded line (a loop's head, a sub).
  auto back_to = [&](const OwordLabel& l) -> GcodeError {
    if (!src) return fail(d, GcodeError::kOwordNoSource, h);
    if (!src->seek(l.at)) return fail(d, GcodeError::kOwordSeek, h, l.at.line);
    c.looped = true;
    c.loop_line = l.at.line;
    return GcodeError::kOk;
  };
  auto needs = [&](bool is_if) -> GcodeError {
    if (found < 0) return fail(d, GcodeError::kOwordUndefinedLabel, h);
    const OwordOp op = c.labels[found].op;
    const bool ok = is_if ? op == OwordOp::kIf : (op == OwordOp::kWhile || op == OwordOp::kDo);
    return ok ? GcodeError::kOk : fail(d, GcodeError::kOwordLabelKind, h, found_line);
  };

  // A definition met again: after a call made before it, or in a loop.
  auto met_again = [&]() {
    return fail(d, same_line ? GcodeError::kOwordSubAgain : GcodeError::kOwordSubRedefined, h, found_line);
  };
  int32_t idx = found;
  // The sub (or M98's program) a call was looking for: record it, then run its body.
  auto sub_found = [&]() -> GcodeError {
    if (found >= 0) return met_again();
    if ((e = record(&idx)) != GcodeError::kOk) return e;
    c.frames[c.level].sub = static_cast<int16_t>(idx);
    c.skip_sub[0] = 0;
    return GcodeError::kOk;
  };
  switch (h.op) {
    case OwordOp::kNone:
      return GcodeError::kOk;

    case OwordOp::kProgramNumber:
      // `O1234` alone: a program number, or the subprogram an M98 looks for.
      if (c.skip_sub[0]) return fanuc_frame ? sub_found() : fail(d, GcodeError::kOwordFanucMix, h);
      if (c.level > 0 && !fanuc_frame) return fail(d, GcodeError::kOwordFanucMix, h);
      return GcodeError::kOk;  // in the flow: LinuxCNC runs on into it

    case OwordOp::kSub:
      if (fanuc_frame) return fail(d, GcodeError::kOwordFanucMix, h);
      if (c.skip_sub[0]) return sub_found();
      if (c.level > 0) return GcodeError::kOk;  // a call read its sub line again
      // A definition met in the flow: record it and pass over its body.
      if (found >= 0) return met_again();
      if ((e = record(&idx)) != GcodeError::kOk) return e;
      c.defining = static_cast<int16_t>(idx);
      c.skip_label = static_cast<int16_t>(idx);
      c.skip_from_line = line;
      return GcodeError::kOk;

    case OwordOp::kM99:
      if (c.level == 0) {
        // LinuxCNC starts the program again, endlessly: a preview stops.
        warn(GcodeError::kWarnM99Main, line, h.col, "M99");
        state_.ended = true;
        return GcodeError::kOk;
      }
      if (!fanuc_frame) return fail(d, GcodeError::kOwordFanucMix, h);
      if (!src) return fail(d, GcodeError::kOwordNoSource, h);
      if (!src->seek(c.frames[c.level].back)) return fail(d, GcodeError::kOwordSeek, h, c.frames[c.level].back.line);
      if ((e = context_return(c.level, line, h.col, d)) != GcodeError::kOk) return e;
      params_drop_level(&p, c.level);
      --c.level;
      p.level = c.level;
      return GcodeError::kOk;

    case OwordOp::kEndsub:
    case OwordOp::kReturn: {
      if (c.level == 0 && c.defining < 0) return fail(d, GcodeError::kOwordNotInSub, h);
      if (fanuc_frame) return fail(d, GcodeError::kOwordFanucMix, h);
      // LinuxCNC sets the returned value as it reads the line.
      const GValue rv = nv > 0 ? v[0] : GValue{0};
      if (c.level > 0) {
        const OwordFrame& f = c.frames[c.level];
        if (!src) return fail(d, GcodeError::kOwordNoSource, h);
        if (!src->seek(f.back)) return fail(d, GcodeError::kOwordSeek, h, f.back.line);
        for (int k = 0; k < kOwordArgsMax; ++k) p.numbered_e9[k + 1] = f.saved_e9[k];
        if ((e = context_return(c.level, line, h.col, d)) != GcodeError::kOk) return e;
        params_drop_level(&p, c.level);
        --c.level;
        p.level = c.level;
      } else if (h.op == OwordOp::kEndsub) {
        c.defining = -1;  // the end of a definition passed over
        c.skip_label = -1;
      }
      c.return_value = rv;
      c.value_returned = nv > 0;
      return GcodeError::kOk;
    }

    case OwordOp::kM98:
    case OwordOp::kCall: {
      const bool m98 = h.op == OwordOp::kM98;
      if (m98 && h.m98_count == 0) return GcodeError::kOk;  // M98 L0: no call
      if (c.level + 1 >= kOwordLevels) return fail(d, GcodeError::kOwordCallDepth, h);
      if (!src) return fail(d, GcodeError::kOwordNoSource, h);
      SourcePos back = src->line_next();
      if (m98) {
        // M98 L: the call returns to its own line until the count is done
        // (LinuxCNC's m98_loop_counter, kept by the calling level).
        int64_t& left = c.m98_left[c.level];
        if (left < 0) left = h.m98_count;
        if (--left > 0) back = src->line_start();
        else left = -1;
      }
      if (found >= 0) {
        if (!src->seek(c.labels[found].at)) return fail(d, GcodeError::kOwordSeek, h, c.labels[found].at.line);
      } else {
        // Not met yet: its own file on the subroutine path, else further on
        // in this one (LinuxCNC's control_back_to, steps 2 and 3).
        SourcePos start;
        (void)src->open_subroutine(h.name, &start);
        memcpy(c.skip_sub, h.name, sizeof c.skip_sub);
        c.skip_from_line = line;
      }
      OwordFrame& f = c.frames[c.level + 1];
      f.sub = static_cast<int16_t>(found);
      f.back = back;
      f.fanuc = m98;
      for (int k = 0; !m98 && k < kOwordArgsMax; ++k) {  // M98 passes #1..#30 as they are
        f.saved_e9[k] = p.numbered_e9[k + 1];
        p.numbered_e9[k + 1] = k < nv ? v[k].e9 : 0;
      }
      ++c.level;
      p.level = c.level;
      contexts_[c.level].valid = false;  // a called level starts with nothing saved
      c.looped = true;
      c.loop_line = line;
      return GcodeError::kOk;
    }

    case OwordOp::kDo:
      c.skip_label = -1;
      if (found < 0) return record(&idx);
      return GcodeError::kOk;

    case OwordOp::kWhile: {
      if (found >= 0 && c.labels[found].op != OwordOp::kDo && !same_line)
        return fail(d, GcodeError::kOwordDuplicateLabel, h, found_line);
      if (found < 0 && (e = record(&idx)) != GcodeError::kOk) return e;
      OwordLabel& l = c.labels[idx];
      if (l.op == OwordOp::kWhile) {
        c.skip_label = truth ? -1 : static_cast<int16_t>(idx);
        c.skip_from_line = line;
        return GcodeError::kOk;
      }
      // The closing while of a do.
      if (truth && !c.doing_break) {
        if ((e = back_to(l)) != GcodeError::kOk) return e;
      } else {
        c.doing_break = false;
      }
      c.skip_label = -1;
      return GcodeError::kOk;
    }

    case OwordOp::kRepeat: {
      if (found >= 0 && !same_line) return fail(d, GcodeError::kOwordDuplicateLabel, h, found_line);
      if (found < 0 && (e = record(&idx)) != GcodeError::kOk) return e;
      OwordLabel& l = c.labels[idx];
      c.skip_label = -1;
      if (l.repeat_left < 0) l.repeat_left = round_half_even(v[0].e9);
      if (l.repeat_left > 0) {
        --l.repeat_left;
      } else {
        c.skip_label = static_cast<int16_t>(idx);
        c.skip_from_line = line;
        l.repeat_left = -1;
      }
      return GcodeError::kOk;
    }

    case OwordOp::kIf:
      if (found >= 0 && !same_line) return fail(d, GcodeError::kOwordDuplicateLabel, h, found_line);
      if (found < 0 && (e = record(&idx)) != GcodeError::kOk) return e;
      c.executed_if = truth;
      c.skip_label = truth ? -1 : static_cast<int16_t>(idx);
      c.skip_from_line = line;
      return GcodeError::kOk;

    case OwordOp::kElseif:
      if ((e = needs(true)) != GcodeError::kOk) return e;
      if (c.executed_if) {
        c.skip_label = static_cast<int16_t>(found);
      } else if (truth) {
        c.skip_label = -1;
        c.executed_if = true;
      }
      return GcodeError::kOk;

    case OwordOp::kElse:
      if ((e = needs(true)) != GcodeError::kOk) return e;
      if (c.executed_if) {
        c.skip_label = static_cast<int16_t>(found);
      } else if (c.skip_label == found) {
        c.executed_if = true;
        c.skip_label = -1;
      }
      return GcodeError::kOk;

    case OwordOp::kEndif:
      if ((e = needs(true)) != GcodeError::kOk) return e;
      c.skip_label = -1;
      c.executed_if = true;
      return GcodeError::kOk;

    case OwordOp::kBreak:
      if ((e = needs(false)) != GcodeError::kOk) return e;
      c.skip_label = static_cast<int16_t>(found);
      c.skip_from_line = line;
      c.doing_break = true;
      return GcodeError::kOk;

    case OwordOp::kContinue:
      if ((e = needs(false)) != GcodeError::kOk) return e;
      if (c.skip_label == found) return GcodeError::kOk;
      c.skip_label = static_cast<int16_t>(found);
      c.skip_from_line = line;
      c.doing_continue = true;
      return GcodeError::kOk;

    case OwordOp::kEndwhile:
    case OwordOp::kEndrepeat: {
      if (found < 0) return fail(d, GcodeError::kOwordUndefinedLabel, h);
      const OwordOp want = h.op == OwordOp::kEndwhile ? OwordOp::kWhile : OwordOp::kRepeat;
      if (c.labels[found].op != want) return fail(d, GcodeError::kOwordLabelKind, h, found_line);
      if (c.skip_label == found) {
        if (!c.doing_continue) {
          c.skip_label = -1;  // the loop is over
          return GcodeError::kOk;
        }
        if ((e = back_to(c.labels[found])) != GcodeError::kOk) return e;
        c.doing_continue = false;
        c.skip_label = -1;
        return GcodeError::kOk;
      }
      return back_to(c.labels[found]);
    }
  }
  return GcodeError::kOk;
}

GcodeError Interp::oword_unclosed(GcodeDiag* d) const {
  const OwordStore* c = options_.control;
  if (!c) return GcodeError::kOk;
  OwordHead h{};
  h.col = 1;
  if (c->skip_sub[0]) {
    memcpy(h.name, c->skip_sub, sizeof h.name);
    fail(d, GcodeError::kOwordSubNotFound, h);
  } else if (c->skip_label >= 0) {
    memcpy(h.name, c->labels[c->skip_label].name, sizeof h.name);
    fail(d, GcodeError::kOwordUnclosed, h, c->skip_from_line);
  } else {
    return GcodeError::kOk;
  }
  d->line = c->skip_from_line;
  d->follow_on = false;
  return d->code;
}

}  // namespace dexmill
