// Computed values; see expr.h.
#include "core/gcode/expr.h"

#include <string.h>

#include "core/gcode/lex.h"
#include "core/math/decimal.h"

namespace dexmill {
namespace {

inline bool blank(char c) { return gcode_is_blank(c); }
inline char up(char c) { return gcode_upper(c); }
inline bool alpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

struct Func {
  const char* name;
  int kind;  // 0 unary, 1 ATAN, 2 EXISTS
  GUnary f;
};
const Func kFuncs[] = {
    {"ABS", 0, GUnary::kAbs},  {"ACOS", 0, GUnary::kAcos}, {"ASIN", 0, GUnary::kAsin},   {"ATAN", 1, GUnary::kAbs},
    {"COS", 0, GUnary::kCos},  {"EXISTS", 2, GUnary::kAbs}, {"EXP", 0, GUnary::kExp},    {"FIX", 0, GUnary::kFix},
    {"FUP", 0, GUnary::kFup},  {"LN", 0, GUnary::kLn},     {"ROUND", 0, GUnary::kRound}, {"SIN", 0, GUnary::kSin},
    {"SQRT", 0, GUnary::kSqrt}, {"TAN", 0, GUnary::kTan},
};

struct Op {
  const char* text;
  GBinary op;
};
// Longer spellings first ("**" before "*").
const Op kOps[] = {
    {"**", GBinary::kPower}, {"*", GBinary::kTimes}, {"/", GBinary::kDivide}, {"+", GBinary::kPlus},
    {"-", GBinary::kMinus},  {"MOD", GBinary::kMod}, {"EQ", GBinary::kEq},    {"NE", GBinary::kNe},
    {"GT", GBinary::kGt},    {"GE", GBinary::kGe},   {"LT", GBinary::kLt},    {"LE", GBinary::kLe},
    {"AND", GBinary::kAnd},  {"OR", GBinary::kOr},   {"XOR", GBinary::kXor},
};

class Reader {
 public:
  Reader(const char* s, size_t n, size_t pos, const ParamStore& p, GcodeDiag* d) : s_(s), n_(n), pos_(pos), p_(p), d_(d) {
    for (size_t k = pos; k < n; ++k) closes_ += s[k] == ']' ? 1 : 0;
  }
  size_t pos() const { return pos_; }

  // depth: the levels around this value (expr.h); each opening checks that
  // its own level is within kExprDepthMax before it recurses.
  GcodeError value(int depth, GValue* out) {
    skip();
    if (pos_ >= n_) return fail(GcodeError::kMissingNumber, pos_, 0);
    const char c = s_[pos_];
    if (c == '[') return bracketed(depth, out);
    if (c == '#') return parameter(depth, out);
    if ((c == '-' || c == '+') && expr_starts_computed(s_, n_, pos_ + 1)) {
      if (depth >= kExprDepthMax) return fail(GcodeError::kExprTooDeep, pos_, 1);
      ++pos_;
      GcodeError e = value(depth + 1, out);
      if (e == GcodeError::kOk && c == '-') out->e9 = -out->e9;
      return e;
    }
    if (alpha(c)) return function(depth, out);
    return number(out);
  }

  // '#' then <name> or a real value giving the number.
  GcodeError reference(int depth, ParamRef* ref) {
    const size_t at = pos_;
    ++pos_;  // '#'
    skip();
    if (pos_ < n_ && s_[pos_] == '<') return named(at, ref);
    ref->named = false;
    return numbered(depth, at, &ref->number);
  }

 private:
  // <name> after '#' at `at` (no recursion: kept out of the nesting's frames).
  __attribute__((noinline)) GcodeError named(size_t at, ParamRef* ref) {
    const size_t start = ++pos_;
    while (pos_ < n_ && s_[pos_] != '>') ++pos_;
    if (pos_ >= n_) return fail(GcodeError::kExprSyntax, at, n_ - at);
    ref->named = true;
    if (!param_fold_name(s_ + start, pos_ - start, ref->name)) return fail(GcodeError::kParamNameTooLong, at, pos_ - at);
    ++pos_;  // '>'
    return GcodeError::kOk;
  }

  // The real value after '#' at `at` as a parameter number: one nesting
  // level, so ##..#1 chains cost a value's frame and this one's a '#'.
  GcodeError numbered(int depth, size_t at, int64_t* number) {
    if (depth >= kExprDepthMax) return fail(GcodeError::kExprTooDeep, at, 1);
    GValue idx;
    GcodeError e = value(depth + 1, &idx);
    if (e != GcodeError::kOk) return e;
    // LinuxCNC: the number must be an integer (within its 1e-6).
    const int64_t n = (idx.e9 + (idx.e9 < 0 ? -kGValueOne / 2 : kGValueOne / 2)) / kGValueOne;
    const int64_t off = idx.e9 - n * kGValueOne;
    if (off > 1000 || off < -1000) return fail(GcodeError::kNotInteger, at, pos_ - at);
    if (n < 1 || n > kParamsNumbered) return fail(GcodeError::kParamNumberRange, at, pos_ - at);
    *number = n;
    return GcodeError::kOk;
  }

