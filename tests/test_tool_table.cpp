// LinuxCNC tool tables: fields, units, shapes from comments, errors.
#include <cstdio>
#include <cstring>
#include <string>

#include <unistd.h>

#include "core/math/fixed.h"
#include "platform/format/tool_table.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
ToolTableFile::Load parse(ToolTableFile* t, const char* text, bool inch = false) {
  return t->parse("tt.tbl", text, std::strlen(text), inch);
}
}  // namespace

TEST(tool_table_reads_linuxcnc_lines) {
  ToolTableFile t;
  CHECK_EQ(parse(&t,
                 "; a table\n"
                 "T1 P1 D6.0 Z+30.0 ;flat end mill 6 mm\n"
                 "\n"
                 "T2 P2 X0 Y0 Z35 D6 I0 J0 Q0 ;Ball nose 6mm\r\n"
                 "t3 p3 d5 z40 ;spot drill vbit:5:118\n"
                 "T4 P4 D10 Z50 ;bull:99:2,len=20 (its D is the table's)\n"),
           ToolTableFile::Load::kOk);
  CHECK_EQ(t.entries().size(), 4u);
  Tool tool;
  CHECK(t.tool(1, &tool));
  CHECK_EQ(tool.kind, ToolKind::kFlat);
  CHECK_EQ(tool.diameter_nm, 6 * kNmPerMm);
  CHECK(t.tool(2, &tool));
  CHECK_EQ(tool.kind, ToolKind::kBall);
  CHECK(t.tool(3, &tool));
  CHECK_EQ(tool.kind, ToolKind::kVBit);
  CHECK_EQ(tool.tip_angle_mdeg, 118000);
  CHECK_EQ(tool.diameter_nm, 5 * kNmPerMm);
  CHECK(t.tool(4, &tool));
  CHECK_EQ(tool.kind, ToolKind::kBullNose);
  CHECK_EQ(tool.diameter_nm, 10 * kNmPerMm);
  CHECK_EQ(tool.corner_radius_nm, 2 * kNmPerMm);
  CHECK_EQ(tool.flute_length_nm, 20 * kNmPerMm);
  int64_t z = 0;
  CHECK(t.tool_length_nm(2, &z));
  CHECK_EQ(z, 35 * kNmPerMm);
  CHECK(!t.tool(9, &tool));
  CHECK(!t.tool_length_nm(9, &z));
  CHECK(t.warnings().empty());
  // G41/G42 take half the D column.
  int64_t r = 0;
  CHECK(t.tool_radius_nm(4, &r));
  CHECK_EQ(r, 5 * kNmPerMm);
  CHECK(!t.tool_radius_nm(9, &r));
}

TEST(tool_table_single_tool_gives_its_radius) {
  // `run` without --tools: every number is --tool, length 0, radius D / 2.
  Tool tool;
  tool.diameter_nm = 6350000;
  const SingleToolLibrary one(tool);
  int64_t r = 0, z = 1;
  CHECK(one.tool_radius_nm(17, &r));
  CHECK_EQ(r, 3175000);
  CHECK(one.tool_length_nm(17, &z));
  CHECK_EQ(z, 0);
}

TEST(tool_table_inch_and_warnings) {
  ToolTableFile t;
  CHECK_EQ(parse(&t, "T7 P7 D0.25 Z1.5 ;1/4 V-bit\n", true), ToolTableFile::Load::kOk);
  Tool tool;
  CHECK(t.tool(7, &tool));
  CHECK_EQ(tool.diameter_nm, 6350000);
  CHECK_EQ(tool.kind, ToolKind::kFlat);
  int64_t z = 0;
  CHECK(t.tool_length_nm(7, &z));
  CHECK_EQ(z, 38100000);
  CHECK_EQ(t.warnings().size(), 1u);
  CHECK(t.warnings()[0].find("tt.tbl:1:1: warning: T7 is simulated as a flat end mill") == 0);
}

