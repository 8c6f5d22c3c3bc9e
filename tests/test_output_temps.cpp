// Output temporaries (platform/os/temp_file.h): a name that fits whatever the
// output's length (a 255-byte name used to fail with "File name too long",
// its temporary being NAME.tmp-PID), and a clean-up that removes only what no
// live process holds (it used to judge by the PID alone, and deleted a live
// run's temporary when that run was in another PID namespace).
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "platform/os/output_file.h"
#include "platform/os/temp_file.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

std::string fresh_dir(const char* name) {
  const std::string d = tmp_dir() + "/temps-" + name;
  std::system(("rm -rf '" + d + "' && mkdir -p '" + d + "'").c_str());
  return d;
}

bool exists(const std::string& path) {
  struct stat st;
  return lstat(path.c_str(), &st) == 0;
}

// An empty file at path, held under an exclusive flock while the returned
// descriptor is open: what a live run's temporary looks like.
int held_file(const std::string& path) {
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0 && flock(fd, LOCK_EX) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

TEST(locked_temp_is_removed_only_once_released) {
  const std::string d = fresh_dir("unit");
  dexmill::LockedTemp t;
  CHECK(dexmill::make_locked_temp(d, ".dexmill-tmp-", 0644, &t));
  CHECK_EQ(t.path.size(), d.size() + 1 + 13 + 8);
  CHECK(exists(t.path));
  CHECK_EQ(dexmill::remove_stale_temps(d, ".dexmill-tmp-"), 0);  // held: this very process is its owner
  CHECK(exists(t.path));
  dexmill::release_locked_temp(&t);
  CHECK_EQ(dexmill::remove_stale_temps(d, ".dexmill-tmp-"), 1);
  CHECK(!exists(t.path));
  // Other names of the folder are never touched, nor a link of that form.
  const std::string other = d + "/.dexmill-tmp-notours", link = d + "/.dexmill-tmp-ABCDEFGH";
  std::FILE* f = std::fopen(other.c_str(), "wb");
  if (f) std::fclose(f);
  CHECK_EQ(symlink(other.c_str(), link.c_str()), 0);
  CHECK_EQ(dexmill::remove_stale_temps(d, ".dexmill-tmp-"), 0);
  CHECK(exists(other));
  CHECK(exists(link));
}

TEST(output_with_a_255_byte_name_is_written) {
  if (skip()) return;
  const std::string d = fresh_dir("long");
  for (size_t len : {247u, 251u, 255u}) {
    const std::string name = std::string(len - 4, 'n') + ".png";
    const Result r = run("pocket.ngc -q --size 32x24 --image '" + d + "/" + name + "'");
    CHECK_EQ(r.code, 0);
    if (r.code) std::printf("  %zu bytes: %s\n", len, r.err.c_str());
    CHECK(exists(d + "/" + name));
  }
  CHECK_EQ(count_names(d, "tmp"), 0);
}

TEST(output_cleanup_leaves_a_live_runs_temporary) {
  if (skip()) return;
  const std::string d = fresh_dir("live");
  // A stale temporary (its run was killed: nobody holds it), a live run's
  // (held), and a live run's in the former NAME.tmp-PID form whose PID is
  // no process here (another PID namespace's run).
  const std::string stale = d + "/.dexmill-tmp-Stale123", live = d + "/.dexmill-tmp-Live1234";
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  const std::string foreign = d + "/r.json.tmp-" + std::to_string(static_cast<long>(child));
  std::FILE* f = std::fopen(stale.c_str(), "wb");
  if (f) std::fclose(f);
  const int live_fd = held_file(live), foreign_fd = held_file(foreign);
  CHECK(live_fd >= 0);
  CHECK(foreign_fd >= 0);
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/r.json").code, 0);
  CHECK(!exists(stale));
  CHECK(exists(live));
  CHECK(exists(foreign));
  CHECK(has(slurp(d + "/r.json"), "\"dexmill_report\": 1"));
  if (live_fd >= 0) close(live_fd);
  if (foreign_fd >= 0) close(foreign_fd);
  unlink(live.c_str());
  unlink(foreign.c_str());
}
