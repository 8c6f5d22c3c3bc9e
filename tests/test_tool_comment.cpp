// Tools in comments (core/tool/tool_comment.h): each CAM post's form, in
// mm and inch, and comments that mention sizes but are no tool. The texts
// are written here in the forms the posts write (none is copied from a
// program).
#include <cstdio>
#include <cstring>
#include <string>

#include "core/tool/spec.h"
#include "core/tool/tool_comment.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// The tool the comment describes as spec text in a program in inch or mm,
// its number after '#' and a '~' when weak ("flat:6#1"); "-" for none.
std::string read(const char* text, bool inch = false, ToolCommentState* st = nullptr) {
  ToolCommentState own;
  ToolComment c;
  if (!tool_comment_read(text, std::strlen(text), st ? st : &own, &c)) return "-";
  Tool t;
  if (!tool_comment_tool(c, inch, &t)) return "out of range";
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  std::string o = spec;
  if (c.number >= 0) o += "#" + std::to_string(c.number);
  if (c.weak) o += "~";
  return o;
}

ToolCommentForm form(const char* text) {
  ToolCommentState st;
  ToolComment c;
  return tool_comment_read(text, std::strlen(text), &st, &c) ? c.form : ToolCommentForm::kNone;
}

bool expect(const char* file, int line, const char* text, bool inch, const char* want) {
  const std::string got = read(text, inch);
  if (got == want) return true;
  char d[400];
  std::snprintf(d, sizeof d, "comment (%s) in %s: got %s, want %s", text, inch ? "inch" : "mm", got.c_str(), want);
  t::fail(file, line, "tool comment", d);
  return false;
}

}  // namespace

#define EXPECT_TOOL(text, inch, want) expect(__FILE__, __LINE__, text, inch, want)

TEST(tool_comment_fusion_tool_list) {
  EXPECT_TOOL("T1  D=6.35 CR=0 - ZMIN=-19.8 - flat end mill", false, "flat:6.35#1");
  EXPECT_TOOL("T1 D=3.175 CR=0. - ZMIN=-5. - flat end mill", false, "flat:3.175#1");
  EXPECT_TOOL("T3 D=6. CR=3. - ZMIN=-2 - ball end mill", false, "ball:6#3");
  EXPECT_TOOL("T2 D=6. CR=1. - ZMIN=-2 - bullnose end mill", false, "bull:6:1#2");
  EXPECT_TOOL("T11 D=0.5 CR=0.03 - ZMIN=0.1475 - BULLNOSE END MILL", true, "bull:12.7:0.762#11");
  // A chamfer mill's taper is its half angle; a drill's its point angle.
  EXPECT_TOOL("T9  D=6. CR=0. TAPER=45deg - ZMIN=-1.3 - chamfer mill - 6mm Chamfer Mill", false, "vbit:6:90#9");
  EXPECT_TOOL("T12 D=6.5 CR=0. TAPER=118deg - ZMIN=-14.953 - drill - 6.5mm Drill", false, "vbit:6.5:118#12");
  EXPECT_TOOL("T1 D=0.125 CR=0. TAPER=90deg - ZMIN=1.1 - center drill", true, "vbit:3.175:90#1");
  EXPECT_TOOL("T4 D=3. CR=0. - drill", false, "vbit:3:118#4");
  // A description between the number and D=, no ZMIN, a face mill's lead angle.
  EXPECT_TOOL("T8  Chamfering Bit - 1/8 Shank      D=3.175 CR=0. TAPER=45deg - ZMIN=-0.5 - chamfer mill", false,
              "vbit:3.175:90#8");
  EXPECT_TOOL("T5 D=50. CR=0. TAPER=45deg - face mill", false, "flat:50#5");
  EXPECT_TOOL("T1 D=0.25 CR=0. - ZMIN=-0.5 - flat end mill", true, "flat:6.35#1");
  CHECK(form("T1 D=6 CR=0 - flat end mill") == ToolCommentForm::kFusion);
  // Shapes dexmill does not cut, and a taper on an end mill.
  EXPECT_TOOL("T3 D=0.3125 CR=0. - ZMIN=0.2259 - right hand tap", true, "-");
  EXPECT_TOOL("T12 D=1.872 CR=1. TAPER=3.8deg - ZMIN=-0.7 - tapered mill", false, "-");
  EXPECT_TOOL("T6 D=6 CR=0 - thread mill", false, "-");
  EXPECT_TOOL("T7 D=6 CR=0 TAPER=10deg - flat end mill", false, "-");
  EXPECT_TOOL("T2 D=6 CR=1 TAPER=45deg - chamfer mill", false, "-");
}

