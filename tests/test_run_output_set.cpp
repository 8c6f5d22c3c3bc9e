// A run's files are published together (platform/os/output_set.h):
// each is written to its temporary, the report last, and all are renamed in
// one pass at the end. A signal in the writing phase used to leave the new
// image beside the old heightmap, STL and report; now it leaves the old set
// whole. The report names the run and lists the files with their sizes.
#include <sys/stat.h>

#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

std::string fresh_dir(const std::string& name) {
  const std::string d = tmp_dir() + "/set-" + name;
  std::system(("rm -rf '" + d + "' && mkdir -p '" + d + "'").c_str());
  return d;
}

long long file_size(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? static_cast<long long>(st.st_size) : -1;
}

}  // namespace

TEST(run_signal_while_writing_leaves_the_old_set_whole) {
  if (skip()) return;
  // The image in a folder of its own: once a temporary shows in the other
  // folder, the image is complete (and was already renamed, before).
  const std::string a = fresh_dir("image"), b = fresh_dir("rest");
  const std::string outs = " --image " + a + "/a.png --heightmap " + b + "/h.png --stl " + b + "/s.stl --report " + b + "/r.json";
  CHECK_EQ(run("tool_change.ngc -q --size 64x48" + outs).code, 0);
  const uint64_t old_image = file_hash(a + "/a.png"), old_height = file_hash(b + "/h.png"),
                 old_stl = file_hash(b + "/s.stl"), old_report = file_hash(b + "/r.json");
  const Result r = run_shell("{bin} run pocket.ngc -q --size 64x48 --grid 2048x2048" + outs +
                             " & pid=$!; n=0; until ls -A '" + b + "' | grep -q tmp; do sleep 0.005; n=$((n+1)); "
                             "[ $n -gt 6000 ] && break; done; kill -TERM $pid; wait $pid");
  CHECK_EQ(r.code, 143);  // stopped while writing, not done before the signal came
  CHECK_EQ(file_hash(a + "/a.png"), old_image);
  CHECK_EQ(file_hash(b + "/h.png"), old_height);
  CHECK_EQ(file_hash(b + "/s.stl"), old_stl);
  CHECK_EQ(file_hash(b + "/r.json"), old_report);
  CHECK_EQ(count_names(a, "tmp"), 0);
  CHECK_EQ(count_names(b, "tmp"), 0);
}

TEST(run_report_names_the_run_and_lists_its_files) {
  if (skip()) return;
  const std::string d = fresh_dir("listed");
  CHECK_EQ(run("pocket.ngc -q --size 64x48 --every 50 --frames " + d + "/fr --image " + d + "/a.png --heightmap " + d +
               "/h.pgm --stl " + d + "/s.stl --report " + d + "/r.json")
               .code,
           0);
  const std::string rep = slurp(d + "/r.json");
  CHECK(has(rep, "  \"run\": {\"started\": \"20"));
  CHECK(has(rep, "Z\", \"pid\": "));
  CHECK(has(rep, ("{\"option\": \"--frames\", \"folder\": \"" + d + "/fr\", \"files\": ").c_str()));
  for (const char* f : {"a.png", "h.pgm", "s.stl"}) {
    const std::string path = d + "/" + f;
    CHECK(file_size(path) > 0);
    CHECK(has(rep, ("\"file\": \"" + path + "\", \"bytes\": " + std::to_string(file_size(path)) + "}").c_str()));
  }
  CHECK_EQ(count_names(d, "tmp"), 0);
}
