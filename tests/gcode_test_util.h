// Helpers shared by the G-code tests: run text through the interpreter and
// collect records and diagnostics.
#ifndef DEXMILL_TESTS_GCODE_TEST_UTIL_H
#define DEXMILL_TESTS_GCODE_TEST_UTIL_H

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/canon/canon.h"
#include "core/interp/interp.h"
#include "tests/runner.h"

namespace t {

struct Recorder final : dexmill::CanonSink {
  std::vector<dexmill::CanonRecord> records;
  void emit(const dexmill::CanonRecord& r) override { records.push_back(r); }
  size_t count(dexmill::CanonKind k) const {
    size_t n = 0;
    for (const auto& r : records) n += r.kind == k;
    return n;
  }
};

struct Warnings final : dexmill::GcodeDiagSink {
  std::vector<dexmill::GcodeDiag> list;
  void warning(const dexmill::GcodeDiag& d) override { list.push_back(d); }
};

// Runs `program` (lines separated by '\n') and stops at the first error,
// which is returned (kOk if none); *diag receives it.
inline dexmill::GcodeError run_program(dexmill::Interp* in, const char* program, dexmill::GcodeDiag* diag) {
  uint32_t line = 0;
  const char* p = program;
  while (*p) {
    const char* e = std::strchr(p, '\n');
    size_t n = e ? static_cast<size_t>(e - p) : std::strlen(p);
    dexmill::GcodeError err = in->execute_line(p, n, ++line, diag);
    if (err != dexmill::GcodeError::kOk) return err;
    if (!e) break;
    p = e + 1;
  }
  return dexmill::GcodeError::kOk;
}

// A bad last line of a program: the error it gives, at which column.
struct LineError {
  const char* line;
  dexmill::GcodeError error;
  uint16_t col;
};

// Runs `prefix` (whole lines) and then each case's line, in a fresh
// interpreter each, and checks the error, its line and its column.
template <size_t N>
void check_line_errors(const char* prefix, const LineError (&cases)[N]) {
  uint32_t bad_line = 1;
  for (const char* p = prefix; *p; ++p) bad_line += *p == '\n';
  for (const LineError& c : cases) {
    Recorder rec;
    dexmill::InterpOptions opt;
    dexmill::Interp in(&rec, opt);
    dexmill::GcodeDiag d;
    const std::string program = std::string(prefix) + c.line;
    const bool ok = CHECK_EQ(run_program(&in, program.c_str(), &d), c.error) && CHECK_EQ(d.line, bad_line) &&
                    CHECK_EQ(d.col, c.col);
    if (!ok) std::printf("  in: %s\n", c.line);
  }
}

constexpr int64_t mm(double v) { return static_cast<int64_t>(v * 1000000.0 + (v < 0 ? -0.5 : 0.5)); }

}  // namespace t

#endif
