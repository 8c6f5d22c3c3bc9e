// O-word control flow (core/gcode/oword.h): the reading of o-word lines, the
// flow in memory (a panel's MemorySource) and in files (seeking back,
// subroutine files on a path, standard input), the fixed limits and the block
// limit. The flow's semantics against LinuxCNC are
// tests/gcode/paths/owords_flow (compared with rs274 by
// tools/scripts/oracle-check.sh --rs274) and its errors tests/gcode/bad_flow
// (at rs274's lines).
#include <memory>
#include <string>

#include "core/gcode/oword.h"
#include "core/interp/interp.h"
#include "platform/input/gcode_file.h"
#include "tests/gcode_test_util.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct Flow {
  std::unique_ptr<GcodeMemory> mem = gcode_memory();
  t::Recorder rec;
  InterpOptions opt;
  std::unique_ptr<Interp> in;
  explicit Flow(uint64_t max_blocks = kDefaultMaxBlocks) {
    mem->attach(&opt);
    opt.max_blocks = max_blocks;
    in.reset(new Interp(&rec, opt));
  }
  // Runs a program held in memory (as a panel does); errors counted.
  uint32_t run(const char* text, GcodeDiag* first = nullptr) {
    GcodeDiag d{};
    const uint32_t n = interp_run_text(in.get(), text, std::strlen(text), &d);
    if (first) *first = d;
    return n;
  }
  // X of every straight move, in mm.
  std::string xs() const {
    std::string s;
    for (const CanonRecord& r : rec.records)
      if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) s += std::to_string(r.end.x_nm / 1000000) + " ";
    return s;
  }
};

OwordHead head(const char* s, GcodeError* e = nullptr) {
  static ParamStore p;
  params_clear(&p);
  p.numbered_e9[1] = 42 * kGValueOne;
  OwordHead h{};
  GcodeDiag d{};
  const GcodeError r = oword_read_head(s, std::strlen(s), p, &h, &d);
  if (e) *e = r;
  return h;
}

}  // namespace

TEST(oword_lines_read_as_linuxcnc_reads_them) {
  CHECK(oword_line("o100 sub", 8));
  CHECK(oword_line("  N10 O100 if [1]", 17));
  CHECK(oword_line("/o1 endif", 9));
  CHECK(!oword_line("G0 X1", 5));
  CHECK(!oword_line("N10 G0", 6));
  CHECK(!oword_line("(o100 sub)", 10));
  OwordHead h = head("o100 sub");
  CHECK(h.op == OwordOp::kSub);
  CHECK_EQ(std::string(h.name), std::string("100"));
  h = head("O<My Sub> CALL [1]");  // names fold: lower case, no blanks
  CHECK(h.op == OwordOp::kCall);
  CHECK_EQ(std::string(h.name), std::string("mysub"));
  CHECK(head("o1 end while").op == OwordOp::kEndwhile);  // LinuxCNC drops blanks
  CHECK(head("o1 elseif [1]").op == OwordOp::kElseif);
  CHECK(head("o1 else").op == OwordOp::kElse);
  CHECK(head("o1 endrepeat").op == OwordOp::kEndrepeat);
  CHECK(head("O1234").op == OwordOp::kProgramNumber);
  CHECK(head("O1234 (main)").op == OwordOp::kProgramNumber);
  h = head("o[#1 + 0.00001] call");  // computed, within LinuxCNC's 0.0001 of an integer
  CHECK_EQ(std::string(h.name), std::string("42"));
  GcodeError e;
  head("o[#1 + 0.5] call", &e);
  CHECK(e == GcodeError::kOwordBadLabel);
  head("o100 dog", &e);
  CHECK(e == GcodeError::kOwordUnknownStatement);
  head("o<> sub", &e);
  CHECK(e == GcodeError::kOwordBadLabel);
  head("o<abcdefghijabcdefghijabcdefghijab> sub", &e);  // 32 characters: one too many
  CHECK(e == GcodeError::kOwordBadLabel);
}

