// `dexmill path FILE [--chord MM] [--units mm|inch]`: the interpreted motion
// as a polyline (../shared/CLI.md): rapid/feed end points of the tool tip in
// machine coordinates, mm with 5 decimals, arcs split into chords.
#include <cstdio>
#include <cstring>

#include "core/math/decimal.h"
#include "core/math/fixed.h"
#include "core/motion/arc_chords.h"
#include "core/motion/interp.h"
#include "platform/gcode_file.h"
#include "tools/cli.h"
#include "tools/read_options.h"

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

void usage(std::FILE* f) {
  std::fprintf(f,
               "usage: dexmill path FILE|- [--chord MM] [--units mm|inch] [--default-feed MM/MIN]\n"
               "                           [--subroutine-path DIR] [--max-blocks N]\n"
               "                           [--tools FILE]\n\n"
               "Prints the interpreted motion as a polyline: `rapid X Y Z` / `feed X Y Z`,\n"
               "tool tip in machine coordinates (work offsets and G92 applied, tool length\n"
               "offset not applied), mm with 5 decimals. Arcs and splines become chords\n"
               "with sagitta <= --chord mm (default 0.001). Stops at the first error (exit 1).\n"

               "%s",
               kReadOptionsUsage);
}

}  // namespace

int cmd_path(int argc, char** argv) {
  const char* file = nullptr;
  int64_t chord_nm = 1000;
  ReadOptions ro;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      usage(stdout);
      return kExitOk;
    }
    if (const int taken = take_read_option(argc, argv, &i, &ro)) {
      if (taken < 0) return kExitUsage;
      continue;
    }
    if (!std::strcmp(a, "--chord")) {
      if (i + 1 >= argc) return fail(kExitUsage, "%s needs a value", a);
      const char* v = argv[++i];
      Decimal d;
      std::size_t pos = 0, n = std::strlen(v);
      if (decimal_parse(v, n, &pos, &d) != DecimalParse::kOk || pos != n)
        return fail(kExitUsage, "--chord needs a number of mm, not '%s'", v);
      chord_nm = decimal_to_nm(d, false);
      if (chord_nm < 1 || chord_nm > 1000 * kNmPerMm)
        return fail(kExitUsage, "--chord must be between 0.000001 and 1000 mm, not '%s'", v);
      continue;
    }
    if (const int code = take_input_file("path", a, &file)) return code;
  }
  if (!file) {
    usage(stderr);
    return kExitUsage;
  }
  GcodeFile in;
  if (!in.open(file)) return fail(kExitIo, "%s", in.error());
  static char outbuf[1 << 16];
  std::setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);
  GcodeStderrMessages msgs(in.name());
  GcodeNotes notes(in.name());
  ReadSetup setup;
  if (const int code = setup.load_tools(ro)) return code;
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
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) return fail(kExitIo, "cannot write the path to standard output");
  if (runner.io_error()) return fail(kExitIo, "%s", in.error());
  return msgs.errors() ? kExitInput : kExitOk;
}

}  // namespace cli
}  // namespace dexmill
