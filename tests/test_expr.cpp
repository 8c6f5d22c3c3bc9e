// core/gcode/gvalue.h and expr.h: every operator and function
// against a double oracle within its stated bound, LinuxCNC's precedence
// and its MOD, EQ, ROUND, FIX and FUP rules, parameters numbered and named
// (assignments made after the line), the errors (division by zero, domain,
// range, syntax, unknown names, read-only, nesting), and message comments.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/gcode/block.h"
#include "core/gcode/expr.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

double as_double(GValue v) { return double(v.e9) * 1e-9; }
GValue of(double d) { return GValue{int64_t(std::llround(d * 1e9))}; }

struct Eval {
  ParamStore p;
  Eval() { params_clear(&p); }
  GcodeError run(const char* text, GValue* out, GcodeDiag* d = nullptr) {
    GcodeDiag dd{};
    size_t pos = 0;
    return expr_read_value(text, std::strlen(text), &pos, p, out, d ? d : &dd);
  }
  double value(const char* text) {
    GValue v{0};
    const GcodeError e = run(text, &v);
    CHECK(e == GcodeError::kOk);
    if (e != GcodeError::kOk) std::printf("  %s: error %d\n", text, int(e));
    return as_double(v);
  }
};

}  // namespace

TEST(expr_functions_against_double_oracle) {
  t::Rng rng(21);
  const double kPi = 3.14159265358979323846;
  double worst[12] = {};
  for (int rep = 0; rep < 20000; ++rep) {
    const double a = double(rng.range(-2000000000, 2000000000)) * 1e-6;  // +-2000
    const double u = double(rng.range(-1000000000, 1000000000)) * 1e-9;  // +-1
    const double pos = double(rng.range(1, 2000000000000)) * 1e-9;       // (0, 2000]
    GValue r;
    auto err = [&](int k, double got, double want, double bound) {
      const double e = std::fabs(got - want);
      worst[k] = std::max(worst[k], e);
      CHECK_LE(e, bound);
    };
    CHECK(gvalue_unary(GUnary::kSin, of(a), &r) == GcodeError::kOk);
    err(0, as_double(r), std::sin(as_double(of(a)) * kPi / 180), 5e-9);
    CHECK(gvalue_unary(GUnary::kCos, of(a), &r) == GcodeError::kOk);
    err(1, as_double(r), std::cos(as_double(of(a)) * kPi / 180), 5e-9);
    CHECK(gvalue_unary(GUnary::kSqrt, of(pos), &r) == GcodeError::kOk);
    err(2, as_double(r), std::sqrt(as_double(of(pos))), 0.51e-9 + 1e-15 * pos);
    CHECK(gvalue_unary(GUnary::kAsin, of(u), &r) == GcodeError::kOk);
    err(3, as_double(r), std::asin(as_double(of(u))) * 180 / kPi, 2e-7);
    CHECK(gvalue_unary(GUnary::kAcos, of(u), &r) == GcodeError::kOk);
    err(4, as_double(r), std::acos(as_double(of(u))) * 180 / kPi, 2e-7);
    err(5, as_double(gvalue_atan2(of(a), of(pos))), std::atan2(as_double(of(a)), as_double(of(pos))) * 180 / kPi, 2e-7);
    CHECK(gvalue_unary(GUnary::kLn, of(pos), &r) == GcodeError::kOk);
    err(6, as_double(r), std::log(as_double(of(pos))), 2e-9);
    const double x = u * 20;  // EXP over +-20
    CHECK(gvalue_unary(GUnary::kExp, of(x), &r) == GcodeError::kOk);
    const double ex = std::exp(as_double(of(x)));
    // The oracle's own input (e9 times 1e-9 in double) is off by up to 4e-15 of x.
    err(7, as_double(r), ex, 0.51e-9 + 5e-15 * ex);
    CHECK(gvalue_binary(GBinary::kTimes, of(a), of(u * 1000), &r) == GcodeError::kOk);
    err(8, as_double(r), as_double(of(a)) * as_double(of(u * 1000)), 0.51e-9 + 1e-15 * std::fabs(a * u * 1000));
    CHECK(gvalue_binary(GBinary::kDivide, of(a), of(pos), &r) == GcodeError::kOk);
    err(9, as_double(r), as_double(of(a)) / as_double(of(pos)), 0.51e-9 + 1e-15 * std::fabs(a / pos));
    // A non-integer power of a positive base, within 1000.
    const double base = 0.5 + pos / 1000, expo = u * 3;
    if (std::pow(base, expo) < 1000) {
      CHECK(gvalue_binary(GBinary::kPower, of(base), of(expo), &r) == GcodeError::kOk);
      const double pw = std::pow(as_double(of(base)), as_double(of(expo)));
      err(10, as_double(r), pw, 3e-9 * (1 + pw));
    }
    // Integer powers exactly as repeated products.
    CHECK(gvalue_binary(GBinary::kPower, of(u * 3), gvalue_int(3), &r) == GcodeError::kOk);
    const double c = as_double(of(u * 3));
    err(11, as_double(r), c * c * c, 2e-9);
  }
  std::printf("expr: worst sin %.2g cos %.2g sqrt %.2g asin %.2g acos %.2g atan %.2g ln %.2g exp %.2g * %.2g / %.2g pow %.2g ipow %.2g\n",
              worst[0], worst[1], worst[2], worst[3], worst[4], worst[5], worst[6], worst[7], worst[8], worst[9], worst[10],
              worst[11]);
}

