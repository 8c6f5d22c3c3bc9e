// `dexmill bench [NAME...]`: runs the registered benchmarks whose name starts
// with one of the arguments (all without arguments), one result line each.
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "tools/bench/bench.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"

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
namespace {

struct BenchArgs {
  bool list = false;
  std::vector<std::string> names;  // prefixes; none: every benchmark
};

const Option<BenchArgs> kBenchOptions[] = {
    {"--list", nullptr, "print the names of the benchmarks instead of running them",
     [](BenchArgs* a, const char*) -> int { return a->list = true, kExitOk; }},
    {"--once", nullptr, "every figure from a single run (for instruction counts under valgrind)",
     [](BenchArgs*, const char*) -> int { return bench::g_once = true, kExitOk; }},
};

const CommandText kBenchText = {
    "bench",
    "usage: dexmill bench [--list] [--once] [NAME...]\n"
    "  Runs the benchmarks whose names start with a NAME (all without one).\n",
    nullptr,
    "bench: ",
    false,
};

const OptionTable<BenchArgs>& bench_table() {
  static const OptionTable<BenchArgs> t = [] {
    OptionTable<BenchArgs> table;
    table.text = &kBenchText;
    table.sections.push_back(section<BenchArgs>(nullptr, option_list(kBenchOptions), [](BenchArgs& a) -> BenchArgs& { return a; }));
    table.operand = [](BenchArgs* a, const char* arg, int) -> int { return a->names.emplace_back(arg), kExitOk; };
    return table;
  }();
  return t;
}

}  // namespace

CommandDoc bench_doc() { return command_doc(bench_table()); }

int cmd_bench(int argc, char** argv) {
  BenchArgs a;
  bool help = false;
  const int parsed = parse_options(bench_table(), argc, argv, &a, &help);
  if (help) print_help(bench_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  int ran = 0;
  for (bench::Case* c = bench::first(); c; c = c->next) {
    bool selected = a.names.empty();
    for (const std::string& n : a.names)
      if (!std::strncmp(c->name, n.c_str(), n.size())) selected = true;
    if (!selected) continue;
    ++ran;
    if (a.list) std::printf("%s\n", c->name);
    else c->run(c->name);
  }
  if (!ran) return fail(kExitUsage, "bench: no benchmark matches (try 'dexmill bench --list')");
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
