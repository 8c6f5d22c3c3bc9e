// A tool's canonical spec text (core/tool/spec.h's tool_spec_format) must
// read back as the same tool, and shorter buffers must get the text's
// first n - 1 bytes, NUL-terminated, with nothing written past them. Used
// by the pipeline target (the line-1 tool) and the tool table target.
#ifndef DEXMILL_TESTS_FUZZ_SPEC_H
#define DEXMILL_TESTS_FUZZ_SPEC_H

#include <cstring>

#include "core/tool/spec.h"
#include "core/tool/tool.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz {

inline bool same_tool(const dexmill::Tool& a, const dexmill::Tool& b) {
  return a.kind == b.kind && a.diameter_nm == b.diameter_nm && a.corner_radius_nm == b.corner_radius_nm &&
         a.tip_angle_mdeg == b.tip_angle_mdeg && a.flute_length_nm == b.flute_length_nm && a.length_nm == b.length_nm;
}

inline void check_spec_text(const dexmill::Tool& t) {
  using namespace dexmill;
  char full[96];
  const size_t n = tool_spec_format(t, full, sizeof full);
  FUZZ_REQUIRE(n < sizeof full - 1 && std::strlen(full) == n);
  Tool back;
  FUZZ_REQUIRE(tool_spec_parse(full, n, &back) == ToolSpecError::kOk);
  FUZZ_REQUIRE(same_tool(back, t));
  for (size_t cap = 1; cap <= n + 1; ++cap) {
    char buf[96];
    std::memset(buf, '#', sizeof buf);
    const size_t m = tool_spec_format(t, buf, cap);
    FUZZ_REQUIRE(m == (cap - 1 < n ? cap - 1 : n) && buf[m] == 0 && std::memcmp(buf, full, m) == 0);
    for (size_t k = m + 1; k < sizeof buf; ++k) FUZZ_REQUIRE(buf[k] == '#');
  }
}

}  // namespace fuzz

#endif
