// `dexmill path FILE [--chord MM] [reading options]`: the interpreted motion
// as a polyline: rapid/feed end points of the tool tip in machine
// coordinates, mm with 5 decimals, arcs split into chords.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/math/decimal.h"
#include "core/math/fixed.h"
#include "core/canon/arc_chords.h"
#include "core/interp/interp.h"
#include "platform/input/file_guard.h"
#include "platform/input/gcode_file.h"
#include "platform/os/process.h"
#include "tools/cli/cli.h"
#include "tools/run/guard_inputs.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/read_options.h"

namespace dexmill {
namespace cli {
namespace {

// nm as mm with 5 decimals (rounded to nearest 10 nm, ties away from zero).
char* put_mm5(char* p, int64_t nm) {
  int64_t v = div_round(nm, 10);
  uint64_t a = abs_u64(v);
  if (v < 0) *p++ = '-';
  char tmp[24];
  int k = 0;
  uint64_t ip = a / 100000, fp = a % 100000;
  do { tmp[k++] = static_cast<char>('0' + ip % 10); ip /= 10; } while (ip);
  while (k) *p++ = tmp[--k];
  *p++ = '.';
  for (uint64_t d = 10000; d; d /= 10) *p++ = static_cast<char>('0' + (fp / d) % 10);
  return p;
}

void print_point(std::FILE* out, const char* kind, const PointNm& pt) {
  char line[128];
  char* p = line;
  for (const char* k = kind; *k;) *p++ = *k++;
  *p++ = ' ';
  p = put_mm5(p, pt.x_nm);
  *p++ = ' ';
  p = put_mm5(p, pt.y_nm);
  *p++ = ' ';
  p = put_mm5(p, pt.z_nm);
  *p++ = '\n';
  std::fwrite(line, 1, static_cast<std::size_t>(p - line), out);
}

class PathPrinter final : public CanonSink {
 public:
  PathPrinter(std::FILE* out, int64_t chord_nm) : out_(out), chord_nm_(chord_nm) {}
  void emit(const CanonRecord& r) override {
    switch (r.kind) {
      case CanonKind::kTraverse: print_point(out_, "rapid", r.end); break;
      case CanonKind::kFeed: print_point(out_, "feed", r.end); break;
      case CanonKind::kArc: {
        ArcChords ch;
        ch.init(r, chord_nm_);
        PointNm p;
        while (ch.next(&p)) print_point(out_, "feed", p);
        break;
      }
      default: break;
    }
  }

 private:
  std::FILE* out_;
  int64_t chord_nm_;
};

struct PathArgs {
  std::string file;
  int64_t chord_nm = 1000;
  ReadOptions read;
};

int chord(PathArgs* a, const char* v) {
  Decimal d;
  std::size_t pos = 0, n = std::strlen(v);
  if (decimal_parse(v, n, &pos, &d) != DecimalParse::kOk || pos != n)
    return fail(kExitUsage, "--chord needs a number of mm, not '%s'", v);
  a->chord_nm = decimal_to_nm(d, false);
  if (a->chord_nm < 1 || a->chord_nm > 1000 * kNmPerMm)
    return fail(kExitUsage, "--chord must be between 0.000001 and 1000 mm, not '%s'", v);
  return kExitOk;
}

const Option<PathArgs> kPathOptions[] = {
    {"--chord", "MM", "the most an arc's or spline's chord may stray from it (sagitta; default 0.001)", chord},
};

const CommandText kPathText = {
    "path",
    "usage: dexmill path FILE|- [--chord MM] [reading options]\n\n"
    "Prints the interpreted motion as a polyline: `rapid X Y Z` / `feed X Y Z`,\n"
    "tool tip in machine coordinates (work offsets and G92 applied, tool length\n"
    "offset not applied), mm with 5 decimals. Arcs and splines become chords\n"
    "with sagitta <= --chord mm. Stops at the first error (exit 1).\n",
    nullptr,
};

ReadOptions& read_part(PathArgs& a) { return a.read; }
PathArgs& whole(PathArgs& a) { return a; }

const OptionTable<PathArgs>& path_table() {
  static const OptionTable<PathArgs> t = [] {
    OptionTable<PathArgs> table;
    table.text = &kPathText;
    table.sections.push_back(section<PathArgs>(nullptr, option_list(kPathOptions), whole));
    table.sections.push_back(section<PathArgs>("Reading the program", read_option_list(), read_part));
    table.operand = [](PathArgs* a, const char* arg, int index) -> int { return take_file(&a->file, arg, index); };
    return table;
  }();
  return t;
}

}  // namespace

CommandDoc path_doc() { return command_doc(path_table()); }

int cmd_path(int argc, char** argv) {
  PathArgs a;
  bool help = false;
  const int parsed = parse_options(path_table(), argc, argv, &a, &help);
  if (help) print_help(path_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (a.file.empty()) {
    print_help(path_doc(), stderr);
    return kExitUsage;
  }
  std::string err;
  if (!standard_output_usable(&err)) return fail(kExitIo, "cannot print the path: %s", err.c_str());
  const int64_t chord_nm = a.chord_nm;
  const ReadOptions& ro = a.read;
  FileGuard guard;
  if (const int code = guard_read_inputs(a.file, ro, &guard)) return code;
  if (const int code = guard_status(guard, guard.check_output("", "-"))) return code;
  GcodeFile in;
  if (!in.open(a.file.c_str())) return fail(kExitIo, "%s", in.error());
  in.set_guard(&guard);
  static char outbuf[1 << 16];
  std::setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);
  GcodeStderrMessages msgs(in.name());
  GcodeNotes notes(in.name());
  ReadSetup setup;
  if (const int code = setup.load_tools(ro, a.file)) return code;
  InterpOptions opt;
  setup.apply(ro, &opt, &in);
  opt.warnings = &msgs;
  opt.messages = &notes;
  opt.spline_sagitta_nm = chord_nm;  // splines (G5, G5.1) come as chords of the same sagitta
  PathPrinter printer(stdout, chord_nm);
  Interp interp(&printer, opt);
  char tol[32];
  *put_mm5(tol, chord_nm) = 0;
  // Trim the tolerance to the digits it needs ("0.00100" -> "0.001").
  for (std::size_t k = std::strlen(tol); k > 0 && tol[k - 1] == '0' && tol[k - 2] != '.'; --k) tol[k - 1] = 0;
  std::printf("# dexmill-path v1 units=mm frame=machine tol=%s\n", tol);
  print_point(stdout, "# start", interp.position());
  GcodeRunner runner(&in, &interp, &msgs, true);
  runner.run_all();
  msgs.finish();
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    return fail(kExitIo, "cannot write the path to standard output: %s", std::strerror(errno));
  if (runner.io_error()) return fail(in.refused() ? kExitUsage : kExitIo, "%s", in.error());
  return msgs.errors() ? kExitInput : kExitOk;
}

}  // namespace cli
}  // namespace dexmill
