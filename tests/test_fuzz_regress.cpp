// The fuzz target's inputs that once failed (tests/fuzz/regress/) and its
// seed corpus, run through the same pipeline in every `make test`: each must
// finish without a crash, a sanitizer report or an abort.
#include <dirent.h>

#include <cstdio>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_pipeline.cpp"
#include "tests/runner.h"

namespace {

int run_dir(const std::string& dir) {
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
    // Each input twice: as written and with the render bit set.
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    if (!bytes.empty()) bytes[0] = static_cast<uint8_t>(bytes[0] | 0x80);
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    ++n;
  }
  closedir(d);
  return n;
}

}  // namespace

TEST(fuzz_regressions_and_seeds_run_clean) {
  CHECK_GE(run_dir(std::string(t::tests_dir()) + "/fuzz/regress"), 1);
  CHECK_GE(run_dir(std::string(t::tests_dir()) + "/fuzz/seeds"), 5);
}