TEST(tool_comment_apt_tool_mill) {
  EXPECT_TOOL("TOOL/MILL,3.17, 0.00, 0.00, 0.00", false, "flat:3.17");
  EXPECT_TOOL("TOOL/MILL,6.35, 3.17, 0.00, 0.00", false, "ball:6.35");  // CR rounded below D/2
  EXPECT_TOOL("TOOL/MILL,10, 1, 25, 0", false, "bull:10:1");
  EXPECT_TOOL(" TOOL/MILL,1,0,50 ", false, "flat:1");
  EXPECT_TOOL("TOOL/MILL,0.1,0.05,0.000,0", false, "ball:0.1");
  // A V-bit: the tip's diameter, the height and the half angle give the top.
  EXPECT_TOOL("TOOL/MILL,0.03, 0.00, 6.35, 45.00", false, "vbit:12.73:90");
  EXPECT_TOOL("TOOL/MILL,0.0250,0,10.0000,15.0", false, "vbit:5.383984:30");
  EXPECT_TOOL("TOOL/MILL,0.03, 0.00, 6.35, 45.00", true, "vbit:323.342:90");
  EXPECT_TOOL("TOOL/DRILL, 3, 118", false, "vbit:3:118");
  // No height: no width to the cone; a tapered ball; a tapered flat end.
  EXPECT_TOOL("TOOL/MILL,0.03, 0.00, 0.00, 45.00", false, "-");
  EXPECT_TOOL("TOOL/MILL,3, 0.5, 10, 5", false, "-");
  EXPECT_TOOL("TOOL/MILL,3, 0, 10, 5", false, "-");
  EXPECT_TOOL("TOOL/MILL,abc", false, "-");
  CHECK(form("TOOL/MILL,3.17, 0.00, 0.00, 0.00") == ToolCommentForm::kApt);
}

TEST(tool_comment_estlcam_vectric_camotics_names) {
  EXPECT_TOOL("HSS, 2-Flute Endmill, 2mm", false, "flat:2");
  EXPECT_TOOL("End mill 3mm", true, "flat:3");
  EXPECT_TOOL("Change tool: End mill 3mm", false, "flat:3");
  EXPECT_TOOL("1 = End Mill {6 mm}", false, "flat:6#1");
  EXPECT_TOOL("5 = End Mill {0.2500 inch} UpDown", false, "flat:6.35#5");
  EXPECT_TOOL("T2 = End Mill {0.5 inches}", false, "flat:12.7#2");
  EXPECT_TOOL("Tool: End Mill {0.2500 inch} UpDown", false, "flat:6.35");
  EXPECT_TOOL("Tool: Ball Nose {0.125 inch}", false, "ball:3.175");
  EXPECT_TOOL("Tool: 60 deg V-Bit {12.7 mm}", false, "vbit:12.7:60");
  EXPECT_TOOL("Tool: 1/4 in Carbide End Mill", false, "flat:6.35");
  EXPECT_TOOL(" Tool: 3.0mm", false, "flat:3");
  EXPECT_TOOL("Bit diameter: 1/8\"", false, "flat:3.175");
  EXPECT_TOOL("5mm Endmill001", true, "flat:5");
  EXPECT_TOOL("begin operation: 5mm Endmill001", false, "flat:5");
  EXPECT_TOOL("1/8 inch 2-flute upcut, 1/4 inch shank", false, "flat:3.175");
  EXPECT_TOOL("Bull nose 10mm R1.5mm", false, "bull:10:1.5");
  EXPECT_TOOL("90 degree V-bit 1/2\"", true, "vbit:12.7:90");
  EXPECT_TOOL("3mm drill", false, "vbit:3:118");
  EXPECT_TOOL("1 1/4\" slot drill", false, "flat:31.75");
  EXPECT_TOOL("Tool 3: 6mm ball nose", false, "ball:6#3");
  CHECK(form("End mill 3mm") == ToolCommentForm::kNamed);
}

