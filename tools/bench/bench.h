// `dexmill bench`: benchmarks register themselves (BENCH below), one result
// line each: "name=NAME key=value ...".
#ifndef DEXMILL_TOOLS_BENCH_BENCH_H
#define DEXMILL_TOOLS_BENCH_BENCH_H

namespace dexmill {
namespace bench {

struct Case {
  const char* name;   // e.g. "paper-w3"; `dexmill bench NAME...` selects by prefix
  void (*run)(const char* name);
  Case* next;
};

struct Registrar {
  explicit Registrar(Case* c);
};

// Monotonic wall clock in seconds.
double now_s();

// Prints one result line: "name=NAME " followed by the formatted pairs.
void result(const char* name, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

// Runs `fn` repeatedly until at least `min_s` seconds have passed (at least
// once) and returns the fastest single run: the figure least disturbed by
// other load on a shared machine. `fn` returns the seconds it measured
// itself, so that set-up work in it (resetting a grid) is not counted.
template <class F>
double best_time_s(F fn, double min_s = 0.2, int max_runs = 50) {
  double best = 1e300, start = now_s();
  for (int run = 0; run < max_runs; ++run) {
    double dt = fn();
    if (dt < best) best = dt;
    if (now_s() - start >= min_s) break;
  }
  return best;
}

Case* first();

// True with `dexmill bench --once`: every figure from a single run (for
// instruction counts under valgrind, where repeats only multiply the total).
bool single_run();

}  // namespace bench
}  // namespace dexmill

#define BENCH(ident, name_str, fn)                                                   \
  static ::dexmill::bench::Case ident##_bench_case_{name_str, fn, nullptr};         \
  static ::dexmill::bench::Registrar ident##_bench_reg_(&ident##_bench_case_)

#endif
