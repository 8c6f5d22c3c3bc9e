// `dexmill run` takes the tool a program's comments describe when no
// --tool or --tools gives it (core/sim/tool_choice.h), says where each tool
// came from, and warns when it cuts with a guess. The programs are written
// here in the forms pcb2gcode and Fusion write (none is copied from one).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace run_cli;

namespace {

// Two drills, as pcb2gcode writes a drill file: T, the message, then M6.
const char kDrills[] =
    "( drill file, two bit sizes )\n"
    "G94 (Millimeters per minute feed rate.)\n"
    "G21 (Units == Millimeters.)\n"
    "G90\n"
    "G00 S10000\n"
    "G00 Z10.00000 (Retract)\n"
    "T1\n"
    "M5      (Spindle stop.)\n"
    "G04 P1.00000\n"
    "(MSG, Change tool bit to drill size 0.8mm)\n"
    "M6      (Tool change.)\n"
    "M3\n"
    "G0 Z5.00000\n"
    "G81 R2.00000 Z-2.00000 F300.00000 X5.00000 Y5.00000\n"
    "G80\n"
    "G00 Z10.00000 (Retract)\n"
    "T2\n"
    "M5      (Spindle stop.)\n"
    "(MSG, Change tool bit to drill size 2mm)\n"
    "M6      (Tool change.)\n"
    "M3\n"
    "G0 Z5.00000\n"
    "G81 R2.00000 Z-2.00000 F300.00000 X15.00000 Y5.00000\n"
    "G80\n"
    "M2\n";

// A Fusion-style tool list: a ball and a bull nose, in mm.
const char kFusion[] =
    "(T1  D=3. CR=1.5 - ZMIN=-1. - ball end mill)\n"
    "(T2  D=6. CR=1. - ZMIN=-1. - bullnose end mill)\n"
    "G90 G94 G17\n"
    "G21\n"
    "(Slot1)\n"
    "T1 M6\n"
    "S10000 M3\n"
    "G0 X5 Y5 Z5\n"
    "G1 Z-1 F300\n"
    "G1 X25 F600\n"
    "G0 Z5\n"
    "(Slot2)\n"
    "T2 M6\n"
    "G0 X5 Y15\n"
    "G1 Z-1 F300\n"
    "G1 X25 F600\n"
    "G0 Z5\n"
    "M30\n";

// The same list in inch, before the G20 that says so.
const char kFusionInch[] =
    "(T3  D=0.125 CR=0. - ZMIN=-0.04 - flat end mill)\n"
    "G90 G94 G17\n"
    "G20\n"
    "T3 M6\n"
    "G0 X0.2 Y0.2 Z0.2\n"
    "G1 Z-0.04 F10\n"
    "G1 X1 F20\n"
    "G0 Z0.2\n"
    "M30\n";

// No word of its tool.
const char kBare[] =
    "G21 G90\n"
    "G0 X5 Y5 Z5\n"
    "G1 Z-1 F300\n"
    "G1 X25 F600\n"
    "G0 Z5\n"
    "T1 M6\n"
    "G0 X5 Y15\n"
    "G1 Z-1 F300\n"
    "G1 X25 F600\n"
    "G0 Z5\n"
    "M2\n";

// The "removed_mm3" number of a report, or -1.
double removed(const std::string& report) {
  const size_t at = report.find("\"removed_mm3\": ");
  return at == std::string::npos ? -1 : std::atof(report.c_str() + at + 15);
}

// A 16-bit PGM (the heightmap): width, height, samples; empty when not one.
struct Heights {
  int w = 0, h = 0;
  std::vector<uint32_t> v;
  uint32_t at(int i, int j) const { return v[static_cast<size_t>(h - 1 - j) * static_cast<size_t>(w) + static_cast<size_t>(i)]; }
};

Heights read_pgm16(const std::string& bytes) {
  Heights hm;
  int maxval = 0, consumed = 0;
  if (std::sscanf(bytes.c_str(), "P5 %d %d %d%n", &hm.w, &hm.h, &maxval, &consumed) != 3 || maxval != 65535) return Heights();
  const size_t start = static_cast<size_t>(consumed) + 1;
  const size_t n = static_cast<size_t>(hm.w) * static_cast<size_t>(hm.h);
  if (bytes.size() < start + 2 * n) return Heights();
  hm.v.resize(n);
  for (size_t k = 0; k < n; ++k)
    hm.v[k] = (static_cast<unsigned char>(bytes[start + 2 * k]) << 8) | static_cast<unsigned char>(bytes[start + 2 * k + 1]);
  return hm;
}

}  // namespace