  void skip() {
    while (pos_ < n_ && blank(s_[pos_])) ++pos_;
  }

  GcodeError fail(GcodeError e, size_t at, size_t len) {
    d_->code = e;
    d_->col = static_cast<uint16_t>(at + 1);
    gcode_set_word(d_, s_ + at, len ? len : (at < n_ ? 1 : 0));
    return e;
  }

  GcodeError parameter(int depth, GValue* out) {
    const size_t at = pos_;
    ++pos_;  // '#'
    skip();
    if (pos_ < n_ && s_[pos_] == '<') return named_value(at, out);
    int64_t number = 0;
    GcodeError e = numbered(depth, at, &number);
    if (e != GcodeError::kOk) return e;
    e = param_get(p_, number, out);
    return e == GcodeError::kOk ? e : fail(e, at, pos_ - at);
  }

  // #<name>'s value (the name's buffer out of the nesting's frames).
  __attribute__((noinline)) GcodeError named_value(size_t at, GValue* out) {
    ParamRef ref;
    GcodeError e = named(at, &ref);
    if (e != GcodeError::kOk) return e;
    e = param_get_named(p_, ref.name, strlen(ref.name), out, nullptr);
    return e == GcodeError::kOk ? e : fail(e, at, pos_ - at);
  }

  // A plain number (no nesting: kept out of the nesting's frames).
  __attribute__((noinline)) GcodeError number(GValue* out) {
    const size_t at = pos_;
    Decimal dv{0, 0};
    const DecimalParse r = decimal_parse(s_, n_, &pos_, &dv);
    if (r == DecimalParse::kNoDigits) return fail(GcodeError::kBadNumber, at, 1);
    if (r == DecimalParse::kTooLarge) return fail(GcodeError::kNumberTooLarge, at, pos_ - at);
    const GcodeError e = gvalue_from_decimal(dv, out);
    return e == GcodeError::kOk ? e : fail(e, at, pos_ - at);
  }

  // '[' value (op value)* ']', reduced by precedence, left to right.
  GcodeError bracketed(int depth, GValue* out) {
    const size_t open = pos_;
    if (depth >= kExprDepthMax) return fail(GcodeError::kExprTooDeep, open, 1);
    // Each open bracket needs its own ']' further on: an unclosed run of
    // '[' is refused here, before it recurses (expr.h: the stack bound).
    if (open_ >= closes_) return fail(GcodeError::kExprSyntax, open, n_ - open);
    ++pos_;
    ++open_;
    const GcodeError e = bracket_body(depth, open, out);
    --open_;
    return e;
  }

  GcodeError bracket_body(int depth, size_t open, GValue* out) {
    // Operators wait only while each binds tighter than the one before it
    // (the reduction below), so at most one per precedence level.
    GValue vals[kExprPendingMax + 1];
    GBinary ops[kExprPendingMax];
    uint32_t op_at[kExprPendingMax];
    int nv = 0, no = 0;
    GcodeError e = value(depth + 1, &vals[nv++]);
    if (e != GcodeError::kOk) return e;
    for (;;) {
      skip();
      if (pos_ >= n_) return fail(GcodeError::kExprSyntax, open, n_ - open);
      GBinary op = GBinary::kPlus;
      const size_t at = pos_;
      const bool close = s_[pos_] == ']';
      if (close) {
        ++pos_;
      } else {
        e = read_op(&op);
        if (e != GcodeError::kOk) return e;
      }
      // Reduce while the stacked operator binds at least as tightly.
      while (no > 0 && (close || gbinary_precedence(op) <= gbinary_precedence(ops[no - 1]))) {
        GValue r;
        e = gvalue_binary(ops[no - 1], vals[nv - 2], vals[nv - 1], &r);
        if (e != GcodeError::kOk) return fail(e, op_at[no - 1], 1);
        vals[nv - 2] = r;
        --nv;
        --no;
      }
      if (close) {
        *out = vals[0];
        return GcodeError::kOk;
      }
      if (no >= kExprPendingMax) return fail(GcodeError::kExprTooDeep, at, 1);  // cannot happen: see above
      ops[no] = op;
      op_at[no++] = static_cast<uint32_t>(at);
      e = value(depth + 1, &vals[nv++]);
      if (e != GcodeError::kOk) return e;
    }
  }