TEST(oword_flow_runs_from_memory_as_on_a_panel) {
  Flow f;
  // Loops and calls seek back in the text itself (MemorySource).
  CHECK_EQ(f.run("G21\n"
                 "o<mv> sub\nG0 X[#1 * 10]\no<mv> endsub\n"
                 "o1 repeat [3]\n#2 = [#2 + 1]\no<mv> call [#2]\no1 endrepeat\n"
                 "#3 = 0\no2 while [#3 LT 2]\n#3 = [#3 + 1]\nG0 X#3\no2 endwhile\nM2\n"),
           0u);
  CHECK_EQ(f.xs(), std::string("10 20 30 1 2 "));
}

TEST(oword_calls_keep_the_callers_parameters) {
  Flow f;
  CHECK_EQ(f.run("G21\n#1 = 5 #2 = 6 #31 = 7\n#<_g> = 1\n"
                 "o10 sub\n#<local> = [#1 + 100]\n#<_g> = #<local>\n#31 = #1\n#2 = 99\no10 return [#<local>]\no10 endsub\n"
                 "o10 call [1]\n"
                 "G0 X#1\nG0 X#2\nG0 X#31\nG0 X#<_g>\nG0 X#<_value>\nG0 X[EXISTS[#<local>]]\nM2\n"),
           0u);
  // #1..#30 come back; #31 and globals are shared; the local is gone.
  CHECK_EQ(f.xs(), std::string("5 6 1 101 101 0 "));
}

TEST(oword_without_a_source_runs_ifs_and_refuses_loops) {
  t::Recorder rec;
  const std::unique_ptr<GcodeMemory> mem = gcode_memory();
  InterpOptions opt;
  mem->attach(&opt);
  Interp in(&rec, opt);
  GcodeDiag d{};
  // execute_line alone: no source to go back in.
  CHECK(t::run_program(&in, "G21\no1 if [0]\nG0 X1\no1 else\nG0 X2\no1 endif\nG0 X3", &d) == GcodeError::kOk);
  CHECK_EQ(rec.count(CanonKind::kTraverse), 2u);
  CHECK(t::run_program(&in, "o2 while [1]\nG0 X4\no2 endwhile", &d) == GcodeError::kOwordNoSource);
  // Without the memory at all, o-words are not supported (a panel without it).
  InterpOptions bare;
  Interp plain(&rec, bare);
  CHECK(t::run_program(&plain, "o1 if [1]", &d) == GcodeError::kUnsupportedOword);
}

TEST(oword_block_limit_stops_an_endless_loop_at_its_line) {
  Flow f(1000);
  GcodeDiag d{};
  CHECK_EQ(f.run("G21\nG0 X1\no7 while [1]\nG0 X2\no7 endwhile\nG0 X3\nM2\n", &d), 1u);
  CHECK(d.code == GcodeError::kBlockLimit);
  CHECK_EQ(d.line, 3u);
  CHECK_EQ(d.a_nm, 1000);
  CHECK(f.in->ended());  // nothing after it runs
  CHECK_LE(f.rec.count(CanonKind::kTraverse), 1000u);
  // A plain program longer than the limit is not stopped: it never loops.
  Flow g(3);
  CHECK_EQ(g.run("G0 X1\nG0 X2\nG0 X3\nG0 X4\nG0 X5\nM2\n"), 0u);
}

TEST(oword_input_ending_inside_control_flow_is_an_error) {
  Flow f;
  GcodeDiag d{};
  CHECK_EQ(f.run("G21\no3 if [0]\nG0 X1\n", &d), 1u);
  CHECK(d.code == GcodeError::kOwordUnclosed);
  CHECK_EQ(d.line, 2u);
  Flow g;
  CHECK_EQ(g.run("G21\no<gone> call\nG0 X1\nM2\n", &d), 1u);
  CHECK(d.code == GcodeError::kOwordSubNotFound);
  CHECK_EQ(d.line, 2u);
  CHECK_EQ(g.rec.count(CanonKind::kTraverse), 0u);  // skipped while looking for it
}

