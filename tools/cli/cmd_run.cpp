// `dexmill run [FILE|-] [options]`: the options (tools/run/run_option_table.h),
// then the job (tools/run/run_job.h). With no FILE it reads standard input, or
// on a terminal runs the built-in demo (tools/run/run_options.h choose_program).
#include "platform/input/file_guard.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_help.h"
#include "tools/run/run_chain.h"
#include "tools/run/run_demo.h"
#include "tools/run/run_job.h"
#include "tools/run/run_option_table.h"

namespace dexmill {
namespace cli {

int cmd_run(int argc, char** argv) {
  RunOptions o;
  bool help = false;
  const int code = parse_run_options(argc, argv, &o, &help);
  if (help) print_help(run_doc(), stdout);
  if (code != kExitOk || help) return code;
  FileGuard guard;  // every file the run reads, writes or removes (platform/input/file_guard.h)
  if (!o.job.demo.empty()) return run_demo(o, &guard);
  if (!o.job.chain.empty() || !o.job.steps.empty()) return run_chain(o);
  return run_job(o, &guard);
}

}  // namespace cli
}  // namespace dexmill
