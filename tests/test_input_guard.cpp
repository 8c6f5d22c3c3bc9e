// The input guard (platform/input/file_guard.h): no subcommand writes
// or removes a file it reads. Each surface is refused with exit 2 and a
// message naming both files, before anything is written or removed, under
// the file's own name, through a symbolic link and through a hard link;
// and what only looks alike (another name beside an input, the program in
// the frames folder under a name that is not a frame's, /dev/null twice)
// still runs.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// A fresh folder of the temporary one for each test.
std::string folder(const char* name) {
  const std::string d = tmp_dir() + "/guard-" + name;
  mkdir(d.c_str(), 0755);
  return d;
}

std::string put(const std::string& path, const char* text) {
  write_file(path, text);
  return path;
}

bool exists(const std::string& path) {
  struct stat st;
  return lstat(path.c_str(), &st) == 0;
}

const char* const kProgram = "G21 G90\nG0 X2 Y2 Z1\nG1 Z-1 F100\nG1 X10\nG0 Z1\nM2\n";
const char* const kMaterial = "material alu plain max_feed=1200\ndefault alu\n";
const char* const kTable = "T1 P1 D6 Z0\n";
const char* const kSmall = " -q --stock 0,0,-5,20,20,0 --pitch 0.5 --size 64x48";

// Refused before anything is written: exit 2, the message names both, and
// `kept` holds what it held.
void check_refused(const std::string& args, const std::string& kept, const char* a, const char* b) {
  const uint64_t before = file_hash(kept);
  const Result r = run_command(args);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, a));
  CHECK(has(r.err, b));
  CHECK(exists(kept));
  CHECK_EQ(file_hash(kept), before);
}

// `dexmill ARGS > OUT` (or `>>`) in `dir`, the shell opening OUT: the exit
// status and standard error.
Result with_stdout(const std::string& dir, const std::string& args, const char* redirect, const std::string& out) {
  Result r;
  const std::string err = dir + "/shell.err";
  char abs[4096];
  const std::string binary = realpath(t::dexmill_binary(), abs) ? abs : t::dexmill_binary();
  const std::string cmd = "cd '" + dir + "' && '" + binary + "' " + args + " " + redirect + "'" + out + "' 2>'" + err +
                          "' </dev/null";
  const int st = std::system(cmd.c_str());
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.err = slurp(err);
  return r;
}

}  // namespace

TEST(guard_material_file_is_never_an_output) {
  if (skip()) return;
  const std::string d = folder("material");
  const std::string p = put(d + "/p.ngc", kProgram), m = put(d + "/m.txt", kMaterial);
  const std::string job = p + kSmall + " --material " + m;
  check_refused("run " + job + " --report " + m, m, "--report", "the input --material");
  CHECK_EQ(symlink("m.txt", (d + "/link.json").c_str()), 0);
  check_refused("run " + job + " --report " + d + "/link.json", m, "--report", "--material");
  CHECK_EQ(link(m.c_str(), (d + "/hard.json").c_str()), 0);
  check_refused("run " + job + " --report " + d + "/hard.json", m, "--report", "--material");
  check_refused("check --simulate " + job + " --report " + m, m, "--report", "--material");
  // Beside it, under another name: written.
  CHECK_EQ(run_command("run " + job + " --report " + d + "/m.json --image " + d + "/m.png").code, 0);
  CHECK(has(slurp(d + "/m.json"), "\"dexmill_report\": 1"));
}

TEST(guard_subroutine_opened_mid_run_is_never_an_output) {
  if (skip()) return;
  const std::string d = folder("sub");
  const std::string q = put(d + "/q.ngc", "G21 G90\nG0 X2 Y2 Z1\no<sub> call\nG0 Z1\nM2\n");
  const std::string s = put(d + "/sub.ngc", "o<sub> sub\nG1 Z-1 F100\nG1 X10\no<sub> endsub\nM2\n");
  const std::string job = q + kSmall + " --subroutine-path " + d;
  // Known only when the program calls it: the run stops there, exit 2.
  check_refused("run " + job + " --report " + s, s, "--report", "the input subroutine");
  CHECK_EQ(symlink("sub.ngc", (d + "/alias.json").c_str()), 0);
  check_refused("run " + job + " --report " + d + "/alias.json", s, "--report", "subroutine");
  CHECK_EQ(link(s.c_str(), (d + "/hard.json").c_str()), 0);
  check_refused("run " + job + " --report " + d + "/hard.json", s, "--report", "subroutine");
  CHECK_EQ(symlink(".", (d + "/again").c_str()), 0);  // the path through a link to the folder
  check_refused("run " + q + kSmall + " --subroutine-path " + d + "/again --report " + s, s, "--report", "subroutine");
  check_refused("check --simulate " + job + " --report " + s, s, "--report", "subroutine");
  // A report beside the subroutine: the run goes through.
  const Result r = run_command("run " + job + " --report " + d + "/q.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(d + "/q.json"), "\"errors\": []"));
}

