// libFuzzer target: the LinuxCNC tool table reader (platform/format/tool_table.h)
// and the tool specs it finds in comments (core/tool/spec.h). Input: one
// byte of flags (bit 0: the machine is in inches), then the table's text.
// A table that reads must give each of its tools back by number, each a
// tool that passes tool_check, whose canonical spec text (written into
// buffers of every length, truncated as spec.h says) reads back as the
// same tool, but D0 pockets, which it keeps and refuses; a table that
// does not read, one error line naming the file.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/tool/tool.h"
#include "platform/format/tool_table.h"
#include "tests/fuzz/fuzz_entry.h"
#include "tests/fuzz/fuzz_spec.h"

namespace fuzz_tool_table {

using namespace dexmill;

int fuzz_tool_table(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const bool inch = (data[0] & 1) != 0;
  ToolTableFile table;
  const ToolTableFile::Load r = table.parse("fuzz.tbl", reinterpret_cast<const char*>(data + 1), size - 1, inch);
  FUZZ_REQUIRE(r != ToolTableFile::Load::kIoError);
  for (const std::string& w : table.warnings()) FUZZ_REQUIRE(w.compare(0, 9, "fuzz.tbl:") == 0);
  if (r != ToolTableFile::Load::kOk) {
    FUZZ_REQUIRE(table.message().compare(0, 9, "fuzz.tbl:") == 0);
    FUZZ_REQUIRE(table.message().find('\n') == std::string::npos);
    return 0;
  }
  for (const ToolTableEntry& e : table.entries()) {
    Tool t;
    int64_t z = 0, radius_nm = -1;
    FUZZ_REQUIRE(table.tool_length_nm(e.number, &z) && z == e.length_offset_nm);
    FUZZ_REQUIRE(table.tool_radius_nm(e.number, &radius_nm) && radius_nm == e.tool.diameter_nm / 2);
    if (e.tool.diameter_nm == 0) {
      // D0, an empty pocket (LinuxCNC tables keep them): read, but no
      // cutter; a program that picks it gets an error naming the table.
      FUZZ_REQUIRE(!table.tool(e.number, &t));
      continue;
    }
    FUZZ_REQUIRE(ok(tool_check(e.tool)));
    FUZZ_REQUIRE(table.tool(e.number, &t) && fuzz::same_tool(t, e.tool));
    fuzz::check_spec_text(e.tool);
  }
  return 0;
}

}  // namespace fuzz_tool_table

DEXMILL_FUZZ_ENTRY(fuzz_tool_table::fuzz_tool_table)
