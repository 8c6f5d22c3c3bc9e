// `dexmill zig` (paper §3): programs generated from design parts the test
// writes (a PGM relief with a raised block, steep steps and a pit; an STL
// pyramid) are cut on the engine with the job of the same options and the
// design (tests/sim_util.h): no gouge, lifted or zigzag, along x or y, with
// a flat or a ball, and no warning reading them; the header says how the
// program was made and how to simulate it; usage errors.
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

namespace {

using namespace run_cli;

// A 60 x 40 px relief: waves, a raised block with vertical sides, a pit.
std::string relief_pgm() {
  std::string s = "P5\n60 40\n255\n";
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 60; ++i) {
      const double x = i / 60.0, y = j / 40.0;
      double z = 0.5 + 0.25 * std::sin(6 * x) * std::cos(5 * y);
      if (x > 0.3 && x < 0.5 && y > 0.3 && y < 0.6) z = 0.95;
      if ((x - 0.75) * (x - 0.75) + (y - 0.5) * (y - 0.5) < 0.01) z = 0.1;
      s.push_back(char(int(z * 255)));
    }
  return s;
}

// The stock, tool and grid a program is made for and cut with, and the
// design's heights (a PGM's; null for an STL).
struct Job {
  const char* stock;
  const char* tool;
  const char* pitch;
  const char* z_low;
  const char* z_high;
  // As `dexmill zig` and `dexmill run` take them.
  std::string options() const {
    return std::string("--stock ") + stock + " --tool " + tool + " --pitch " + pitch +
           (z_low ? std::string(" --design-z ") + z_low + "," + z_high : std::string());
  }
};

const Job kRelief{"0,0,-20,60,40,0", "ball:4", "0.25", "-14", "-2"};

struct Assessment {
  bool ok = false;
  std::string text;
};

// Generates with `dexmill zig` (and zig_args), cuts the program on the
// engine with the same job and the design (as `dexmill run PROGRAM
// OPTIONS --design DESIGN` would), returns the report's assessment.
// *r, when given, is the run.
Assessment zig_then_cut(const std::string& design, const Job& job, const std::string& zig_args, const char* name,
                        sim_test::Run* r = nullptr) {
  Assessment a;
  const std::string prog = tmp_dir() + "/" + name + ".ngc";
  const Result z = run_command("zig " + design + " " + job.options() + " " + zig_args + " -o " + prog);
  CHECK_EQ(z.code, 0);
  if (z.code != 0) {
    std::printf("%s\n", z.err.c_str());
    return a;
  }
  CHECK(has(z.err, "dexmill zig: grid"));
  sim_test::Run own;
  sim_test::Run& run = r ? *r : own;
  run.stock(job.stock).tool(job.tool).pitch(job.pitch).design(design);
  if (job.z_low) run.design_z(job.z_low, job.z_high);
  if (!run.program(prog)) return a;
  CHECK(run.sim().state() == dexmill::SimState::kDone);
  CHECK_EQ(run.scan_errors(), 0u);
  a.text = run.assessment();
  a.ok = run.sim().state() == dexmill::SimState::kDone;
  return a;
}

}  // namespace

TEST(zig_programs_cut_no_gouge) {
  if (skip()) return;
  std::string pgm = relief_pgm();
  FILE* f = std::fopen((tmp_dir() + "/relief.pgm").c_str(), "wb");
  std::fwrite(pgm.data(), 1, pgm.size(), f);
  std::fclose(f);
  const std::string design = tmp_dir() + "/relief.pgm";
  struct Case {
    const char* name;
    Job job;
    const char* zig;
  } cases[] = {
      {"ball-x", kRelief, ""},
      {"ball-y-zigzag", kRelief, "--direction y --zigzag --stepover 0.5 --step 0.75"},
      {"flat-x", Job{"0,0,-20,60,40,0", "flat:3", "0.25", "-14", "-2"}, "--stepover 1"},
      {"bull-zigzag", Job{"0,0,-20,60,40,0", "bull:6:1.5", "0.25", "-14", "-2"}, "--zigzag"},
  };
  for (const Case& c : cases) {
    const Assessment a = zig_then_cut(design, c.job, c.zig, c.name);
    if (!a.ok) continue;
    // No column of the part cut below it (the gouge watch and the
    // assessment agree), and most of the surface within 0.05 mm.
    CHECK(has(a.text, "\"max_gouge\": null"));
    CHECK(has(a.text, "\"gouges_total\": 0"));
    if (!has(a.text, "\"max_gouge\": null")) std::printf("%s: %s\n", c.name, a.text.c_str());
  }
  // With an allowance the whole surface keeps at least that much.
  const Assessment a = zig_then_cut(design, kRelief, "--allowance 0.3", "allowance");
  CHECK(has(a.text, "\"max_gouge\": null"));
  CHECK(has(a.text, "\"within_tolerance_percent\": 0.00"));
}