// A remark without a spec is read with the program comments' kind words
// (core/tool/tool_comment.h tool_remark_shape): the shapes it names are
// cut, a shape it cannot complete or a tool dexmill does not cut is a flat
// end mill with a warning, and a plain remark is a flat end mill, silently.
TEST(tool_table_remark_kinds) {
  struct Case {
    const char* row;
    ToolKind kind;
    int32_t tip_mdeg;
    bool warned;
  } cases[] = {
      {"T1 P1 D6 ;flat end mill\n", ToolKind::kFlat, 0, false},
      {"T1 P1 D3 ;3 mm drill\n", ToolKind::kVBit, 118000, false},
      {"T1 P1 D3 ;spot drill 90deg\n", ToolKind::kVBit, 90000, false},
      {"T1 P1 D6 ;vbit 60deg\n", ToolKind::kVBit, 60000, false},
      {"T1 P1 D6 ;Ball nose\n", ToolKind::kBall, 0, false},
      {"T1 P1 D6 ;roughing\n", ToolKind::kFlat, 0, false},
      {"T1 P1 D6\n", ToolKind::kFlat, 0, false},
      {"T1 P1 D6 ;vbit\n", ToolKind::kFlat, 0, true},
      {"T1 P1 D6 ;bull nose\n", ToolKind::kFlat, 0, true},
      {"T1 P1 D6 ;M6 tap\n", ToolKind::kFlat, 0, true},
      {"T1 P1 D6 ;probe\n", ToolKind::kFlat, 0, true},
  };
  for (const Case& c : cases) {
    ToolTableFile t;
    CHECK_EQ(parse(&t, c.row, false), ToolTableFile::Load::kOk);
    Tool tool;
    CHECK(t.tool(1, &tool));
    const bool right = tool.kind == c.kind && tool.tip_angle_mdeg == c.tip_mdeg && t.warnings().empty() != c.warned;
    if (!right) std::printf("  %s -> kind %d tip %d, %zu warnings\n", c.row, static_cast<int>(tool.kind), tool.tip_angle_mdeg, t.warnings().size());
    CHECK(right);
  }
}

TEST(tool_table_errors) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"T1 D6 K3\n", "tt.tbl:1:7: error: unknown word 'K'"},
      {"T1 P1\n", "tt.tbl:1:1: error: tool T1 has no diameter (D)"},
      {"P1 D6\n", "tt.tbl:1:1: error: a tool needs a number (T)"},
      {"T1 D6\nT1 D3\n", "tt.tbl:2:1: error: tool T1 is already defined on line 1"},
      {"T1.5 D6\n", "tt.tbl:1:1: error: the tool number must be a whole number"},
      {"T1 D-1\n", "tt.tbl:1:4: error: the diameter must be 0 or between"},
      {"T1 D0.0001\n", "tt.tbl:1:4: error: the diameter must be 0 or between"},
      {"T1 DX\n", "tt.tbl:1:4: error: 'D' needs a number"},
      {"T1 D4 ;bull:4:1.5\nT2 D2 ;bull:4:1.5\n", "tt.tbl:2:1: error: the corner radius of T2 is larger than D/2"},
      // A shape that does not parse is said to be wrong, not replaced by a
      // flat end mill with a warning asking for a shape.
      {"T1 P1 D6 ;engraver vbit:1000:0.001\n", "tt.tbl:1:20: error: the shape 'vbit:1000:0.001' of T1 is not usable: "},
  };
  for (const Case& c : cases) {
    ToolTableFile t;
    CHECK_EQ(parse(&t, c.text), ToolTableFile::Load::kInputError);
    if (t.message().find(c.message) != 0) {
      std::printf("  message: %s\n  wanted:  %s...\n", t.message().c_str(), c.message);
      CHECK(false);
    }
  }
  ToolTableFile t;
  CHECK_EQ(t.load("/nonexistent/tools.tbl", false), ToolTableFile::Load::kIoError);
  CHECK(t.message().find("cannot read '/nonexistent/tools.tbl'") == 0);
  // A table past the size limit is an error, not a table cut short (it
  // used to end at 64 MB, then say a later tool was missing).
  char path[] = "/tmp/dexmill-tool-table-XXXXXX";
  const int fd = mkstemp(path);
  CHECK(fd >= 0);
  if (fd >= 0) {
    CHECK_EQ(ftruncate(fd, static_cast<off_t>(kToolTableMaxBytes) + 1), 0);
    close(fd);
    ToolTableFile big;
    CHECK_EQ(big.load(path, false), ToolTableFile::Load::kInputError);
    CHECK(big.message().find(": error: larger than 64 MB") != std::string::npos);
    unlink(path);
  }
}

// The holder and the other safety fields ride in the comment's spec word.
TEST(tool_table_holder_in_comment) {
  ToolTableFile t;
  CHECK_EQ(parse(&t, "T7 P7 D6 Z40 ;roughing flat:6,len=12,stick=30,holder=20x10,32-40x15,nocentre\n"),
           ToolTableFile::Load::kOk);
  Tool tool;
  CHECK(t.tool(7, &tool));
  CHECK_EQ(tool.flute_length_nm, 12 * kNmPerMm);
  CHECK_EQ(tool.length_nm, 30 * kNmPerMm);
  CHECK_EQ(tool.holder_segments, 2);
  CHECK_EQ(tool.holder[1].top_diameter_nm, 40 * kNmPerMm);
  CHECK(!tool.centre_cutting);
  ToolTableFile bad;
  CHECK_EQ(parse(&bad, "T7 P7 D6 Z40 ;flat:6,holder=20\n"), ToolTableFile::Load::kInputError);
  CHECK(bad.message().find("tt.tbl:1:") == 0);
  CHECK(bad.message().find("holder") != std::string::npos);
}
