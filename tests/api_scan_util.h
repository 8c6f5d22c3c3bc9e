// The embedding API's first pass in tests (tests/test_api_scan.cpp,
// test_api_tool_table.cpp, test_api_demo.cpp): a scan with its memory fed
// in pieces, a job with a tool, the grid of a simulation of a job.
#ifndef DEXMILL_TESTS_API_SCAN_UTIL_H
#define DEXMILL_TESTS_API_SCAN_UTIL_H

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "tests/runner.h"

namespace api_scan {

// A scan with its memory.
struct Scan {
  std::vector<uint64_t> mem;
  dm_scan* scan = nullptr;
  explicit Scan(const dm_job& j) {
    size_t n = 0;
    CHECK_EQ(dm_scan_bytes(&j, &n), DM_OK);
    mem.assign(n / 8 + 1, 0);
    CHECK_EQ(dm_scan_create(&j, mem.data(), n, &scan), DM_OK);
  }
  ~Scan() { dm_scan_destroy(scan); }
  // Feeds text in pieces of `piece` bytes, `lines` lines a step; the final state.
  int32_t run(const std::string& text, size_t piece, uint32_t lines = 0) {
    dm_budget b{};
    b.lines = lines;
    size_t at = 0;
    int32_t state = DM_READY;
    for (int guard = 0; guard < 1000000; ++guard) {
      CHECK_EQ(dm_scan_step(scan, &b, &state), DM_OK);
      if (state == DM_NEED_INPUT) {
        if (at >= text.size()) {
          CHECK_EQ(dm_scan_end_input(scan), DM_OK);
        } else {
          const size_t n = std::min(piece, text.size() - at);
          CHECK_EQ(dm_scan_feed(scan, text.data() + at, n), DM_OK);
          at += n;
        }
        continue;
      }
      if (state != DM_READY) break;
    }
    return state;
  }
};

inline dm_job tool_job(const char* spec) {
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  j.tool.spec = spec;
  return j;
}

// The grid of a simulation of the job.
inline dm_grid_info grid_of(const dm_job& j) {
  dm_grid_info g{};
  size_t n = 0;
  CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
  std::vector<uint64_t> mem(n / 8 + 1);
  dm_sim* sim = nullptr;
  CHECK_EQ(dm_create(&j, mem.data(), n, &sim), DM_OK);
  CHECK_EQ(dm_get_grid(sim, &g), DM_OK);
  dm_destroy(sim);
  return g;
}

}  // namespace api_scan

#endif