TEST(zig_program_header_and_stl_design) {
  if (skip()) return;
  // A pyramid 10 mm high on a 40 x 40 mm plate 5 mm thick (ASCII STL).
  const std::string stl = write_tmp("pyramid.stl",
                                    "solid p\n"
                                    "facet normal 0 0 1\nouter loop\nvertex 0 0 -15\nvertex 40 0 -15\nvertex 20 20 -5\nendloop\nendfacet\n"
                                    "facet normal 0 0 1\nouter loop\nvertex 40 0 -15\nvertex 40 40 -15\nvertex 20 20 -5\nendloop\nendfacet\n"
                                    "facet normal 0 0 1\nouter loop\nvertex 40 40 -15\nvertex 0 40 -15\nvertex 20 20 -5\nendloop\nendfacet\n"
                                    "facet normal 0 0 1\nouter loop\nvertex 0 40 -15\nvertex 0 0 -15\nvertex 20 20 -5\nendloop\nendfacet\n"
                                    "endsolid p\n");
  const Job job{"0,0,-20,40,40,0", "ball:6", "0.25", nullptr, nullptr};
  const std::string shared = job.options();
  sim_test::Run cut;
  const Assessment a = zig_then_cut(stl, job, "--stepover 1", "pyramid", &cut);
  CHECK(has(a.text, "\"max_gouge\": null"));
  // The header: how it was made, how to simulate it; then plain G-code that
  // dexmill reads without a warning (as `dexmill check` would say).
  const std::string prog = slurp(tmp_dir() + "/pyramid.ngc");
  CHECK(has(prog, "(dexmill zig: "));
  CHECK(has(prog, "tool ball:6, stripes along x every 1.0000 mm"));
  CHECK(has(prog, "(simulate with: dexmill run PROGRAM --stock 0.000,0.000,-20.000,40.000,40.000,0.000 --pitch 0.2500"));
  CHECK(has(prog, "G21 G90 G17 G94\nS12000 M3\nG0 Z5\n"));
  CHECK_EQ(cut.scan_errors() + cut.scan_warnings(), 0u);
  Result r;
  // To standard output when no -o.
  r = run_command("zig " + stl + " " + shared + " --stepover 4");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "M30\n"));
  // Without --tool, a 3 mm ball; without a material, the default feeds.
  r = run_command("zig " + stl + " --stock 0,0,-20,40,40,0 --stepover 4");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, ", tool ball:3, "));
  CHECK(has(r.out, "S12000 M3"));
  CHECK(has(r.out, " F300\n"));
  // With a material preset, within its limits (bronze: 400 mm/min, 1500..8000 rpm).
  r = run_command("zig " + stl + " --stock 0,0,-20,40,40,0 --stepover 4 --material bronze");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "S8000 M3"));
  CHECK(has(r.out, " F400\n"));
}

TEST(zig_usage_errors) {
  if (skip()) return;
  const std::string stl = write_tmp("flat.stl",
                                    "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 -5\nvertex 10 0 -5\nvertex 10 10 -5\nendloop\n"
                                    "endfacet\nendsolid f\n");
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"", "zig needs a DESIGN"},
      {" --tool ball:3", "zig needs --stock"},
      {" --stock 0,0,-10,10,10,0 --direction z", "--direction must be x or y"},
      {" --stock 0,0,-10,10,10,0 --safe-z -1", "--safe-z must be above the stock's top"},
      {" --stock 0,0,-10,10,10,0 --stepover 0", "--stepover needs a length in mm above 0"},
      {" --stock 0,0,-10,10,10,0 --image x.png", "zig writes a program only"},
      {" --stock 0,0,-10,10,10,0 --frobnicate", "unknown option '--frobnicate' (try 'dexmill zig --help')"},
  };
  for (const Case& c : cases) {
    const std::string args = std::string("zig") + (c.args[0] ? " " + stl : "") + c.args;
    const Result r = run_command(args);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, c.message));
    if (!has(r.err, c.message)) std::printf("%s -> %s\n", args.c_str(), r.err.c_str());
  }
}

// A built-in part takes --stock as its block (it ignored it, the output
// byte-identical): the part stays where it is, the stripes span the block
// given, and the program cut from that block does not gouge the part.
TEST(zig_builtin_part_honours_stock) {
  if (skip()) return;
  const Result own = run_command("zig smiley");
  CHECK_EQ(own.code, 0);
  // Its own block given is the same program (no false change)...
  Result r = run_command("zig smiley --stock 0,0,-16,63.5,63.5,0");
  CHECK_EQ(r.code, 0);
  CHECK(r.out == own.out);
  // ...a larger one another, made for it.
  r = run_command("zig smiley --stock -5,-5,-16,70,70,0 -o %/smiley-wide.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "dexmill zig: grid 153 x 153 at 0.5000 mm"));
  const std::string prog = slurp(tmp_dir() + "/smiley-wide.ngc");
  CHECK(prog != own.out);
  CHECK(has(prog, "(simulate with: dexmill run PROGRAM --stock -5.000,-5.000,-16.000,70.000,70.000,0.000 --pitch 0.5000"));
  r = run("%/smiley-wide.ngc -q --stock -5,-5,-16,70,70,0 --pitch 0.5 --tool ball:6,len=16 --design smiley --report "
          "%/smiley-wide.json");
  CHECK_EQ(r.code, 0);
  const std::string rep = slurp(tmp_dir() + "/smiley-wide.json");
  CHECK(has(rep, "\"bounds_mm\": {\"min\": [-5.5000, -5.5000, "));
  CHECK(has(assessment_of(rep), "\"max_gouge\": null"));
  // A blank is no block to start the zig path from: refused, not ignored.
  r = run_command("zig smiley --stock %/blank.stl");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the built-in part smiley takes --stock as a box"));
}
