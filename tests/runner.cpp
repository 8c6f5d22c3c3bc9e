// main() of the test binary: runs every registered case (or those whose name
// contains one of the arguments) and prints `N passed, M failed`.
#include "tests/runner.h"

#include <cstdlib>
#include <cstring>

namespace t {
namespace {
Case* g_head = nullptr;
Case* g_tail = nullptr;
int g_case_failures = 0;
const int kMaxLinesPerCase = 12;  // a broken loop must not flood the log
}  // namespace

Registrar::Registrar(Case* c) {
  // Keep registration order (file order within a TU) for readable output.
  if (g_tail) g_tail->next = c; else g_head = c;
  g_tail = c;
}

void fail(const char* file, int line, const char* what, const char* detail) {
  ++g_case_failures;
  if (g_case_failures > kMaxLinesPerCase) return;
  std::printf("%s:%d: %s failed%s%s\n", file, line, what, detail ? ": " : "", detail ? detail : "");
  if (g_case_failures == kMaxLinesPerCase) std::printf("%s:%d: (further failures of this test not shown)\n", file, line);
}

const char* dexmill_binary() { return std::getenv("DEXMILL"); }

const char* tests_dir() {
  static char dir[512];
  if (!dir[0]) {
    const char* f = __FILE__;  // ".../tests/runner.cpp" or "tests/runner.cpp"
    const char* slash = std::strrchr(f, '/');
    std::size_t n = slash ? static_cast<std::size_t>(slash - f) : 0;
    if (n == 0 || n >= sizeof dir) { std::snprintf(dir, sizeof dir, "tests"); }
    else { std::memcpy(dir, f, n); dir[n] = 0; }
  }
  return dir;
}

}  // namespace t

int main(int argc, char** argv) {
  int passed = 0, failed = 0;
  for (t::Case* c = t::g_head; c; c = c->next) {
    if (argc > 1) {
      bool match = false;
      for (int i = 1; i < argc; ++i) match = match || std::strstr(c->name, argv[i]);
      if (!match) continue;
    }
    t::g_case_failures = 0;
    c->fn();
    if (t::g_case_failures) {
      ++failed;
      std::printf("FAILED %s (%s:%d), %d check(s)\n", c->name, c->file, c->line, t::g_case_failures);
    } else {
      ++passed;
    }
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
