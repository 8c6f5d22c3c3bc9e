// The reading options; see read_options.h.
#include "tools/run/read_options.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/math/decimal.h"
#include "tools/cli/cli.h"
#include "tools/run/run_tool_table.h"

namespace dexmill {
namespace cli {
namespace {

int parse_units(ReadOptions* o, const char* v) {
  if (!std::strcmp(v, "mm")) o->inch = false;
  else if (!std::strcmp(v, "inch")) o->inch = true;
  else return fail(kExitUsage, "--units must be mm or inch, not '%s'", v);
  o->units_given = true;
  return kExitOk;
}

int parse_tool_units(ReadOptions* o, const char* v) {
  if (!std::strcmp(v, "mm")) o->tool_units = ReadOptions::ToolUnits::kMm;
  else if (!std::strcmp(v, "inch")) o->tool_units = ReadOptions::ToolUnits::kInch;
  else return fail(kExitUsage, "--tool-units must be mm or inch, not '%s'", v);
  return kExitOk;
}

int parse_default_feed(ReadOptions* o, const char* v) {
  Decimal d;
  std::size_t pos = 0, n = std::strlen(v);
  const bool number = n && decimal_parse(v, n, &pos, &d) == DecimalParse::kOk && pos == n;
  o->default_feed_nm_per_min = number ? decimal_to_nm(d, false) : 0;
  if (o->default_feed_nm_per_min < 1000 || o->default_feed_nm_per_min > 1000000 * 1000000LL)
    return fail(kExitUsage, "--default-feed needs a feed in mm/min, from 0.001 to 1000000, not '%s'", v);
  return kExitOk;
}

int parse_subroutine_path(ReadOptions* o, const char* v) {
  if (!*v) return fail(kExitUsage, "--subroutine-path needs a directory");
  for (const char* p = v; *p;) {
    const char* e = std::strchr(p, ':');
    const std::size_t n = e ? static_cast<std::size_t>(e - p) : std::strlen(p);
    if (n) o->subroutine_path.emplace_back(p, n);
    p += n + (e ? 1 : 0);
  }
  return kExitOk;
}

int parse_max_blocks(ReadOptions* o, const char* v) {
  char* end = nullptr;
  const unsigned long long n = std::strtoull(v, &end, 10);
  if (!*v || *end || v[0] == '-' || n > 1000000000000ULL)
    return fail(kExitUsage, "--max-blocks needs a count from 0 (no limit) to 1000000000000, not '%s'", v);
  o->max_blocks = n;
  return kExitOk;
}

const Option<ReadOptions> kReadOptions[] = {
    {"--units", "mm|inch",
     "units of programs that set none (G20/G21) before they move (default mm; without the option such a program "
     "is warned of, and warned loudly when its numbers look like inches)",
     parse_units},
    {"--tool-units", "mm|inch",
     "units of the --tools table (default: the program's when it sets G20/G21 before its first T, else --units)",
     parse_tool_units},
    {"--default-feed", "MM/MIN",
     "the controller's feed for moves made with no F in force (warned once; default: none, such a move is an "
     "error)",
     parse_default_feed},
    {"--subroutine-path", "DIR[:DIR]",
     "where `o<name> call` finds NAME.ngc when the program does not define the subroutine (LinuxCNC's "
     "SUBROUTINE_PATH)",
     parse_subroutine_path},
    {"--max-blocks", "N",
     "blocks a program may run once it loops or calls (default 10000000; 0: no limit); an endless loop stops "
     "with an error naming it",
     parse_max_blocks},
    {"--tools", "FILE",
     "a LinuxCNC tool table: T/M6 pick from it, G43 takes the tool length and G41/G42 the radius (D/2) from it "
     "(without a table run takes --tool's, or the program's tool comments'; path and check take 0, with a warning); "
     "run takes a T the table lacks from the program's comments",
     [](ReadOptions* o, const char* v) -> int { return o->tools_file = v, kExitOk; }},
};

}  // namespace

OptionList<ReadOptions> read_option_list() { return option_list(kReadOptions); }

int ReadSetup::load_tools(const ReadOptions& o, const std::string& program) {
  if (o.tools_file.empty()) return kExitOk;
  if (const int code = load_read_tool_table(o, program, &table)) return code;
  for (const std::string& w : table.warnings()) std::fprintf(stderr, "%s\n", w.c_str());
  have_table = true;
  return kExitOk;
}

void ReadSetup::apply(const ReadOptions& o, InterpOptions* opt, GcodeFile* file) {
  opt->inch = o.inch;
  opt->units_given = o.units_given;
  opt->feed_in_line_units = o.feed_in_line_units;
  opt->default_feed_nm_per_min = o.default_feed_nm_per_min;
  opt->max_blocks = o.max_blocks;
  memory->attach(opt);
  if (have_table) opt->tools = &table;
  if (file) file->set_subroutine_path(o.subroutine_path);
}

}  // namespace cli
}  // namespace dexmill
