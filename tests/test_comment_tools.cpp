// Comments bound to the tools a program loads (core/sim/comment_tools.h)
// and the run's precedence (core/sim/tool_choice.h), through the first
// pass (core/sim/scan.h) as the CLI runs it.
#include <memory>
#include <string>
#include <vector>

#include "core/gcode/line_reader.h"
#include "core/math/fixed.h"
#include "core/sim/chunk_input.h"
#include "core/sim/scan.h"
#include "core/sim/tool_choice.h"
#include "core/tool/spec.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

class Quiet final : public GcodeMessages {
 public:
  void error(const GcodeDiag&) override { ++errors_; }
  void warning(const GcodeDiag&) override { ++warnings_; }
};

// A library of one tool for every number: a table stand-in.
class OneTool final : public ToolLibrary {
 public:
  OneTool(int32_t n, const char* spec) : n_(n) { (void)tool_spec_parse(spec, std::char_traits<char>::length(spec), &t_); }
  bool tool(int32_t number, Tool* out) const override {
    if (number != n_) return false;
    *out = t_;
    return true;
  }

 private:
  int32_t n_;
  Tool t_;
};

Tool default_tool() {
  Tool t;
  (void)tool_spec_parse("flat:6", 6, &t);
  return t;
}

// The first pass over `text` with `choice` as the job's library.
struct Scanned {
  std::unique_ptr<ToolChoice> choice;
  std::unique_ptr<ProgramScan> scan;
};

Scanned scan(const std::string& text, bool option = false, const ToolLibrary* table = nullptr) {
  Scanned s;
  s.choice.reset(new ToolChoice(default_tool(), option, table, nullptr));
  SimJob job;
  job.tool = default_tool();
  job.library = s.choice.get();
  job.offsets = s.choice.get();
  s.scan.reset(new ProgramScan(job));
  s.scan->set_tool_choice(s.choice.get());
  std::vector<char> buf(LineReader::kStartBytes);
  ChunkInput in(buf.data(), buf.size());
  in.feed(text.data(), text.size());
  in.close();
  Quiet q;
  const std::unique_ptr<ProgramMemory> mem(new ProgramMemory());
  s.scan->run(&in, &q, mem.get());
  return s;
}

// T n's tool as spec text, and where it comes from ("flat:6 default").
std::string tool_of(const Scanned& s, int32_t n) {
  Tool t;
  ToolSource src;
  if (n == kSpindleToolNumber) {
    t = s.choice->initial(&src);
  } else {
    if (!s.choice->tool(n, &t)) return "none";
    src = s.choice->source(n);
  }
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  return std::string(spec) + " " + tool_source_name(src);
}

}  // namespace

TEST(comment_tools_numbered_list_in_the_units_of_its_m6) {
  // Fusion writes its list before G20: read in inch, where T1 is loaded.
  const Scanned s = scan("(T1 D=0.25 CR=0. - flat end mill)\n(T2 D=0.125 CR=0.0625 - ball end mill)\n"
                         "G20 G90\nT1 M6\nG0 X0 Y0 Z0.2\nG1 Z-0.1 F10\nG1 X1\nT2 M6\nG1 X2 Y1\nM30\n");
  CHECK(tool_of(s, 1) == "flat:6.35 comment");
  CHECK(tool_of(s, 2) == "ball:3.175 comment");
  CHECK(tool_of(s, 7) == "flat:6 default");
  const CommentTool* c = s.choice->comments().find(2);
  CHECK(c != nullptr);
  if (c) CHECK_EQ(c->line, 2u);
  CHECK_EQ(s.scan->ntools, 3);
  CHECK_EQ(s.scan->max_radius_nm, 3175000);  // the listed tools, not the default's 3 mm
  CHECK(s.scan->cuts[1] && s.scan->cuts[2] && !s.scan->cuts[0]);
}

TEST(comment_tools_beside_their_m6) {
  // pcb2gcode: T, M5, the message, then M6; a move before it closes the
  // window of the one before.
  const Scanned p = scan("G21\nG0 Z10\nT1\nM5\n(MSG, Change tool bit to drill size 0.8mm)\nM6\nG0 X1 Y1 Z2\nG1 Z-1 F100\n"
                         "G0 Z10\nT2\nM5\n(MSG, Change tool bit to drill size 1.2mm)\nM6\nG0 X5\nG1 Z-1\nM2\n");
  CHECK(tool_of(p, 1) == "vbit:0.8:118 comment");
  CHECK(tool_of(p, 2) == "vbit:1.2:118 comment");
  // Estlcam's list, then a change naming its tool on the M6's line.
  const Scanned e = scan("(Required tools:)\n(End mill 3mm)\n(End mill 6mm)\nG21\nT2 M06 (Change tool: End mill 6mm)\n"
                         "G0 X0 Y0 Z5\nG1 Z-1 F300\nG1 X10\nM30\n");
  CHECK(tool_of(e, 2) == "flat:6 comment");
  const CommentTool* e2 = e.choice->comments().find(2);
  CHECK(e2 != nullptr);
  if (e2) CHECK_EQ(e2->line, 5u);
  // Vectric: the name after the M6, before the first move.
  const Scanned v = scan("G21\nT4 M6\n(Tool: Ball Nose {0.125 inch})\nG0 X0 Y0 Z5\nG1 Z-1 F300\nG1 X10\nM30\n");
  CHECK(tool_of(v, 4) == "ball:3.175 comment");
  // A comment before the next M6 is that one's, not the last one's.
  const Scanned b = scan("G21\nT1 M6 (Reset tool)\n(Tool: 1/8 in Carbide End Mill)\nT2 M6\nG0 X0 Y0 Z5\nG1 Z-1 F300\nM2\n");
  CHECK(tool_of(b, 1) == "flat:6 default");
  CHECK(tool_of(b, 2) == "flat:3.175 comment");
  // A weak name counts on its M6's line only.
  const Scanned w = scan("G20\nM06 T7 ( 0.0625 mill )\nG0 X0 Y0 Z0.1\nG1 Z-0.05 F10\nG1 X1\n(1/4 endmill)\nT8 M6\nG1 X2\nM2\n");
  CHECK(tool_of(w, 7) == "flat:1.5875 comment");
  CHECK(tool_of(w, 8) == "flat:6 default");
}

