// `dexmill run`'s output files as a careful Unix tool writes them
// (tools/README.md, "Outputs"): devices and FIFOs written through, symbolic
// links kept, the format from the extension, "-" for standard output, an
// output that is an input refused before anything runs, earlier frames
// removed, a folder the user cannot write, and the summary a run with no
// output prints.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tools/run/run_live.h"

namespace {

using namespace run_cli;

std::string sub(const char* name) {
  const std::string d = tmp_dir() + "/out-" + name;
  mkdir(d.c_str(), 0755);
  return d;
}

bool is_png(const std::string& bytes) { return bytes.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) == 0; }

void write_text(const std::string& path, const char* text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fputs(text, f);
  std::fclose(f);
}

}  // namespace

TEST(run_output_format_follows_the_extension) {
  if (skip()) return;
  const std::string d = sub("fmt");
  CHECK_EQ(run("pocket.ngc -q --size 64x48 --image " + d + "/a.png --heightmap " + d + "/h.png").code, 0);
  CHECK(is_png(slurp(d + "/a.png")));
  CHECK(is_png(slurp(d + "/h.png")));
  CHECK_EQ(run("pocket.ngc -q --size 64x48 --image " + d + "/b.PPM --heightmap " + d + "/h.pgm").code, 0);
  CHECK_EQ(slurp(d + "/b.PPM").compare(0, 3, "P6\n"), 0);
  CHECK_EQ(slurp(d + "/h.pgm").compare(0, 3, "P5\n"), 0);
  // An unknown or missing extension is a usage error, and nothing is written.
  const Result jpg = run("pocket.ngc -q --image " + d + "/c.jpg");
  CHECK_EQ(jpg.code, 2);
  CHECK(has(jpg.err, "must end in .ppm or .png"));
  CHECK_EQ(run("pocket.ngc -q --image " + d + "/noext").code, 2);
  CHECK_EQ(run("pocket.ngc -q --heightmap " + d + "/h.ppm").code, 2);
  struct stat st;
  CHECK(stat((d + "/c.jpg").c_str(), &st) != 0);
  CHECK(stat((d + "/noext").c_str(), &st) != 0);
}

