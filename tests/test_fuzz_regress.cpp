// Every fuzz target's inputs that once failed (tests/fuzz/regress/TARGET/)
// and its seeds (tests/fuzz/seeds/TARGET/), run through the same code in
// every `make test`: each must finish without a crash, a sanitizer report
// or a failed check (the targets abort on those).
#include <dirent.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#define DEXMILL_FUZZ_REPLAY
#include "tests/fuzz/fuzz_machine.cpp"
#include "tests/fuzz/fuzz_material.cpp"
#include "tests/fuzz/fuzz_pgm.cpp"
#include "tests/fuzz/fuzz_pipeline.cpp"
#include "tests/fuzz/fuzz_stl.cpp"
#include "tests/fuzz/fuzz_stock.cpp"
#include "tests/fuzz/fuzz_tool_table.cpp"
#include "tests/runner.h"

namespace {

// Runs every file of dir through `target`; the count, -1 without the dir.
int run_dir(const std::string& dir, int (*target)(const uint8_t*, size_t)) {
  int n = 0;
  DIR* d = opendir(dir.c_str());
  if (!d) return -1;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    std::string path = dir + "/" + e->d_name;
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) continue;
    std::vector<uint8_t> bytes;
    int c;
    while ((c = std::fgetc(f)) != EOF) bytes.push_back(static_cast<uint8_t>(c));
    std::fclose(f);
    target(bytes.data(), bytes.size());
    ++n;
  }
  closedir(d);
  return n;
}

struct Target {
  const char* name;
  int (*fn)(const uint8_t*, size_t);
};
const Target kTargets[] = {{"pipeline", fuzz_pipeline::fuzz_pipeline},
                           {"tool_table", fuzz_tool_table::fuzz_tool_table},
                           {"stl", fuzz_stl::fuzz_stl},
                           {"pgm", fuzz_pgm::fuzz_pgm},
                           {"material", fuzz_material::fuzz_material},
                           {"stock", fuzz_stock::fuzz_stock},
                           {"machine", fuzz_machine::fuzz_machine}};

}  // namespace

TEST(fuzz_regressions_and_seeds_run_clean) {
  const std::string dir = std::string(t::tests_dir()) + "/fuzz/";
  int regressions = 0;
  for (const Target& t : kTargets) {
    CHECK_GE(run_dir(dir + "seeds/" + t.name, t.fn), 3);
    // A target that has found nothing has no folder.
    regressions += std::max(run_dir(dir + "regress/" + t.name, t.fn), 0);
  }
  CHECK_GE(regressions, 2);
}
