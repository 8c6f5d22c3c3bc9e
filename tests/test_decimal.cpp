// core/math/decimal.h: decimal text straight to nanometres, exact and rounded.
#include <cstdio>
#include <cstring>

#include "core/math/decimal.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

bool parse(const char* s, Decimal* d, size_t* end = nullptr) {
  size_t pos = 0;
  bool ok = decimal_parse(s, std::strlen(s), &pos, d) == DecimalParse::kOk;
  if (end) *end = pos;
  return ok;
}

int64_t nm(const char* s, bool inch) {
  Decimal d;
  if (!parse(s, &d)) return INT64_MIN;
  return decimal_to_nm(d, inch);
}

// k / 10^places written with exactly `places` decimals ("-0.000007").
const char* fixed_text(int64_t k, int places, char (&buf)[32]) {
  int64_t scale = 1;
  for (int i = 0; i < places; ++i) scale *= 10;
  const int64_t a = k < 0 ? -k : k;
  std::snprintf(buf, sizeof buf, "%s%lld.%0*lld", k < 0 ? "-" : "", static_cast<long long>(a / scale), places,
                static_cast<long long>(a % scale));
  return buf;
}

}  // namespace

TEST(decimal_forms) {
  Decimal d;
  size_t end;
  CHECK(parse("10", &d, &end));
  CHECK_EQ(d.mant, 10);
  CHECK_EQ(d.frac, 0);
  CHECK(parse(".5", &d));
  CHECK_EQ(d.mant, 5);
  CHECK_EQ(d.frac, 1);
  CHECK(parse("-.5", &d));
  CHECK_EQ(d.mant, -5);
  CHECK(parse("+3.", &d, &end));
  CHECK_EQ(d.mant, 3);
  CHECK_EQ(end, 3u);
  CHECK(parse("0010.500", &d));
  CHECK_EQ(d.mant, 10500);
  CHECK_EQ(d.frac, 3);
  // White space inside a number is ignored (RS274/NGC), and not consumed after it.
  CHECK(parse(" 1 0 . 2 5 Y", &d, &end));
  CHECK_EQ(d.mant, 1025);
  CHECK_EQ(d.frac, 2);
  CHECK_EQ(end, 10u);
  CHECK(!parse("", &d));
  CHECK(!parse("-", &d));
  CHECK(!parse(".", &d));
  CHECK(!parse("-.", &d));
  CHECK(!parse("Y1", &d));
  size_t pos = 0;
  CHECK(decimal_parse("123456789012345678", 18, &pos, &d) == DecimalParse::kTooLarge);
  pos = 0;
  CHECK(decimal_parse("99999999999999999", 17, &pos, &d) == DecimalParse::kOk);
}

TEST(decimal_mm_exact) {
  CHECK_EQ(nm("1", false), 1000000);
  CHECK_EQ(nm("0.000001", false), 1);
  CHECK_EQ(nm("-0.000001", false), -1);
  CHECK_EQ(nm("12345.678901", false), 12345678901);
  CHECK_EQ(nm("-9999.999999", false), -9999999999);
  // Every 6-decimal value is exact: sweep a range of them.
  char buf[32];
  for (int64_t k = -200000; k <= 200000; k += 7)
    if (!CHECK_EQ(nm(fixed_text(k, 6, buf), false), k)) break;
}

TEST(decimal_mm_rounding) {
  CHECK_EQ(nm("0.0000004", false), 0);
  CHECK_EQ(nm("0.0000005", false), 1);   // ties away from zero
  CHECK_EQ(nm("-0.0000005", false), -1);
  CHECK_EQ(nm("0.00000049999999", false), 0);
  CHECK_EQ(nm("1.9999999", false), 2000000);
  // Digits past 12 decimals are dropped (truncation), never wrapped.
  CHECK_EQ(nm("0.0000004999999999999999", false), 0);
  CHECK_EQ(nm("0.12345678901234567890", false), 123457);
}

TEST(decimal_inch) {
  CHECK_EQ(nm("1", true), 25400000);
  CHECK_EQ(nm("0.00001", true), 254);  // 5 decimals are exact
  CHECK_EQ(nm("-2.54321", true), -64597534);
  char buf[32];
  for (int64_t k = -100000; k <= 100000; k += 13)
    if (!CHECK_EQ(nm(fixed_text(k, 5, buf), true), k * 254)) break;
  // 6 decimals: nearest nm (0.000001 in = 25.4 nm -> 25).
  CHECK_EQ(nm("0.000001", true), 25);
  CHECK_EQ(nm("0.000003", true), 76);   // 76.2
  CHECK_EQ(nm("0.0000005", true), 13);  // 12.7
}

TEST(decimal_overflow_saturates) {
  Decimal d;
  CHECK(parse("99999999999999999", &d));
  CHECK_EQ(decimal_to_nm(d, true), INT64_MAX);  // saturates; the interpreter range-checks
  CHECK(parse("-99999999999999999", &d));
  CHECK_EQ(decimal_to_nm(d, false), INT64_MIN);
}

TEST(decimal_integers_and_tenths) {
  Decimal d;
  int64_t v;
  CHECK(parse("38.2", &d));
  CHECK(decimal_to_tenths(d, &v));
  CHECK_EQ(v, 382);
  CHECK(parse("01", &d));
  CHECK(decimal_to_tenths(d, &v));
  CHECK_EQ(v, 10);
  CHECK(parse("1.00", &d));
  CHECK(decimal_to_tenths(d, &v));
  CHECK_EQ(v, 10);
  CHECK(parse("38.25", &d));
  CHECK(!decimal_to_tenths(d, &v));
  CHECK(parse("3.0", &d));
  CHECK(decimal_to_int(d, &v));
  CHECK_EQ(v, 3);
  CHECK(parse("3.5", &d));
  CHECK(!decimal_to_int(d, &v));
  CHECK(parse("2.5", &d));
  CHECK_EQ(decimal_scale(d, 1000), 2500);  // seconds -> ms
  CHECK(parse("0.0005", &d));
  CHECK_EQ(decimal_scale(d, 1000), 1);      // ties away from zero
}
