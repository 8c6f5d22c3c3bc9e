// `dexmill bench [NAME...]`: runs the registered benchmarks whose name starts
// with one of the arguments (all without arguments), one result line each.
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "tools/bench.h"
#include "tools/cli.h"

namespace dexmill {
namespace bench {
namespace {
Case* g_head = nullptr;
Case* g_tail = nullptr;
bool g_once = false;
}  // namespace

bool single_run() { return g_once; }

Registrar::Registrar(Case* c) {
  if (g_tail) g_tail->next = c; else g_head = c;
  g_tail = c;
}

Case* first() { return g_head; }

double now_s() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void result(const char* name, const char* fmt, ...) {
  std::printf("name=%s ", name);
  va_list ap;
  va_start(ap, fmt);
  std::vprintf(fmt, ap);
  va_end(ap);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace bench

namespace cli {

int cmd_bench(int argc, char** argv) {
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::printf("usage: dexmill bench [--list] [--once] [NAME...]\n  Runs the benchmarks whose names start with a NAME (all without one).\n");
      return kExitOk;
    }
    if (!std::strcmp(argv[i], "--list")) list = true;
    else if (!std::strcmp(argv[i], "--once")) bench::g_once = true;
    else if (argv[i][0] == '-') return fail(kExitUsage, "bench: unknown option '%s'", argv[i]);
  }
  int ran = 0;
  for (bench::Case* c = bench::first(); c; c = c->next) {
    bool selected = true;
    int names = 0;
    for (int i = 1; i < argc; ++i) {
      if (argv[i][0] == '-') continue;
      if (names++ == 0) selected = false;
      if (!std::strncmp(c->name, argv[i], std::strlen(argv[i]))) selected = true;
    }
    if (!selected) continue;
    ++ran;
    if (list) std::printf("%s\n", c->name);
    else c->run(c->name);
  }
  if (!ran) return fail(kExitUsage, "bench: no benchmark matches (try 'dexmill bench --list')");
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
