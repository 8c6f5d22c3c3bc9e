// `dexmill run` and `check` on a program's units and its tool table's
// (core/interp/units_guess.h, core/sim/tool_units.h): the warnings at the
// first move, counted in the summary and listed in the report, and
// --tool-units. The programs are written here.
#include <algorithm>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace run_cli;

namespace {

// A 3 x 2 inch pocket outline without its G20 (line 2 is its first move).
const char kInch[] =
    "G90 G17\n"
    "G0 Z0.1\n"
    "G0 X0.5 Y0.5\n"
    "G1 Z-0.05 F10\n"
    "G1 X3.5 F20\n"
    "G1 Y2.5\n"
    "G0 Z0.1\n"
    "M2\n";

// The same in mm.
const char kMm[] =
    "G90 G17\n"
    "G0 Z2.5\n"
    "G0 X12.7 Y12.7\n"
    "G1 Z-1.27 F250\n"
    "G1 X88.9 F500\n"
    "G1 Y63.5\n"
    "G0 Z2.5\n"
    "M2\n";

const char kArgs[] = " --tool flat:3 --stock 0,0,-5,100,70,0 --pitch 0.5";

const char kPlain[] = "no G20/G21 before the first move: the program is read in mm";
const char kLoud[] = "the program never sets its units and its numbers look like inches";

}  // namespace

TEST(run_units_inch_looking_program_warns_loudly) {
  if (skip()) return;
  write_tmp("u_inch.ngc", kInch);
  const Result r = run(std::string("u_inch.ngc") + kArgs + " --report %/u_inch.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, (std::string("u_inch.ngc:2:1: warning: ") + kPlain).c_str()));
  CHECK(has(r.err, (std::string("u_inch.ngc:2:1: warning: ") + kLoud).c_str()));
  CHECK(has(run(std::string("u_inch.ngc") + kArgs, nullptr, true).out, "warnings 2"));
  const std::string rep = slurp(tmp_dir() + "/u_inch.json");
  CHECK(has(rep, "\"warnings_total\": 2"));
  CHECK(has(rep, kPlain));
  CHECK(has(rep, kLoud));
  // check says the same.
  const Result c = run_command("check " + tmp_dir() + "/u_inch.ngc");
  CHECK_EQ(c.code, 0);
  CHECK(has(c.err, kPlain));
  CHECK(has(c.err, kLoud));
}

TEST(run_units_mm_program_warns_plainly) {
  if (skip()) return;
  write_tmp("u_mm.ngc", kMm);
  const Result r = run(std::string("u_mm.ngc") + kArgs + " --report %/u_mm.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, (std::string("u_mm.ngc:2:1: warning: ") + kPlain).c_str()));
  CHECK(r.err.find(kLoud) == std::string::npos);
  CHECK(has(run(std::string("u_mm.ngc") + kArgs, nullptr, true).out, "warnings 1"));
  const std::string rep = slurp(tmp_dir() + "/u_mm.json");
  CHECK(has(rep, "\"warnings_total\": 1"));
  CHECK(rep.find(kLoud) == std::string::npos);
  const Result c = run_command("check " + tmp_dir() + "/u_mm.ngc");
  CHECK(has(c.err, kPlain));
  CHECK(c.err.find(kLoud) == std::string::npos);
}

TEST(run_units_set_or_given_warn_nothing) {
  if (skip()) return;
  write_tmp("u_g20.ngc", (std::string("G20\n") + kInch).c_str());
  write_tmp("u_g21.ngc", (std::string("G21\n") + kMm).c_str());
  write_tmp("u_inch2.ngc", kInch);
  for (const char* args : {"u_g20.ngc", "u_g21.ngc", "u_inch2.ngc --units inch", "u_inch2.ngc --units mm"}) {
    const Result r = run(std::string(args) + kArgs, nullptr, true);
    CHECK_EQ(r.code, 0);
    CHECK(r.err.find("G20/G21") == std::string::npos);
    CHECK(r.err.find("inches") == std::string::npos);
    CHECK(has(r.out, "warnings 0"));
  }
  const Result c = run_command("check " + tmp_dir() + "/u_g20.ngc");
  CHECK_EQ(c.code, 0);
  CHECK(has(c.err, "u_g20.ngc: ok, 9 blocks, 0 warnings"));  // check's one line, and nothing else
  CHECK(c.err.find(": warning") == std::string::npos);
  CHECK_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1);
}

TEST(run_units_tool_table_in_the_programs_units) {
  if (skip()) return;
  write_tmp("quarter.tbl", "T1 P1 D0.25 Z0 ;flat end mill\n");
  write_tmp("u_t_inch.ngc", (std::string("G20\nT1 M6\n") + kInch).c_str());
  write_tmp("u_t_late.ngc", (std::string("T1 M6\nG20\n") + kInch).c_str());
  const std::string common = " --tools quarter.tbl --stock 0,0,-5,100,70,0 --pitch 0.5 --report %/";
  // G20 before the T: the table is in inch, D0.25 is a 6.35 mm tool.
  const Result a = run("u_t_inch.ngc" + common + "t_inch.json", nullptr, true);
  CHECK_EQ(a.code, 0);
  const std::string ra = slurp(tmp_dir() + "/t_inch.json");
  CHECK(has(ra, "\"table_units\": \"inch\""));
  CHECK(has(ra, "{\"number\": 1, \"spec\": \"flat:6.35\", \"source\": \"table\""));
  // --tool-units says otherwise: a quarter of a millimetre.
  const Result b = run("u_t_inch.ngc --tool-units mm" + common + "t_mm.json", nullptr, true);
  CHECK_EQ(b.code, 0);
  const std::string rb = slurp(tmp_dir() + "/t_mm.json");
  CHECK(has(rb, "\"table_units\": \"mm\""));
  CHECK(has(rb, "{\"number\": 1, \"spec\": \"flat:0.25\", \"source\": \"table\""));
  // The units come after the T: --units (mm by default), or --tool-units.
  const Result c = run("u_t_late.ngc" + common + "t_late.json", nullptr, true);
  CHECK_EQ(c.code, 0);
  CHECK(has(slurp(tmp_dir() + "/t_late.json"), "\"spec\": \"flat:0.25\", \"source\": \"table\""));
  const Result d = run("u_t_late.ngc --tool-units inch" + common + "t_late_i.json", nullptr, true);
  CHECK_EQ(d.code, 0);
  CHECK(has(slurp(tmp_dir() + "/t_late_i.json"), "\"spec\": \"flat:6.35\", \"source\": \"table\""));
  const Result e = run("u_t_late.ngc --units inch" + common + "t_late_u.json", nullptr, true);
  CHECK_EQ(e.code, 0);
  CHECK(has(slurp(tmp_dir() + "/t_late_u.json"), "\"spec\": \"flat:6.35\", \"source\": \"table\""));
  // A bad value is a usage error.
  const Result f = run("u_t_inch.ngc --tool-units feet" + common + "t_bad.json", nullptr, true);
  CHECK_EQ(f.code, 2);
  CHECK(has(f.err, "--tool-units must be mm or inch, not 'feet'"));
}