TEST(expr_linuxcnc_rules) {
  Eval e;
  // Precedence: ** over * / MOD over + - over comparisons over AND OR XOR;
  // left to right at equal precedence (LinuxCNC: 2 ** 3 ** 2 = 64).
  CHECK_EQ(e.value("[2 + 3 * 4 ** 2 - 1]"), 49.0);
  CHECK_EQ(e.value("[2 ** 3 ** 2]"), 64.0);
  CHECK_EQ(e.value("[8 / 4 / 2]"), 1.0);
  CHECK_EQ(e.value("[2 GT 1 AND 0 LT 1]"), 1.0);
  CHECK_EQ(e.value("[1 + 1 EQ 2]"), 1.0);
  CHECK_EQ(e.value("[1 OR 0 XOR 1]"), 0.0);
  // EQ and NE within LinuxCNC's 0.0001.
  CHECK_EQ(e.value("[1 EQ 1.00001]"), 1.0);
  CHECK_EQ(e.value("[1 NE 1.001]"), 1.0);
  CHECK_EQ(e.value("[1 GE 1]"), 1.0);
  CHECK_EQ(e.value("[1 LT 1]"), 0.0);
  // MOD takes the divisor's magnitude: -7 MOD 3 = 2 (as rs274 gives).
  CHECK_EQ(e.value("[-7 MOD 3]"), 2.0);
  CHECK_EQ(e.value("[7 MOD -3]"), 1.0);
  CHECK_EQ(e.value("[10 mod 3]"), 1.0);
  // FIX floors, FUP ceils, ROUND halves away from zero.
  CHECK_EQ(e.value("FIX[-2.5]"), -3.0);
  CHECK_EQ(e.value("FUP[-2.5]"), -2.0);
  CHECK_EQ(e.value("ROUND[2.5]"), 3.0);
  CHECK_EQ(e.value("ROUND[-2.5]"), -3.0);
  CHECK_EQ(e.value("abs[-3]"), 3.0);
  CHECK_EQ(e.value("ATAN[1]/[1]"), 45.0);
  CHECK_EQ(e.value("ATAN [0] / [-1]"), 180.0);
  CHECK_LE(std::fabs(e.value("[ SQRT[ 2 ] * SQRT[ 2 ] ]") - 2.0), 1.01e-9);  // each root rounded to 1e-9
  CHECK_EQ(e.value("-[1+1]"), -2.0);
  CHECK_EQ(e.value("0.0000000004"), 0.0);  // a tenth of the last place rounds away
  CHECK_EQ(e.value("1.0000000005"), 1.000000001);
  // Parameters: numbered, indirect, named (case and blanks folded).
  params_clear(&e.p);
  CHECK(param_set(&e.p, 7, gvalue_int(3)) == GcodeError::kOk);
  CHECK(param_set(&e.p, 3, gvalue_int(11)) == GcodeError::kOk);
  CHECK(param_set_named(&e.p, "My Depth", 8, GValue{2500000000}) == GcodeError::kOk);
  CHECK_EQ(e.value("#7"), 3.0);
  CHECK_EQ(e.value("##7"), 11.0);
  CHECK_EQ(e.value("#[1+2]"), 11.0);
  CHECK_EQ(e.value("#<mydepth>"), 2.5);
  CHECK_EQ(e.value("[#<MY DEPTH> * 2]"), 5.0);
  CHECK_EQ(e.value("EXISTS[#<mydepth>]"), 1.0);
  CHECK_EQ(e.value("EXISTS[#<other>]"), 0.0);
  CHECK_EQ(e.value("#99"), 0.0);  // never set: 0, as LinuxCNC
}