TEST(comment_tools_disagreeing_and_conflicting) {
  const Scanned d = scan("G21\n(End mill 3mm)\n(End mill 6mm)\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F300\nM2\n");
  CHECK(tool_of(d, 1) == "flat:6 default");
  CHECK_EQ(d.choice->comments().ambiguous().count, 1u);
  CHECK_EQ(d.choice->comments().ambiguous().number, 1);
  CHECK_EQ(d.choice->comments().ambiguous().line_a, 2u);
  CHECK_EQ(d.choice->comments().ambiguous().line_b, 3u);
  // The same T described twice otherwise: the first is kept.
  const Scanned c = scan("(T1 ball:3)\n(T1 flat:2)\nG21\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F300\nM2\n");
  CHECK(tool_of(c, 1) == "ball:3 comment");
  CHECK_EQ(c.choice->comments().conflicts().count, 1u);
  CHECK_EQ(c.choice->comments().conflicts().line_b, 2u);
}

TEST(comment_tools_the_tool_before_any_m6) {
  // One tool described before the first cut.
  const Scanned one = scan("( T0 : 1.0 )\nG21 G90\nG0 Z3\n( T0 : 1.0 )\nG0 X1 Y1\nG1 Z-1 F300\nG1 X5\nM2\n");
  CHECK(tool_of(one, kSpindleToolNumber) == "flat:1 comment");
  CHECK(one.scan->cuts[0]);
  CHECK_EQ(one.scan->first_lines[0], 6u);
  CHECK_EQ(one.scan->tools[0].diameter_nm, kNmPerMm);
  // Two, apart: the last, which stands by the cut.
  const Scanned last = scan("(TOOL/MILL,0.1,0.05,0.000,0)\nG21\nM3 S1000\nG0 X0 Y0 Z5\n(TOOL/MILL,3,0,0,0)\nG0 X1\n"
                            "G1 Z-1 F300\nG1 X5\nM2\n");
  CHECK(tool_of(last, kSpindleToolNumber) == "flat:3 comment");
  // Two in a list: which one is in the spindle is not said.
  const Scanned list = scan("(End mill 3mm)\n(End mill 6mm)\nG21\nG0 X1 Y1 Z5\nG1 Z-1 F300\nM2\n");
  CHECK(tool_of(list, kSpindleToolNumber) == "flat:6 default");
  CHECK_EQ(list.choice->comments().ambiguous().count, 1u);
  // A list, and the T selected (no M6): that T's.
  const Scanned sel = scan("(T1 D=3 CR=0 - flat end mill)\n(T2 D=6 CR=0 - flat end mill)\nG21\nT2\nG0 X0 Y0 Z5\n"
                           "G1 Z-1 F300\nM2\n");
  CHECK(tool_of(sel, kSpindleToolNumber) == "flat:6 comment");
  // A G1 with no axis word moves nothing: the tool has not cut yet.
  const Scanned f = scan("G21\nG1 F100\nT1\n(MSG, Change tool bit to drill size 0.8mm)\nM6\nG0 X0 Y0 Z1\nG1 Z-1\nM2\n");
  CHECK(!f.scan->cuts[0]);
  CHECK(tool_of(f, 1) == "vbit:0.8:118 comment");
}

TEST(comment_tools_precedence) {
  const std::string prog = "(T1 ball:3)\n(T2 ball:4)\nG21\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F300\nT2 M6\nG1 X5\nM2\n";
  // --tool: every T, the comments aside.
  const Scanned o = scan(prog, true);
  CHECK(tool_of(o, 1) == "flat:6 option");
  CHECK(tool_of(o, kSpindleToolNumber) == "flat:6 option");
  // A table: its T's; a T it lacks from the comments; lengths 0 and the
  // comment's radius for G41/G42.
  const OneTool table(2, "flat:10");
  const Scanned t = scan(prog, false, &table);
  CHECK(tool_of(t, 2) == "flat:10 table");
  CHECK(tool_of(t, 1) == "ball:3 comment");
  CHECK(tool_of(t, 5) == "none");
  int64_t r = 0;
  CHECK(t.choice->tool_radius_nm(1, &r));
  CHECK_EQ(r, 1500000);
  CHECK(!t.choice->tool_radius_nm(5, &r));
  // No table, no option: the default for what no comment gives.
  const Scanned d = scan(prog);
  CHECK(tool_of(d, 2) == "ball:4 comment");
  CHECK(tool_of(d, 9) == "flat:6 default");
  CHECK(d.choice->tool_radius_nm(9, &r));
  CHECK_EQ(r, 3000000);
  int64_t z = 1;
  CHECK(d.choice->tool_length_nm(9, &z));
  CHECK_EQ(z, 0);
  // A list entry no M6 loads still answers G41 D (bound at the first move).
  const Scanned g = scan("(T5 D=4 CR=0 - flat end mill)\nG21\nT1 M6\nG0 X0 Y0 Z5\nM2\n");
  CHECK(g.choice->tool_radius_nm(5, &r));
  CHECK_EQ(r, 2000000);
}
