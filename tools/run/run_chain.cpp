// tools/run/run_chain.h: a chain of programs on one stock.
#include "tools/run/run_chain.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tools/cli/cli.h"
#include "tools/run/guard_inputs.h"
#include "tools/run/run_job.h"
#include "tools/run/setups_file.h"

namespace dexmill {
namespace cli {
namespace {

// The stock between programs k and k + 1: the temporary folder's, named for
// this process (removed when the chain ends, however it ends).
std::string link_path(size_t k) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/dexmill-chain-" + std::to_string(static_cast<long>(getpid())) +
         "-" + std::to_string(k) + ".dxstock";
}

struct Links {
  std::vector<std::string> paths;
  ~Links() {
    for (const std::string& p : paths) std::remove(p.c_str());
  }
};

// The setups before a program, as one: "none" when it has none.
std::string setup_words(const JobOptions& j) {
  if (j.setups.empty()) return "none";
  std::string o;
  for (size_t s = 0; s < j.setup_texts.size(); ++s) o += (s ? "+" : "") + j.setup_texts[s];
  return o;
}

}  // namespace

int run_chain(const RunOptions& o) {
  const size_t n = 1 + o.job.chain.size();
  Links links;
  std::vector<ProgramFindings> findings;  // each program's, for the last one's report
  for (size_t k = 0; k < n; ++k) {
    RunOptions one = o;
    one.job.chain.clear();
    one.job.file = k == 0 ? o.job.file : o.job.chain[k - 1];
    one.job.setups.clear();
    one.job.setup_texts.clear();
    one.job.setup_program.clear();
    for (size_t s = 0; s < o.job.setups.size(); ++s)
      if (o.job.setup_program[s] == static_cast<int>(k)) {
        one.job.setups.push_back(o.job.setups[s]);
        one.job.setup_texts.push_back(o.job.setup_texts[s]);
      }
    if (k < o.job.steps.size())
      if (const int code = apply_step(o.job.steps[k], &one)) return code;  // checked when the file was read
    one.job.chain_findings = findings;
    if (k > 0) {  // the stock the program before left
      one.job.stock_file = links.paths.back();
      one.job.have_stock = false;
      one.job.stock_stl.clear();
      one.job.grid_nx = one.job.grid_ny = 0;
      one.job.pitch_nm = 0;
    }
    if (k + 1 < n) {  // only its stock, for the next
      one.out = OutputOptions{};
      one.out.print_summary = false;
      one.view.window = false;
      one.view.fbdev.clear();
      links.paths.push_back(link_path(k));
      one.out.save_stock = links.paths.back();
    }
    // Each program's files (the stock between two is a new name), and the
    // chain's other programs: no output of the last may replace one.
    FileGuard guard;
    if (const int c = guard_status(guard, guard.register_input(o.job.setups_file, "--setups"))) return c;
    for (size_t p = 0; p < n; ++p)
      if (p != k) {
        const std::string& file = p == 0 ? o.job.file : o.job.chain[p - 1];
        if (const int c = guard_status(guard, guard.register_input(file, FileGuard::kProgram))) return c;
      }
    if (n > 1 && !one.view.quiet)
      std::fprintf(stderr, "dexmill: program %zu of %zu, %s, setup %s\n", k + 1, n, one.job.file.c_str(),
                   setup_words(one.job).c_str());
    RunResult result;
    const int code = run_job(one, &guard, &result);
    if (code != kExitOk) return code;
    findings.push_back(result.findings);
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