TEST(expr_errors_name_their_cause) {
  Eval e;
  struct Case {
    const char* text;
    GcodeError code;
    uint16_t col;
  } cases[] = {
      {"[1 / 0]", GcodeError::kExprDivideByZero, 4},
      {"[5 MOD 0]", GcodeError::kExprDivideByZero, 4},
      {"SQRT[-1]", GcodeError::kExprDomain, 1},
      {"LN[0]", GcodeError::kExprDomain, 1},
      {"ACOS[1.5]", GcodeError::kExprDomain, 1},
      {"[-2 ** 0.5]", GcodeError::kExprDomain, 5},
      {"[0 ** -1]", GcodeError::kExprDivideByZero, 4},
      {"[100000 * 100000]", GcodeError::kExprOutOfRange, 9},
      {"EXP[30]", GcodeError::kExprOutOfRange, 1},
      {"TAN[90]", GcodeError::kExprOutOfRange, 1},
      {"[1 + 2", GcodeError::kExprSyntax, 1},
      {"[1 ? 2]", GcodeError::kExprSyntax, 4},
      {"FOO[1]", GcodeError::kExprUnknownFunction, 1},
      {"#0", GcodeError::kParamNumberRange, 1},
      {"#5603", GcodeError::kParamNumberRange, 1},
      {"#1.5", GcodeError::kNotInteger, 1},
      {"#<nothing>", GcodeError::kParamUnknownName, 1},
      {"#<abcdefghijklmnopqrstuvwxyzabcdefgh>", GcodeError::kParamNameTooLong, 1},
  };
  for (const Case& c : cases) {
    GValue v;
    GcodeDiag d{};
    const GcodeError got = e.run(c.text, &v, &d);
    CHECK(got == c.code);
    CHECK_EQ(d.col, c.col);
    if (got != c.code || d.col != c.col) std::printf("  %s: error %d at %d\n", c.text, int(got), d.col);
  }
}

// Nesting as LinuxCNC reads it: as deep as a line holds (rs274 ran 123
// brackets, the most its command line holds), so kExprDepthMax levels are
// read and one more is refused where it opens, with the limit in the message.
TEST(expr_nesting_to_the_limit_and_one_past) {
  Eval e;
  CHECK(param_set(&e.p, 1, GValue{kGValueOne}) == GcodeError::kOk);
  auto nest = [](const std::string& open, const std::string& inner, const std::string& close, int n) {
    std::string t;
    for (int k = 0; k < n; ++k) t += open;
    t += inner;
    for (int k = 0; k < n; ++k) t += close;
    return t;
  };
  struct Kind {
    const char* open;
    const char* inner;
    const char* close;
    int64_t value_e9;  // at kExprDepthMax levels
  };
  const Kind kinds[] = {
      {"[", "1", "]", kGValueOne},      // brackets
      {"ABS[", "-1", "]", kGValueOne},  // a function's bracket is one level
      {"#", "1", "", kGValueOne},       // parameter references (#1 = 1)
  };
  for (const Kind& k : kinds) {
    const size_t open_len = std::strlen(k.open);
    GValue v{0};
    GcodeDiag d{};
    const std::string ok_text = nest(k.open, k.inner, k.close, kExprDepthMax);
    CHECK(e.run(ok_text.c_str(), &v, &d) == GcodeError::kOk);
    CHECK_EQ(v.e9, k.value_e9);
    const std::string deep = nest(k.open, k.inner, k.close, kExprDepthMax + 1);
    d = GcodeDiag{};
    CHECK(e.run(deep.c_str(), &v, &d) == GcodeError::kExprTooDeep);
    // Refused at the opening of level kExprDepthMax + 1 (its last byte: a
    // function's '[' opens its level).
    CHECK_EQ(size_t(d.col), size_t(kExprDepthMax) * open_len + open_len);
    char msg[160];
    gcode_format_message(d, msg, sizeof msg);
    CHECK(std::strstr(msg, "nested deeper than 256 levels") != nullptr);
    if (!std::strstr(msg, "nested deeper than 256 levels")) std::printf("  message: %s\n", msg);
  }
  // Signs before computed values are levels too: 255 of them and a bracket.
  GValue v{0};
  GcodeDiag d{};
  CHECK(e.run((std::string(kExprDepthMax - 1, '-') + "[1]").c_str(), &v, &d) == GcodeError::kOk);
  CHECK_EQ(v.e9, -kGValueOne);
  CHECK(e.run((std::string(kExprDepthMax, '-') + "[1]").c_str(), &v, &d) == GcodeError::kExprTooDeep);
  CHECK_EQ(int(d.col), kExprDepthMax + 1);
  // The deepest a line of kGcodeMaxLine bytes holds, read as a block.
  ParamStore p;
  params_clear(&p);
  const std::string line = "X" + nest("[", "1", "]", int(kGcodeMaxLine - 2) / 2);
  CHECK_EQ(line.size(), kGcodeMaxLine);
  GcodeBlock b;
  GcodeLineKind kind;
  d = GcodeDiag{};
  CHECK(gcode_read_block(line.c_str(), line.size(), 1, &b, &kind, &d, &p) == GcodeError::kOk);
  CHECK_EQ(b.val('X').mant, 1);
}