  __attribute__((noinline)) GcodeError read_op(GBinary* op) {
    for (const Op& o : kOps) {
      size_t k = 0;
      while (o.text[k] && pos_ + k < n_ && up(s_[pos_ + k]) == o.text[k]) ++k;
      if (!o.text[k]) {
        pos_ += k;
        *op = o.op;
        return GcodeError::kOk;
      }
    }
    return fail(GcodeError::kExprSyntax, pos_, 1);
  }

  // EXISTS[#<name>] from its '[' (the name's buffer out of the nesting's frames).
  __attribute__((noinline)) GcodeError exists(int depth, size_t at, GValue* out) {
    ++pos_;
    skip();
    ParamRef ref;
    if (pos_ >= n_ || s_[pos_] != '#') return fail(GcodeError::kExprSyntax, at, pos_ - at);
    GcodeError e = reference(depth, &ref);
    if (e != GcodeError::kOk) return e;
    skip();
    if (!ref.named || pos_ >= n_ || s_[pos_] != ']') return fail(GcodeError::kExprSyntax, at, pos_ - at);
    ++pos_;
    bool exists = false;
    GValue ignored;
    e = param_get_named(p_, ref.name, strlen(ref.name), &ignored, &exists);
    if (e != GcodeError::kOk) return fail(e, at, pos_ - at);
    out->e9 = exists ? kGValueOne : 0;
    return GcodeError::kOk;
  }

  __attribute__((noinline)) GcodeError function(int depth, GValue* out) {
    const size_t at = pos_;
    char name[8];
    size_t k = 0;
    while (pos_ < n_ && (alpha(s_[pos_]) || blank(s_[pos_]))) {
      if (!blank(s_[pos_]) && k < sizeof name - 1) name[k++] = up(s_[pos_]);
      ++pos_;
    }
    name[k] = 0;
    const Func* f = nullptr;
    for (const Func& x : kFuncs) {
      size_t i = 0;
      while (x.name[i] && x.name[i] == name[i]) ++i;
      if (!x.name[i] && !name[i]) f = &x;
    }
    if (!f || pos_ >= n_ || s_[pos_] != '[') return fail(GcodeError::kExprUnknownFunction, at, pos_ - at);
    if (f->kind == 2) return exists(depth, at, out);  // EXISTS[#<name>]
    GValue a;
    GcodeError e = bracketed(depth, &a);  // one level, as a bracket
    if (e != GcodeError::kOk) return e;
    if (f->kind == 1) {  // ATAN[y]/[x]
      skip();
      if (pos_ >= n_ || s_[pos_] != '/') return fail(GcodeError::kExprSyntax, at, pos_ - at);
      ++pos_;
      skip();
      GValue x;
      if (pos_ >= n_ || s_[pos_] != '[') return fail(GcodeError::kExprSyntax, at, pos_ - at);
      e = bracketed(depth, &x);
      if (e != GcodeError::kOk) return e;
      *out = gvalue_atan2(a, x);
      return GcodeError::kOk;
    }
    e = gvalue_unary(f->f, a, out);
    return e == GcodeError::kOk ? e : fail(e, at, pos_ - at);
  }

  const char* s_;
  size_t n_;
  size_t pos_;
  const ParamStore& p_;
  GcodeDiag* d_;
  size_t closes_ = 0;  // ']' in the text from where the reading started
  size_t open_ = 0;    // brackets open now
};

}  // namespace

bool expr_starts_computed(const char* s, size_t n, size_t pos) {
  // Signs in a loop: a line of them is no recursion.
  for (;; ++pos) {
    while (pos < n && blank(s[pos])) ++pos;
    if (pos >= n || (s[pos] != '-' && s[pos] != '+')) break;
  }
  if (pos >= n) return false;
  const char c = s[pos];
  if (c == '[' || c == '#') return true;
  if (!alpha(c)) return false;
  // A function name: letters then '['.
  while (pos < n && (alpha(s[pos]) || blank(s[pos]))) ++pos;
  return pos < n && s[pos] == '[';
}

GcodeError expr_read_value(const char* s, size_t n, size_t* pos, const ParamStore& p, GValue* out, GcodeDiag* d) {
  Reader r(s, n, *pos, p, d);
  const GcodeError e = r.value(0, out);
  *pos = r.pos();
  return e;
}

GcodeError expr_read_param_ref(const char* s, size_t n, size_t* pos, const ParamStore& p, ParamRef* out, GcodeDiag* d) {
  Reader r(s, n, *pos, p, d);
  const GcodeError e = r.reference(0, out);
  *pos = r.pos();
  return e;
}

}  // namespace dexmill