TEST(guard_optimize_output_is_never_another_input) {
  if (skip()) return;
  const std::string d = folder("optimize");
  const std::string p = put(d + "/p.ngc", "G21 G90\nT1 M6\nG0 X2 Y2 Z1\nG1 Z-1 F100\nG1 X10 F2000\nG0 Z1\nM2\n");
  const std::string m = put(d + "/m.txt", kMaterial), t = put(d + "/t.tbl", kTable);
  write_file(d + "/blank.stl", slurp(std::string(t::tests_dir()) + "/run/blank_step.stl"));
  const std::string stl = d + "/blank.stl";
  const std::string job = "optimize " + p + " -q --pitch 0.5 --material " + m + " --tools " + t;
  check_refused(job + " --stock 0,0,-5,20,20,0 -o " + m, m, "-o", "the input --material");
  check_refused(job + " --stock 0,0,-5,20,20,0 -o " + t, t, "-o", "the input --tools");
  check_refused(job + " --stock " + stl + " -o " + stl, stl, "-o", "the input --stock");
  CHECK_EQ(symlink("t.tbl", (d + "/link.ngc").c_str()), 0);
  check_refused(job + " --stock 0,0,-5,20,20,0 -o " + d + "/link.ngc", t, "-o", "--tools");
  CHECK_EQ(link(m.c_str(), (d + "/hard.ngc").c_str()), 0);
  check_refused(job + " --stock 0,0,-5,20,20,0 -o " + d + "/hard.ngc", m, "-o", "--material");
  // The program itself may be rewritten (it is read whole first), and an
  // output beside the inputs or on /dev/null is written.
  CHECK_EQ(run_command(job + " --stock 0,0,-5,20,20,0 -o " + d + "/opt.ngc").code, 0);
  CHECK(has(slurp(d + "/opt.ngc"), "G1 X10 F1200"));
  CHECK_EQ(run_command(job + " --stock 0,0,-5,20,20,0 -o /dev/null").code, 0);
  CHECK_EQ(run_command(job + " --stock 0,0,-5,20,20,0 -o " + p).code, 0);
  CHECK(has(slurp(p), "G1 X10 F1200"));
}

TEST(guard_zig_output_is_never_the_design) {
  if (skip()) return;
  const std::string d = folder("zig");
  const std::string stl = put(d + "/d.stl",
                              "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 -5\nvertex 10 0 -5\nvertex 10 10 -5\n"
                              "endloop\nendfacet\nendsolid f\n");
  const std::string pgm = put(d + "/d.pgm", "P2 2 2 255\n0 255\n255 0\n");
  const std::string box = " --stock 0,0,-10,10,10,0 --pitch 0.5";
  check_refused("zig " + stl + box + " -o " + stl, stl, "-o", "the input --design");
  check_refused("zig " + pgm + box + " --design-z -8,-2 -o " + pgm, pgm, "-o", "--design");
  CHECK_EQ(symlink("d.stl", (d + "/link.ngc").c_str()), 0);
  check_refused("zig " + stl + box + " -o " + d + "/link.ngc", stl, "-o", "--design");
  CHECK_EQ(link(pgm.c_str(), (d + "/hard.ngc").c_str()), 0);
  check_refused("zig " + pgm + box + " --design-z -8,-2 -o " + d + "/hard.ngc", pgm, "-o", "--design");
  CHECK_EQ(run_command("zig " + stl + box + " -o " + d + "/d.ngc").code, 0);
  CHECK(has(slurp(d + "/d.ngc"), "M30\n"));
  CHECK_EQ(run_command("zig " + pgm + box + " --design-z -8,-2 -o /dev/null").code, 0);
}

TEST(guard_frame_clean_up_never_removes_an_input) {
  if (skip()) return;
  const std::string d = folder("frames-in"), fr = d + "/fr";
  mkdir(fr.c_str(), 0755);
  const std::string framed = put(fr + "/frame-000001.png", kProgram);
  check_refused("run " + framed + kSmall + " --frames " + fr, framed, "--frames", "the input program");
  const std::string p = put(d + "/p.ngc", "G21 G90\nT1 M6\nG0 X2 Y2 Z1\nG1 Z-1 F100\nG1 X10\nG0 Z1\nM2\n");
  const std::string table = put(fr + "/frame-000002.ppm", kTable);
  check_refused("run " + p + kSmall + " --tools " + table + " --frames " + fr, table, "--frames", "the input --tools");
  // The program named through a link to a frame, or a frame that is a
  // hard link of the program: the same file.
  const std::string third = put(fr + "/frame-000003.png", kProgram);
  CHECK_EQ(symlink(third.c_str(), (d + "/link.ngc").c_str()), 0);
  check_refused("run " + d + "/link.ngc" + kSmall + " --frames " + fr, third, "--frames", "program");
  CHECK_EQ(link(p.c_str(), (fr + "/frame-000004.png").c_str()), 0);
  check_refused("run " + p + kSmall + " --frames " + fr, fr + "/frame-000004.png", "--frames", "program");
  CHECK(exists(framed) && exists(table) && exists(third));
  // The program in the frames folder under another name: the frames are
  // written around it.
  const std::string e = d + "/clean";
  mkdir(e.c_str(), 0755);
  const std::string prog = put(e + "/prog.ngc", kProgram);
  CHECK_EQ(run_command("run " + prog + kSmall + " --every 50 --frames " + e).code, 0);
  CHECK_EQ(slurp(prog), std::string(kProgram));
  CHECK(exists(e + "/frame-000001.png"));
}