TEST(block_assignments_after_the_line_and_messages) {
  ParamStore p;
  params_clear(&p);
  auto read = [&](const char* text, GcodeBlock* b, GcodeDiag* d) {
    GcodeLineKind kind;
    return gcode_read_block(text, std::strlen(text), 1, b, &kind, d, &p);
  };
  GcodeBlock b;
  GcodeDiag d{};
  // Values on the line see the parameters as they were before it.
  CHECK(read("#1 = 5 G1 X#1 #1 = [#1 + 2]", &b, &d) == GcodeError::kOk);
  CHECK_EQ(b.val('X').mant, 0);
  GValue v;
  CHECK(param_get(p, 1, &v) == GcodeError::kOk);
  CHECK_EQ(v.e9, 2 * kGValueOne);  // the last assignment wins, from the old #1 (0)
  CHECK(read("G1 X[#1 * 1.5] Y-#1 Z#<_unset_global>", &b, &d) == GcodeError::kParamUnknownName);
  CHECK(read("G1 X[#1 * 1.5] Y-#1", &b, &d) == GcodeError::kOk);
  CHECK_EQ(b.val('X').mant, 3);
  CHECK_EQ(b.val('Y').mant, -2);
  // A line with an error makes none of its assignments.
  CHECK(read("#2 = 9 G1 X[1/0]", &b, &d) == GcodeError::kExprDivideByZero);
  CHECK(param_get(p, 2, &v) == GcodeError::kOk);
  CHECK_EQ(v.e9, 0);
  CHECK(read("#2 = ", &b, &d) != GcodeError::kOk);
  CHECK(read("#2 5", &b, &d) == GcodeError::kExprSyntax);
  // Messages: DEBUG and PRINT substituted (LinuxCNC's 6 decimals), MSG as written.
  CHECK(read("#<depth> = 2.5 (DEBUG, depth=#<depth> one=#1 none=#<nope>)", &b, &d) == GcodeError::kOk);
  CHECK(b.message_kind == GcodeMessage::kDebug);
  CHECK_EQ(std::string(b.message), std::string(" depth=2.500000 one=2.000000 none=######"));
  CHECK(read("(msg,Tool #1 please)", &b, &d) == GcodeError::kOk);
  CHECK(b.message_kind == GcodeMessage::kMsg);
  CHECK_EQ(std::string(b.message), std::string("Tool #1 please"));
  CHECK(read("( print , x=#1)", &b, &d) == GcodeError::kOk);
  CHECK(b.message_kind == GcodeMessage::kPrint);
  CHECK_EQ(std::string(b.message), std::string(" x=2.000000"));
  // Without parameters the reader refuses them as before.
  GcodeLineKind kind;
  CHECK(gcode_read_block("G1 X#1", 6, 1, &b, &kind, &d) == GcodeError::kUnsupportedParameter);
}