TEST(run_tools_from_pcb2gcode_drill_messages) {
  if (skip()) return;
  write_tmp("drills.ngc", kDrills);
  // 20 x 10 mm at 0.05 mm: dexel axes X = (i - 1) 0.05 mm, a margin of one each side.
  const Result r = run("drills.ngc --stock 0,0,-5,20,10,0 --pitch 0.05 --heightmap %/drills.pgm --report %/drills.json",
                       nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "drills.ngc:10: note: tool T1 vbit:0.8:118 from the comment on line 10 (pcb2gcode)"));
  CHECK(has(r.err, "drills.ngc:19: note: tool T2 vbit:2:118 from the comment on line 19 (pcb2gcode)"));
  CHECK(r.err.find("warning") == std::string::npos);
  const std::string rep = slurp(tmp_dir() + "/drills.json");
  CHECK(has(rep, "{\"number\": 1, \"spec\": \"vbit:0.8:118\", \"source\": \"comment\", \"line\": 10, \"form\": \"pcb2gcode\"}"));
  CHECK(has(rep, "{\"number\": 2, \"spec\": \"vbit:2:118\", \"source\": \"comment\", \"line\": 19, \"form\": \"pcb2gcode\"}"));
  CHECK(has(rep, "\"warnings_total\": 0"));
  // Two drilled holes: 0.93 mm^3 and 5.02 mm^3 (cylinder and 118-degree
  // point to Z-2), where two 6 mm flat ends took 113.
  const double v = removed(rep);
  CHECK(v > 5.5 && v < 6.4);
  // Each hole as wide as its drill: 0.6 mm from the centre the 0.8 mm hole
  // has left the stock's top, the 2 mm one has cut it.
  const Heights hm = read_pgm16(slurp(tmp_dir() + "/drills.pgm"));
  CHECK_EQ(hm.w, 403);
  CHECK_EQ(hm.h, 203);
  if (hm.w != 403 || hm.h != 203) return;
  const uint32_t top = hm.at(51, 151);  // X2.5 Y7.5: untouched
  CHECK_LT(hm.at(101, 101), top);       // the 0.8 mm hole's centre, X5 Y5
  CHECK_EQ(hm.at(113, 101), top);       // X5.6: outside it
  CHECK_LT(hm.at(301, 101), top);       // the 2 mm hole's centre, X15 Y5
  CHECK_LT(hm.at(313, 101), top);       // X15.6: inside it
  CHECK_EQ(hm.at(323, 101), top);       // X16.1: outside it
}