TEST(guard_outputs_never_land_on_frames) {
  if (skip()) return;
  const std::string d = folder("frames-out"), fr = d + "/fr";
  mkdir(fr.c_str(), 0755);
  const std::string p = put(d + "/p.ngc", kProgram);
  const std::string job = "run " + p + kSmall + " --frames " + fr;
  Result r = run_command(job + " --image " + fr + "/frame-000001.png");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--frames"));
  CHECK(has(r.err, "--image"));
  CHECK(!exists(fr + "/frame-000001.png"));  // nothing written
  r = run_command(job + " --frame-format ppm --report " + fr + "/frame-000002.ppm");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--report"));
  CHECK(!exists(fr + "/frame-000002.ppm"));
  // A frame name of the other format there is the next clean-up's.
  CHECK_EQ(run_command(job + " --report " + fr + "/frame-000002.ppm").code, 2);
  // An earlier run's frame, and a link that lands on a frame's name.
  const std::string old = put(fr + "/frame-000003.png", "an earlier frame");
  check_refused(job + " --image " + old, old, "--frames", "--image");
  CHECK_EQ(symlink("fr/frame-000005.png", (d + "/last.png").c_str()), 0);
  r = run_command(job + " --image " + d + "/last.png");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--image"));
  // Beside the frames folder, and in it under a name that is not a frame's.
  CHECK_EQ(run_command(job + " --every 50 --image " + d + "/final.png --report " + fr + "/report.json").code, 0);
  CHECK(exists(d + "/final.png") && exists(fr + "/report.json") && exists(fr + "/frame-000001.png"));
}

TEST(guard_outputs_are_never_each_other) {
  if (skip()) return;
  const std::string d = folder("each");
  const std::string p = put(d + "/p.ngc", kProgram);
  const std::string a = put(d + "/a.png", "an image");
  CHECK_EQ(link(a.c_str(), (d + "/b.pgm").c_str()), 0);
  check_refused("run " + p + kSmall + " --image " + a + " --heightmap " + d + "/b.pgm", a, "--image", "--heightmap");
  // Standard output is the file the shell opened: the report would go into
  // the image's old file, which the image then replaces.
  const Result r = with_stdout(d, "run p.ngc" + std::string(kSmall) + " --report - --image a.png", ">", "a.png");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--image 'a.png' and standard output (--report) are the same file"));
  // /dev/null as two outputs is no clash: it is written to, never replaced.
  CHECK_EQ(run_command("run " + p + kSmall + " --image /dev/null --heightmap /dev/null --report /dev/null").code, 0);
}

TEST(guard_standard_output_is_never_an_input) {
  if (skip()) return;
  const std::string d = folder("stdout");
  put(d + "/p.ngc", kProgram);
  // The shell has emptied the file already; the command says so and fails.
  Result r = with_stdout(d, "path p.ngc", ">", "p.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "standard output is the input program 'p.ngc'"));
  put(d + "/p.ngc", kProgram);
  r = with_stdout(d, "run p.ngc" + std::string(kSmall), ">", "p.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "standard output"));
  put(d + "/d.stl",
      "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 -5\nvertex 10 0 -5\nvertex 10 10 -5\nendloop\nendfacet\n"
      "endsolid f\n");
  r = with_stdout(d, "zig d.stl --stock 0,0,-10,10,10,0 --pitch 0.5", ">", "d.stl");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the input --design 'd.stl'"));
  // A subroutine that is standard output: refused when the call opens it.
  put(d + "/q.ngc", "G21 G90\nG0 X2 Y2 Z1\no<sub> call\nM2\n");
  put(d + "/sub.ngc", "o<sub> sub\nG1 Z-1 F100\no<sub> endsub\nM2\n");
  r = with_stdout(d, "path q.ngc --subroutine-path .", ">", "sub.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the input subroutine './sub.ngc'"));
  // Appended to, the program is kept, and still refused.
  put(d + "/p.ngc", kProgram);
  r = with_stdout(d, "path p.ngc", ">>", "p.ngc");
  CHECK_EQ(r.code, 2);
  CHECK_EQ(slurp(d + "/p.ngc"), std::string(kProgram));
}

TEST(guard_demo_program_is_never_an_input_or_another_output) {
  if (skip()) return;
  const std::string d = folder("demo");
  mkdir((d + "/out").c_str(), 0755);
  const std::string table = put(d + "/out/demo.ngc", kTable);
  const std::string in_demo = "cd '" + d + "' &&";
  const uint64_t before = file_hash(table);
  Result r = run_command("run --demo pocket -q --tools out/demo.ngc", nullptr, false, in_demo);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the demo's program"));
  CHECK(has(r.err, "the input --tools"));
  CHECK_EQ(file_hash(table), before);
  r = run_command("run --demo pocket -q --report out/demo.ngc", nullptr, false, in_demo);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--report"));
  CHECK_EQ(file_hash(table), before);
}
