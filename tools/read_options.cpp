// The reading options; see read_options.h.
#include "tools/read_options.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "tools/cli.h"
#include "tools/run_tool_table.h"

namespace dexmill {
namespace cli {

const char kReadOptionsUsage[] =
    "--units mm|inch: units before any G20/G21 (mm).\n"
    "--default-feed MM/MIN: the controller's feed for moves made with no F in force\n"
    "  (warned once; without it such a move is an error).\n"
    "--subroutine-path DIR[:DIR...]: where `o<name> call` finds NAME.ngc when the\n"
    "  program does not define the subroutine (LinuxCNC's SUBROUTINE_PATH).\n"
    "--max-blocks N: blocks a program may run once it loops or calls (default\n"
    "  10000000; 0: no limit); an endless loop stops with an error naming it.\n"
    "--tools FILE: a LinuxCNC tool table: G41/G42 take the tool radius (D / 2)\n"
    "  from it (without one the radius is 0, with a warning), G43 the length.\n";

int take_read_option(int argc, char** argv, int* i, ReadOptions* o) {
  const char* a = argv[*i];
  const bool known = !std::strcmp(a, "--units") || !std::strcmp(a, "--default-feed") ||
                     !std::strcmp(a, "--subroutine-path") || !std::strcmp(a, "--max-blocks") ||
                     !std::strcmp(a, "--tools");
  if (!known) return 0;
  if (*i + 1 >= argc) return fail(kExitUsage, "%s needs a value", a), -1;
  const char* v = argv[++*i];
  if (!std::strcmp(a, "--tools")) return o->tools_file = v, 1;
  if (!std::strcmp(a, "--units")) return parse_units(v, &o->inch) ? 1 : -1;
  if (!std::strcmp(a, "--default-feed")) return parse_default_feed(v, &o->default_feed_nm_per_min) ? 1 : -1;
  if (!std::strcmp(a, "--subroutine-path")) {
    if (!*v) return fail(kExitUsage, "--subroutine-path needs a directory"), -1;
    for (const char* p = v; *p;) {
      const char* e = std::strchr(p, ':');
      const std::size_t n = e ? static_cast<std::size_t>(e - p) : std::strlen(p);
      if (n) o->subroutine_path.emplace_back(p, n);
      p += n + (e ? 1 : 0);
    }
    return 1;
  }
  char* end = nullptr;
  const unsigned long long n = std::strtoull(v, &end, 10);
  if (!*v || *end || v[0] == '-' || n > 1000000000000ULL)
    return fail(kExitUsage, "--max-blocks needs a count from 0 (no limit) to 1000000000000, not '%s'", v), -1;
  o->max_blocks = n;
  return 1;
}

int ReadSetup::load_tools(const ReadOptions& o) {
  if (o.tools_file.empty()) return kExitOk;
  if (const int code = load_tool_table(o.tools_file, o.inch, &table)) return code;
  for (const std::string& w : table.warnings()) std::fprintf(stderr, "%s\n", w.c_str());
  have_table = true;
  return kExitOk;
}

void ReadSetup::apply(const ReadOptions& o, InterpOptions* opt, GcodeFile* file) {
  opt->inch = o.inch;
  opt->default_feed_nm_per_min = o.default_feed_nm_per_min;
  opt->max_blocks = o.max_blocks;
  memory->attach(opt);
  if (have_table) opt->tools = &table;
  if (file) file->set_subroutine_path(o.subroutine_path);
}

}  // namespace cli
}  // namespace dexmill