TEST(run_tools_from_a_fusion_tool_list) {
  if (skip()) return;
  write_tmp("fusion.ngc", kFusion);
  const Result r = run("fusion.ngc --stock 0,0,-5,30,20,0 --pitch 0.1 --report %/fusion.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "fusion.ngc:1: note: tool T1 ball:3 from the comment on line 1 (fusion)"));
  CHECK(has(r.err, "fusion.ngc:2: note: tool T2 bull:6:1 from the comment on line 2 (fusion)"));
  const std::string rep = slurp(tmp_dir() + "/fusion.json");
  CHECK(has(rep, "\"used\": [{\"number\": 1, \"spec\": \"ball:3\", \"source\": \"comment\", \"line\": 1, \"form\": \"fusion\"}, "
                 "{\"number\": 2, \"spec\": \"bull:6:1\", \"source\": \"comment\", \"line\": 2, \"form\": \"fusion\"}]"));
  CHECK(has(rep, "\"warnings_total\": 0"));
  // The cut is the one a table of the same tools makes.
  write_tmp("fusion.tbl", "T1 P1 D3 Z0 ;ball:3\nT2 P2 D6 Z0 ;bull:6:1\n");
  const Result t = run("fusion.ngc --tools fusion.tbl --stock 0,0,-5,30,20,0 --pitch 0.1 --report %/fusion_t.json",
                       nullptr, true);
  CHECK_EQ(t.code, 0);
  const std::string rep_t = slurp(tmp_dir() + "/fusion_t.json");
  CHECK(has(rep_t, "{\"number\": 1, \"spec\": \"ball:3\", \"source\": \"table\", \"line\": null, \"form\": null}"));
  CHECK_EQ(removed(rep), removed(rep_t));
  CHECK_GT(removed(rep), 0.0);
  // An inch list before its G20 is read in inch, where the tool is loaded.
  write_tmp("fusion_in.ngc", kFusionInch);
  const Result i = run("fusion_in.ngc --report %/fusion_in.json", nullptr, true);
  CHECK_EQ(i.code, 0);
  CHECK(has(slurp(tmp_dir() + "/fusion_in.json"), "{\"number\": 3, \"spec\": \"flat:3.175\", \"source\": \"comment\""));
}

TEST(run_tool_guess_warns_and_counts) {
  if (skip()) return;
  write_tmp("bare.ngc", kBare);
  const Result r = run("bare.ngc --stock 0,0,-5,30,20,0 --pitch 0.2", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "bare.ngc:3:1: warning: the tool before any M6 and T1 are cut as flat:6, a guess: no --tool, "
                   "--tools table or tool comment of the program gives them (give one with --tool SPEC or --tools FILE)"));
  CHECK(has(r.out, "warnings 1 (on standard error)"));
  const Result j = run("bare.ngc --stock 0,0,-5,30,20,0 --pitch 0.2 --report %/bare.json", nullptr, true);
  const std::string rep = slurp(tmp_dir() + "/bare.json");
  CHECK(has(rep, "\"warnings_total\": 1"));
  CHECK(has(rep, "\"used\": [{\"number\": null, \"spec\": \"flat:6\", \"source\": \"default\", \"line\": null, \"form\": null}, "
                 "{\"number\": 1, \"spec\": \"flat:6\", \"source\": \"default\", \"line\": null, \"form\": null}]"));
  // Given, it is no guess.
  const Result g = run("bare.ngc --tool flat:6 --stock 0,0,-5,30,20,0 --pitch 0.2", nullptr, true);
  CHECK(g.err.find("guess") == std::string::npos);
  CHECK(has(g.out, "warnings 0"));
  // Two comments beside one M6 that disagree: neither is taken.
  write_tmp("two.ngc", "G21\n(End mill 3mm)\n(End mill 6mm)\nT1 M6\nG0 X5 Y5 Z5\nG1 Z-1 F300\nG1 X20\nM2\n");
  const Result d = run("two.ngc --stock 0,0,-5,30,20,0 --pitch 0.2", nullptr, true);
  CHECK(has(d.err, "two.ngc:2:1: warning: the comments on lines 2 and 3 describe different tools for T1; neither is used"));
  CHECK(has(d.err, "T1 is cut as flat:6, a guess"));
  CHECK(has(d.out, "warnings 2"));
}

TEST(run_tool_option_and_table_override_comments) {
  if (skip()) return;
  write_tmp("fusion_o.ngc", kFusion);
  const Result r = run("fusion_o.ngc --tool flat:2 --stock 0,0,-5,30,20,0 --pitch 0.1 --report %/fusion_o.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(r.err.find("from the comment") == std::string::npos);
  const std::string rep = slurp(tmp_dir() + "/fusion_o.json");
  CHECK(has(rep, "{\"number\": 1, \"spec\": \"flat:2\", \"source\": \"option\", \"line\": null, \"form\": null}"));
  CHECK(has(rep, "{\"number\": 2, \"spec\": \"flat:2\", \"source\": \"option\", \"line\": null, \"form\": null}"));
  // A table with T2 only: T1 from the comment, T2 from the table.
  write_tmp("t2.tbl", "T2 P2 D4 Z0 ;flat end mill\n");
  const Result t = run("fusion_o.ngc --tools t2.tbl --stock 0,0,-5,30,20,0 --pitch 0.1 --report %/fusion_t2.json", nullptr, true);
  CHECK_EQ(t.code, 0);
  const std::string rep_t = slurp(tmp_dir() + "/fusion_t2.json");
  CHECK(has(rep_t, "{\"number\": 1, \"spec\": \"ball:3\", \"source\": \"comment\", \"line\": 1, \"form\": \"fusion\"}"));
  CHECK(has(rep_t, "{\"number\": 2, \"spec\": \"flat:4\", \"source\": \"table\", \"line\": null, \"form\": null}"));
}
