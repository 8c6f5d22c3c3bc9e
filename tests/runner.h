// The project's own test runner: no framework package.
//
// TEST(name) { ... } registers a case (static list, no heap). CHECK* macros
// report one line per failure, `file:line: what failed: values`, integers in
// decimal and hex, and the run ends with `N passed, M failed`.
#ifndef DEXMILL_TESTS_RUNNER_H
#define DEXMILL_TESTS_RUNNER_H

#include <cstdint>
#include <cstdio>
#include <type_traits>

namespace t {

struct Case {
  const char* name;
  void (*fn)();
  const char* file;
  int line;
  Case* next;
};

struct Registrar {
  explicit Registrar(Case* c);
};

// Records one failure of the running case. `detail` may be null.
void fail(const char* file, int line, const char* what, const char* detail);

// Formats a value for a failure line: integers as `dec (0xhex)`.
template <class T>
void describe(char* buf, std::size_t n, T v) {
  if constexpr (std::is_same_v<T, bool>) {
    std::snprintf(buf, n, "%s", v ? "true" : "false");
  } else if constexpr (std::is_enum_v<T>) {
    describe(buf, n, static_cast<std::underlying_type_t<T>>(v));
  } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
    long long x = static_cast<long long>(v);
    std::snprintf(buf, n, "%lld (0x%llx)", x, static_cast<unsigned long long>(x));
  } else if constexpr (std::is_integral_v<T>) {
    unsigned long long x = static_cast<unsigned long long>(v);
    std::snprintf(buf, n, "%llu (0x%llx)", x, x);
  } else if constexpr (std::is_floating_point_v<T>) {
    std::snprintf(buf, n, "%.17g", static_cast<double>(v));
  } else if constexpr (std::is_pointer_v<T>) {
    std::snprintf(buf, n, "%p", static_cast<const void*>(v));
  } else {
    std::snprintf(buf, n, "<value>");
  }
}

template <class A, class B>
bool check_cmp(bool ok, const char* file, int line, const char* what, const A& a, const B& b) {
  if (ok) return true;
  char da[64], db[64], detail[160];
  describe(da, sizeof da, a);
  describe(db, sizeof db, b);
  std::snprintf(detail, sizeof detail, "left = %s, right = %s", da, db);
  fail(file, line, what, detail);
  return false;
}

enum class Op { kEq, kNe, kLe, kLt, kGe, kGt };

// Evaluates each side once (the macros pass values, not expressions).
template <class A, class B>
bool check_op(Op op, const char* file, int line, const char* what, const A& a, const B& b) {
  bool ok = false;
  switch (op) {
    case Op::kEq: ok = a == b; break;
    case Op::kNe: ok = a != b; break;
    case Op::kLe: ok = a <= b; break;
    case Op::kLt: ok = a < b; break;
    case Op::kGe: ok = a >= b; break;
    case Op::kGt: ok = a > b; break;
  }
  return check_cmp(ok, file, line, what, a, b);
}

template <class A, class B, class C>
bool check_near(const char* file, int line, const char* what, const A& a, const B& b, const C& tol) {
  // Integers and floats alike: |a - b| <= tol, computed in long double to
  // avoid overflow of the difference.
  long double d = static_cast<long double>(a) - static_cast<long double>(b);
  if (d < 0) d = -d;
  if (d <= static_cast<long double>(tol)) return true;
  char da[64], db[64], dt[64], detail[240];
  describe(da, sizeof da, a);
  describe(db, sizeof db, b);
  describe(dt, sizeof dt, tol);
  std::snprintf(detail, sizeof detail, "left = %s, right = %s, |diff| = %.6Lg > tol %s", da, db, d, dt);
  fail(file, line, what, detail);
  return false;
}

// Name of the case running now (empty between cases): tests/golden_check.cpp
// requires it to hold "golden", so `make bless`, which runs those cases, runs
// every check of a golden.
const char* current_case();

// Path of the built dexmill binary (from $DEXMILL), or null.
const char* dexmill_binary();
// Folder of the test sources (for data files), from __FILE__ of the runner.
const char* tests_dir();

}  // namespace t

#define TEST(name)                                                               \
  static void name();                                                            \
  static ::t::Case name##_case_{#name, name, __FILE__, __LINE__, nullptr};       \
  static ::t::Registrar name##_reg_(&name##_case_);                              \
  static void name()

#define CHECK(cond) \
  ((cond) ? true : (::t::fail(__FILE__, __LINE__, "CHECK(" #cond ")", nullptr), false))
#define CHECK_EQ(a, b) ::t::check_op(::t::Op::kEq, __FILE__, __LINE__, "CHECK_EQ(" #a ", " #b ")", (a), (b))
#define CHECK_NE(a, b) ::t::check_op(::t::Op::kNe, __FILE__, __LINE__, "CHECK_NE(" #a ", " #b ")", (a), (b))
#define CHECK_LE(a, b) ::t::check_op(::t::Op::kLe, __FILE__, __LINE__, "CHECK_LE(" #a ", " #b ")", (a), (b))
#define CHECK_LT(a, b) ::t::check_op(::t::Op::kLt, __FILE__, __LINE__, "CHECK_LT(" #a ", " #b ")", (a), (b))
#define CHECK_GE(a, b) ::t::check_op(::t::Op::kGe, __FILE__, __LINE__, "CHECK_GE(" #a ", " #b ")", (a), (b))
#define CHECK_GT(a, b) ::t::check_op(::t::Op::kGt, __FILE__, __LINE__, "CHECK_GT(" #a ", " #b ")", (a), (b))
#define CHECK_NEAR(a, b, tol) ::t::check_near(__FILE__, __LINE__, "CHECK_NEAR(" #a ", " #b ", " #tol ")", (a), (b), (tol))

#endif