TEST(run_output_devices_and_fifos_are_written_through) {
  if (skip()) return;
  // As root, a rename over /dev/null would have replaced the device.
  CHECK_EQ(run("pocket.ngc -q --size 64x48 --image /dev/null --report /dev/null").code, 0);
  struct stat st;
  CHECK_EQ(stat("/dev/null", &st), 0);
  CHECK(S_ISCHR(st.st_mode));
  // A FIFO gets the bytes (a reader at its other end) and stays a FIFO.
  const std::string d = sub("fifo");
  const std::string fifo = d + "/pipe", got = d + "/got.json";
  CHECK_EQ(mkfifo(fifo.c_str(), 0600), 0);
  char abs[4096];
  const char* bin = t::dexmill_binary();
  const std::string binary = realpath(bin, abs) ? abs : bin;
  const std::string cmd = "cd '" + std::string(t::tests_dir()) + "/run' && { cat '" + fifo + "' > '" + got + "' & '" +
                          binary + "' run pocket.ngc -q --report '" + fifo + "' </dev/null; r=$?; wait; exit $r; }";
  const int status = std::system(cmd.c_str());
  CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  CHECK_EQ(stat(fifo.c_str(), &st), 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(has(slurp(got), "\"dexmill_report\": 1"));
}

TEST(run_output_symlinks_are_kept_and_modes_too) {
  if (skip()) return;
  const std::string d = sub("link");
  // A link to a file: the file is replaced, the link stays a link.
  write_text(d + "/real.json", "old");
  CHECK_EQ(symlink("real.json", (d + "/link.json").c_str()), 0);
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/link.json").code, 0);
  struct stat st;
  CHECK_EQ(lstat((d + "/link.json").c_str(), &st), 0);
  CHECK(S_ISLNK(st.st_mode));
  CHECK(has(slurp(d + "/real.json"), "\"dexmill_report\": 1"));
  // A dangling link: its target is made.
  CHECK_EQ(symlink("made.json", (d + "/dangling.json").c_str()), 0);
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/dangling.json").code, 0);
  CHECK(has(slurp(d + "/made.json"), "\"dexmill_report\": 1"));
  CHECK_EQ(lstat((d + "/dangling.json").c_str(), &st), 0);
  CHECK(S_ISLNK(st.st_mode));
  // A replaced file keeps its permission bits.
  write_text(d + "/private.json", "old");
  CHECK_EQ(chmod((d + "/private.json").c_str(), 0600), 0);
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/private.json").code, 0);
  CHECK_EQ(stat((d + "/private.json").c_str(), &st), 0);
  CHECK_EQ(st.st_mode & 0777, 0600u);
  CHECK(has(slurp(d + "/private.json"), "\"dexmill_report\": 1"));
}

TEST(run_output_that_is_an_input_is_refused_before_the_run) {
  if (skip()) return;
  const std::string d = sub("same");
  const std::string prog = d + "/prog.ngc";
  write_text(prog, "G0 X0 Y0 Z1\nG1 Z-1 F100\nG1 X10\nM2\n");
  const uint64_t before = file_hash(prog);
  Result r = run(prog + " -q --report " + prog);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "is the input"));
  CHECK_EQ(run(prog + " -q --report " + d + "/../out-same/./prog.ngc").code, 2);  // another name for it
  CHECK_EQ(symlink("prog.ngc", (d + "/alias.ngc").c_str()), 0);
  CHECK_EQ(run(prog + " -q --image " + d + "/alias.png --stl " + d + "/alias.ngc").code, 2);  // through a link
  write_text(d + "/t.tbl", "T1 P1 D6 Z0\n");
  const uint64_t table = file_hash(d + "/t.tbl");
  CHECK_EQ(run(prog + " -q --tools " + d + "/t.tbl --report " + d + "/t.tbl").code, 2);
  CHECK_EQ(file_hash(prog), before);
  CHECK_EQ(file_hash(d + "/t.tbl"), table);
  // Two outputs on one file (existing or new) are refused too.
  r = run(prog + " -q --image " + d + "/x.png --heightmap " + d + "/./x.png");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "are the same file"));
  struct stat st;
  CHECK(stat((d + "/x.png").c_str(), &st) != 0);
}

TEST(run_output_dash_is_standard_output) {
  if (skip()) return;
  const std::string d = sub("dash");
  const Result r = run("pocket.ngc -q --report -");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/r.json").code, 0);
  const std::string file = report_body(d + "/r.json"), out = r.out.substr(0, r.out.find("  \"timing\""));
  CHECK(!file.empty());
  CHECK(out == file);
  const Result img = run("pocket.ngc -q --size 64x48 --image -");
  CHECK_EQ(img.code, 0);
  CHECK(is_png(img.out));
  const Result hm = run("pocket.ngc -q --heightmap -");
  CHECK_EQ(hm.code, 0);
  CHECK_EQ(hm.out.compare(0, 3, "P5\n"), 0);
  const Result two = run("pocket.ngc -q --report - --stl -");
  CHECK_EQ(two.code, 2);
  CHECK(has(two.err, "only one can"));
  CHECK(two.out.empty());
}

TEST(run_frames_are_png_and_earlier_frames_go) {
  if (skip()) return;
  const std::string d = sub("frames");
  write_text(d + "/frame-000099.ppm", "stale");
  write_text(d + "/frame-000002.png", "stale");
  write_text(d + "/notes.txt", "mine");
  write_text(d + "/frame-1.png", "not ours");
  const Result r = run("pocket.ngc --size 64x48 --every 20 --frames " + d);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "removed 2 frames of an earlier run"));
  struct stat st;
  CHECK(stat((d + "/frame-000099.ppm").c_str(), &st) != 0);
  CHECK(is_png(slurp(d + "/frame-000002.png")));
  CHECK_EQ(slurp(d + "/notes.txt"), std::string("mine"));
  CHECK_EQ(slurp(d + "/frame-1.png"), std::string("not ours"));
  CHECK_EQ(run("pocket.ngc -q --size 64x48 --every 20 --frame-format ppm --frames " + d).code, 0);
  CHECK(stat((d + "/frame-000002.png").c_str(), &st) != 0);
  CHECK_EQ(slurp(d + "/frame-000002.ppm").compare(0, 3, "P6\n"), 0);
  CHECK_EQ(run("pocket.ngc -q --frame-format gif --frames " + d).code, 2);
}