TEST(oword_labels_have_a_fixed_capacity) {
  std::string prog = "G21\n";
  for (int k = 0; k <= kOwordLabelsMax; ++k)
    prog += "o" + std::to_string(k + 1) + " if [1]\no" + std::to_string(k + 1) + " endif\n";
  prog += "M2\n";
  Flow f;
  GcodeDiag d{};
  CHECK_GE(f.run(prog.c_str(), &d), 1u);  // its endif follows on
  CHECK(d.code == GcodeError::kOwordTooManyLabels);
  CHECK_EQ(d.line, static_cast<uint32_t>(2 + 2 * kOwordLabelsMax));
  // Labels are scoped: the same number in two subs is two labels.
  Flow g;
  CHECK_EQ(g.run("o<a> sub\no1 if [1]\nG0 X1\no1 endif\no<a> endsub\n"
                 "o<b> sub\no1 if [1]\nG0 X2\no1 endif\no<b> endsub\n"
                 "o<a> call\no<b> call\nM2\n"),
           0u);
  CHECK_EQ(g.xs(), std::string("1 2 "));
}

TEST(oword_subroutine_files_come_from_the_path) {
  const std::string dir = run_cli::tmp_dir() + "/subs";
  std::string cmd = "mkdir -p '" + dir + "'";
  CHECK_EQ(std::system(cmd.c_str()), 0);
  run_cli::write_tmp("subs/probe.ngc", "o<probe> sub\nG0 X[#1 + 1]\no<probe> endsub\nM2\n");
  run_cli::write_tmp("subs/broken.ngc", "o<broken> sub\nG0 X[1/0]\no<broken> endsub\n");
  const std::string prog = run_cli::write_tmp("calls_file.ngc", "G21\no<probe> call [4]\no<probe> call [9]\nG0 Y1\nM2\n");
  GcodeFile file;
  CHECK(file.open(prog.c_str()));
  file.set_subroutine_path({run_cli::tmp_dir() + "/nowhere", dir});
  Flow f;
  t::Warnings none;
  struct Msgs final : GcodeMessages {
    std::string last;
    void error(const GcodeDiag& d) override { ++errors_; last = std::string(file) + ":" + std::to_string(d.line); }
    void warning(const GcodeDiag&) override { ++warnings_; }
    void set_file(const char* name) override { file = name; }
    std::string file = "main";
  } msgs;
  GcodeRunner runner(&file, f.in.get(), &msgs, true);
  runner.run_all();
  CHECK_EQ(msgs.errors(), 0u);
  CHECK_EQ(f.xs(), std::string("5 10 10 "));  // the second call seeks into the file kept open
  // An error in a subroutine file is named by that file and its line.
  const std::string bad = run_cli::write_tmp("calls_broken.ngc", "G21\no<broken> call\nM2\n");
  GcodeFile file2;
  CHECK(file2.open(bad.c_str()));
  file2.set_subroutine_path({dir});
  Flow g;
  GcodeRunner runner2(&file2, g.in.get(), &msgs, true);
  runner2.run_all();
  CHECK_EQ(msgs.errors(), 1u);
  CHECK_EQ(msgs.last, dir + "/broken.ngc:2");
}

TEST(oword_loops_read_standard_input_through_the_commands) {
  if (run_cli::skip()) return;
  const std::string p = run_cli::write_tmp("loop_stdin.ngc", "G21\no1 repeat [3]\nG91 G0 X1\no1 endrepeat\nM2\n");
  run_cli::Result r = run_cli::run_command("path -", p.c_str());
  CHECK_EQ(r.code, 0);
  CHECK(run_cli::has(r.out, "rapid 3.00000 0.00000 0.00000"));
  r = run_cli::run_command("check --max-blocks 5 -", p.c_str());
  CHECK_EQ(r.code, 1);
  CHECK(run_cli::has(r.err, "<stdin>:2:1: error: the program ran 5 blocks (the --max-blocks limit)"));
  r = run_cli::run_command("path --max-blocks x " + p);
  CHECK_EQ(r.code, 2);
}