TEST(tool_comment_pcb2gcode_cambam_pycam_table_spec) {
  EXPECT_TOOL("MSG, Change tool bit to drill size 0.8mm", true, "vbit:0.8:118");
  EXPECT_TOOL("MSG, Change tool bit to drill size 0.03150inch", false, "vbit:0.8001:118");
  EXPECT_TOOL("MSG, Change tool bit to mill diameter 0.10000mm", false, "flat:0.1");
  EXPECT_TOOL("MSG, Change tool bit to cutter diameter 0.12000mm", false, "flat:0.12");
  EXPECT_TOOL("MSG, Change tool bit to mill diameter 0.00000in", false, "-");
  CHECK(form("MSG, Change tool bit to drill size 1mm") == ToolCommentForm::kPcb2gcode);
  // CamBam: the number and the diameter, in the program's units.
  EXPECT_TOOL(" T0 : 1.0 ", false, "flat:1#0");
  EXPECT_TOOL("T4 : 0.125", true, "flat:3.175#4");
  // PyCAM: the shape a line before the radius.
  ToolCommentState st;
  CHECK(read("shape = SphericalCutter", false, &st) == "-");
  CHECK(read("tool_radius = 1.5", false, &st) == "ball:3");
  CHECK(read("shape = ToroidalCutter", false, &st) == "-");
  CHECK(read("torus_radius = 0.25", false, &st) == "-");
  CHECK(read("tool_radius = 2", false, &st) == "bull:4:0.25");
  EXPECT_TOOL("tool_radius = 0.79375", false, "flat:1.5875");
  EXPECT_TOOL("tool_radius = 0.0625", true, "flat:3.175");
  // A LinuxCNC tool table line, and its old columns T P Z D.
  EXPECT_TOOL("T1 P1 D6.0 Z+30.0 ;ball nose", false, "ball:6#1");
  EXPECT_TOOL("T3 P3 D5 Z40 ;spot drill vbit:5:118", false, "vbit:5:118#3");
  EXPECT_TOOL("T7 P7 D0.25 Z1.5", true, "flat:6.35#7");
  EXPECT_TOOL("1       1       -1.1901     0.250   3/4 center drill", true, "vbit:6.35:118#1");
  EXPECT_TOOL("4       4       -1.6630     0.25    1/4 end mill", true, "flat:6.35#4");
  EXPECT_TOOL("6       6       -0.1833     0.25    1/4-20 pulley tap", true, "-");
  EXPECT_TOOL("2 2 -0.2875 0.209 #4 tap drill", true, "vbit:5.3086:118#2");
  // A --tool spec word, mm whatever the program's units.
  EXPECT_TOOL("T1 ball:3.175", true, "ball:3.175#1");
  EXPECT_TOOL("tool vbit:6:60,len=10", false, "vbit:6:60,len=10");
}

TEST(tool_comment_weak_names_wait_for_their_m6) {
  EXPECT_TOOL(" 0.0625 mill ", true, "flat:1.5875~");
  EXPECT_TOOL("1/4 endmill", true, "flat:6.35~");
  EXPECT_TOOL("2 flute 1/4 endmill", true, "flat:6.35~");
  EXPECT_TOOL("mill the pocket 3mm", false, "flat:3~");
  EXPECT_TOOL("2 flute endmill", false, "-");
  EXPECT_TOOL("1/4 or 3/8 endmill", false, "-");
  EXPECT_TOOL("endmill at 1000mm/min", false, "-");
  EXPECT_TOOL("1/4 endmill 30 deg", true, "flat:6.35~");
}

TEST(tool_comment_false_alarms) {
  static const char* const kNoTool[] = {
      "stock D=50",
      "Z safe 5mm",
      "Pocket 6mm deep",
      "Drill holes 3mm",
      "Bit sizes: [0.8mm] [1mm]",
      " This file uses a mill head of 0.03150inch to drill the 2 hole sizes. ",
      "Tool change",
      "T1 M6",
      " T0 M6 ",
      "Unit of measure: mm",
      "machine units: mm/min",
      "End mill feed 1000mm/min",
      "Compensated Tool Path. Diameter: 5.0",
      "Change tool to Cylindrical cutter",
      "DrillOrPullZFromTo 15.000 1.000",
      "MillArc l=[9.000|-6.000] r=3.000 a0=109.471",
      "Chamfer 0.5mm",
      "Chamfer mill 6mm 45deg",
      "1/4-20 tap",
      "Thread mill 6mm",
      "V-bit 6mm",
      "Ball nose 3mm radius",
      "Depth per pass: 1.0mm",
      "Safe height: 5.0mm",
      " Tool step over: 0.3mm",
      " Cut from arborite stock with 0.049\" endmill. ",
      "End mill 3mm 6mm",
      "Operation 1: Pocket 10mm",
      "T1 D=6.35 CR=0 - ZMIN=-19.8 - probe",
      "D=3 CR=0 - flat end mill",
      "stockMin:0.00mm, 0.00mm, -12.70mm",
      "STOCK/BLOCK,100.00, 100.00, 1.00,0.00, 0.00, 1.00",
      "   DESCRIPTION:30.0 deg. conical with 0.000 mm tip rad.",
      "tool 4 is 1\" in diameter and must be defined in the tool table",
      "Engraving 1",
      "G21 (mm)",
      "",
      "   ",
  };
  for (const char* text : kNoTool) EXPECT_TOOL(text, false, "-");
}

TEST(tool_comment_units_and_ranges) {
  // No unit: the program's; a unit given: that one.
  EXPECT_TOOL("T1 D=3 CR=0 - flat end mill", true, "flat:76.2#1");
  EXPECT_TOOL("End mill 3mm", true, "flat:3");
  EXPECT_TOOL("End mill 0.125in", false, "flat:3.175");
  EXPECT_TOOL("End mill 1/8\"", false, "flat:3.175");
  // Beyond a metre across: no tool.
  EXPECT_TOOL("T1 D=5000 CR=0 - flat end mill", false, "out of range");
  EXPECT_TOOL("End mill 123456789012mm", false, "-");
  CHECK(std::strcmp(tool_comment_form_name(ToolCommentForm::kFusion), "fusion") == 0);
  CHECK(std::strcmp(tool_comment_form_name(ToolCommentForm::kNone), "none") == 0);
}