TEST(run_output_folder_the_user_cannot_write) {
  if (skip()) return;
  // A folder its owner (root, or this user) keeps to itself, written by
  // someone else: as root the run drops to nobody with setpriv.
  const std::string d = sub("locked");
  CHECK_EQ(chmod(d.c_str(), 0555), 0);
  std::string prefix;
  if (geteuid() == 0) {
    if (std::system("setpriv --version >/dev/null 2>&1") != 0) {
      std::printf("  (skipped: running as root without setpriv)\n");
      return;
    }
    CHECK_EQ(chmod(d.c_str(), 0755), 0);
    CHECK_EQ(chmod(tmp_dir().c_str(), 0755), 0);  // others may look in, not write
    prefix = "setpriv --reuid=65534 --regid=65534 --clear-groups";
  }
  const Result r = run("pocket.ngc -q --image " + d + "/x.png", nullptr, false, prefix);
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "is not writable"));
  chmod(d.c_str(), 0755);
}

TEST(run_without_outputs_prints_a_summary) {
  if (skip()) return;
  const Result r = run("pocket.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "pocket.ngc: "));
  CHECK(has(r.out, "stock    X"));
  CHECK(has(r.out, "grid     "));
  CHECK(has(r.out, "removed  "));
  CHECK(has(r.out, "mm^3"));
  CHECK(has(r.out, "time     "));
  CHECK(has(r.out, "Add --image out.png"));
  // Blocks run, and what the time estimate is (a lower bound without
  // acceleration; with --accel, blended between its bounds).
  CHECK(has(r.out, "pocket.ngc: 23 blocks run, mm;"));
  CHECK(has(r.out, " at programmed feeds, rapids at 5000 mm/min, no acceleration (a lower bound; --accel MM/S2"));
  const Result accel = run("pocket.ngc --accel 500.5");
  CHECK(has(accel.out, "time     0:00:17 blended at corners (G64), each axis within its velocity and acceleration\n"));
  CHECK(has(accel.out, "         bounds: 0:00:17 without acceleration, 0:00:18 stopping at every move (rapids at 5000 mm/min, "
                       "acceleration 500.500 mm/s^2)\n"));
  CHECK_EQ(accel.out.find("no acceleration"), std::string::npos);
  // With an output, standard output stays quiet.
  CHECK(run("pocket.ngc -q --report /dev/null").out.empty());
  // Units: what the moves were written in.
  CHECK(has(run("arcs_inch.ngc").out, ", inch;"));
  const std::string d = sub("units");
  // A loop runs its lines again: 7 lines, 47 blocks (the while line 11 times).
  write_text(d + "/loop.ngc", "G21 G90\n#1=0\no100 while [#1 LT 10]\nG0 X#1\n#1=[#1+1]\no100 endwhile\nM2\n");
  CHECK(has(run(d + "/loop.ngc").out, "loop.ngc: 47 blocks run, mm; 10 rapids"));
  write_text(d + "/mixed.ngc", "G21 G0 X0 Y0 Z1\nG1 Z-1 F100\nG20 G1 X1\nM2\n");
  write_text(d + "/late.ngc", "G21 G0 X0 Y0 Z1\nG1 Z-1 F100\nG20\nM2\n");
  CHECK(has(run(d + "/mixed.ngc").out, ", mixed;"));
  CHECK(has(run(d + "/late.ngc").out, ", mm;"));  // G20 after the last move
}

TEST(live_status_line_labels_line_and_speed) {
  dexmill::cli::LiveStatus s;
  s.line = 4833;
  s.tool = 2;
  s.tool_spec = "ball:6";
  const std::string text = dexmill::cli::status_text(s, 7500, false, false);
  CHECK(has(text, "line 4833 "));
  CHECK(has(text, " x7.500"));
  CHECK(text.find("N4833") == std::string::npos);
}