TEST(oword_m99_in_the_main_program_runs_it_once) {
  // LinuxCNC starts such a program again, endlessly: the preview warns and stops.
  const std::unique_ptr<GcodeMemory> mem = gcode_memory();
  t::Recorder rec;
  t::Warnings warns;
  InterpOptions opt;
  mem->attach(&opt);
  opt.warnings = &warns;
  Interp in(&rec, opt);
  const char* prog = "G21\nG0 X1\nM99\nG0 X2\n";
  CHECK_EQ(interp_run_text(&in, prog, std::strlen(prog), nullptr), 0u);
  CHECK_EQ(rec.count(CanonKind::kTraverse), 1u);
  CHECK(in.ended());
  bool warned = false;
  for (const GcodeDiag& d : warns.list) warned |= d.code == GcodeError::kWarnM99Main && d.line == 3;
  CHECK(warned);
  // M98 L repeats its call; L0 makes none; #1 is the caller's own.
  Flow f;
  CHECK_EQ(f.run("G21\n#1 = 1\nM98 P7 L3\nM98 P7 L0\nG0 X[#1 * 10]\nM30\nO7\n#1 = [#1 + 1]\nG0 X#1\nM99\n"), 0u);
  CHECK_EQ(f.xs(), std::string("2 3 4 40 "));
}

TEST(oword_m73_gives_the_modal_state_back_on_return) {
  Flow f;
  // M73 in a subroutine: its spindle (M4 S2000), coolant (M8), feed, G91
  // and tool length offset go back to the caller's on endsub, with spindle
  // and coolant records so that what follows runs as the caller set it.
  CHECK_EQ(f.run("G21 G90 F100 S1000 M3\no<s> sub\nM73\nG91 F20 S2000 M4 M8 G43.1 Z2\nG1 X1\no<s> endsub\n"
                 "o<s> call\nG1 X5\nM2\n"),
           0u);
  CHECK_EQ(f.xs(), std::string("1 5 "));
  const CanonRecord& last = f.rec.records[f.rec.records.size() - 2];  // G1 X5, before M2
  CHECK(last.kind == CanonKind::kFeed);
  CHECK_EQ(last.feed_nm_per_min, t::mm(100));
  CHECK_EQ(last.spindle_rpm, 1000);
  CHECK_EQ(last.coolant, 0);
  CHECK_EQ(last.tool_length_offset_nm, 0);
  // The tool tip went back up by the offset taken away (the spindle stays).
  CHECK_EQ(last.start.z_nm, 0);
  int spindle = 0, coolant = 0;
  for (const CanonRecord& r : f.rec.records) {
    spindle += r.kind == CanonKind::kSpindle;
    coolant += r.kind == CanonKind::kCoolant;
  }
  CHECK_EQ(spindle, 3);  // M3, M4 in the sub, back to M3 on return
  CHECK_EQ(coolant, 2);  // M8, off on return
  // M70 alone is not given back on return, and a call starts with nothing saved.
  Flow g;
  CHECK_EQ(g.run("G21 G90 F100\no<s> sub\nM70\nG91\no<s> endsub\no<s> call\nG1 X1\nG1 X1\nM2\n"), 0u);
  CHECK_EQ(g.xs(), std::string("1 2 "));
  Flow h;
  GcodeDiag d{};
  CHECK_EQ(h.run("G21 F100\nM70\no<s> sub\nM72\no<s> endsub\no<s> call\nM2\n", &d), 1u);
  CHECK_EQ(d.code, GcodeError::kContextNone);
}
