// main() of the test binary: runs every registered case (or those whose name
// contains one of the arguments; with `--jobs N` in N processes) and prints
// `N passed, M failed`.
#include "tests/runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace t {
namespace {
Case* g_head = nullptr;
Case* g_tail = nullptr;
int g_case_failures = 0;
const char* g_current = "";
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

const char* current_case() { return g_current; }

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

namespace {

// Runs case c; true when it passed.
bool run_case(t::Case* c) {
  t::g_case_failures = 0;
  t::g_current = c->name;
  c->fn();
  t::g_current = "";
  if (!t::g_case_failures) return true;
  std::printf("FAILED %s (%s:%d), %d check(s)\n", c->name, c->file, c->line, t::g_case_failures);
  return false;
}

// With --jobs N (N > 1) the cases run in N worker processes, which take
// the next case from a pipe as they become free (the oracle tests take
// seconds, most cases milliseconds); each worker's output is line by line,
// and its counts come back on a second pipe. The cases share nothing but
// the files they name (each process has its own temporary folder).
void run_parallel(const std::vector<t::Case*>& cases, int jobs, int* passed, int* failed) {
  int work[2], counts[2];
  if (pipe(work) != 0 || pipe(counts) != 0) {
    std::perror("runner: pipe");
    std::exit(2);
  }
  for (uint32_t k = 0; k < cases.size(); ++k)
    if (write(work[1], &k, sizeof k) != static_cast<ssize_t>(sizeof k)) std::exit(2);  // within the pipe's buffer
  close(work[1]);
  std::fflush(stdout);
  for (int w = 0; w < jobs; ++w) {
    if (fork() != 0) continue;
    setvbuf(stdout, nullptr, _IOLBF, 0);
    int32_t mine[2] = {0, 0};
    uint32_t k;
    while (read(work[0], &k, sizeof k) == static_cast<ssize_t>(sizeof k)) ++mine[run_case(cases[k]) ? 0 : 1];
    std::fflush(stdout);
    if (write(counts[1], mine, sizeof mine) != static_cast<ssize_t>(sizeof mine)) _exit(2);
    _exit(0);
  }
  close(work[0]);
  close(counts[1]);
  int32_t got[2];
  int reported = 0;
  while (read(counts[0], got, sizeof got) == static_cast<ssize_t>(sizeof got)) {
    *passed += got[0];
    *failed += got[1];
    ++reported;
  }
  int status = 0;
  while (wait(&status) > 0) {
  }
  if (reported != jobs) {
    std::printf("runner: %d of %d workers did not report (a case crashed one)\n", jobs - reported, jobs);
    ++*failed;
  }
}

}  // namespace

int main(int argc, char** argv) {
  int passed = 0, failed = 0, jobs = 1;
  std::vector<t::Case*> cases;
  std::vector<const char*> names;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--jobs") && i + 1 < argc) jobs = std::atoi(argv[++i]);
    else names.push_back(argv[i]);
  }
  for (t::Case* c = t::g_head; c; c = c->next) {
    bool match = names.empty();
    for (const char* n : names) match = match || std::strstr(c->name, n);
    if (match) cases.push_back(c);
  }
  if (jobs > 1) {
    run_parallel(cases, jobs, &passed, &failed);
  } else {
    for (t::Case* c : cases) ++(run_case(c) ? passed : failed);
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
