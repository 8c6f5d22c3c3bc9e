// `dexmill run`'s option table and its help; see run_option_table.h.
#include "tools/run/run_option_table.h"

#include "platform/os/process.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/setups_file.h"

namespace dexmill {
namespace cli {
namespace {

const CommandText kRunText = {
    "run",
    "usage: dexmill run [FILE|-] [options]\n\n"
    "Simulates milling a G-code program into a block of stock and writes what you ask\n"
    "for. With no FILE it reads standard input when that is a file or a pipe\n"
    "(`dexmill run < prog.nc`), and runs the built-in demo on a terminal (writes\n"
    "out/demo.ngc, out/final.ppm and out/frames/; anywhere: --demo pocket). Several\n"
    "FILEs are cut in order on one stock (dexmill run A.nc --setup flip-x B.nc): the\n"
    "outputs are the last one's.\n",
    "Window keys: drag orbits, wheel zooms, space pauses, + and - change speed, p shows\n"
    "the toolpath, r resets the view, q quits; a click on the part prints measure --at's\n"
    "line for it. Exit status: 0 ok, 1 input errors (the cut goes up to the first), 2\n"
    "usage, 3 I/O, 4 a check asked for failed (--stop-at, --fail-on-gouge,\n"
    "--fail-on-collision).\n",
};

JobOptions& job_part(RunOptions& o) { return o.job; }
ReadOptions& read_part(RunOptions& o) { return o.job.read; }
OutputOptions& out_part(RunOptions& o) { return o.out; }
ViewOptions& view_part(RunOptions& o) { return o.view; }

OptionTable<RunOptions> make_table() {
  OptionTable<RunOptions> t;
  t.text = &kRunText;
  t.sections.push_back(section<RunOptions>("The job", run_job_options(), job_part));
  t.sections.push_back(section<RunOptions>("Reading the program", read_option_list(), read_part));
  t.sections.push_back(section<RunOptions>("The design part", run_design_options(), job_part));
  t.sections.push_back(section<RunOptions>("Checks", run_check_options(), job_part));
  t.sections.push_back(section<RunOptions>("Files written", run_output_options(), out_part));
  t.sections.push_back(section<RunOptions>("How it is shown", run_view_options(), view_part));
  t.sections.push_back(section<RunOptions>("Live (--window, --fbdev)", run_live_options(), view_part));
  // run takes several programs, cut in order on one stock (run_chain.h).
  t.operand = [](RunOptions* o, const char* arg, int index) -> int {
    ++o->job.operands_seen;
    if (index == 0) return take_file(&o->job.file, arg, 0);
    o->job.chain.push_back(arg);
    return kExitOk;
  };
  return t;
}

}  // namespace

const OptionTable<RunOptions>& run_option_table() {
  static const OptionTable<RunOptions> table = make_table();
  return table;
}

int run_operand(RunOptions* o, const char* arg, int index) { return take_file(&o->job.file, arg, index); }

int parse_run_options(int argc, char** argv, RunOptions* o, bool* help) {
  const int code = parse_options(run_option_table(), argc, argv, o, help);
  if (code != kExitOk || *help) return code;
  if (!o->job.setups_file.empty())
    if (const int read = read_setups_file(o)) return read;
  if (const int chosen = choose_program(o, standard_input_is_terminal())) return chosen;
  return finish_run_options(o);
}

CommandDoc run_doc() { return command_doc(run_option_table()); }

}  // namespace cli
}  // namespace dexmill
