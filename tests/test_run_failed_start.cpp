// A run that cannot start harms nothing (tools/run/run_setup.h
// remove_earlier_frames): a --window this build cannot open, a display
// that is missing, a --fbdev that is no framebuffer all exit non-zero with
// a message and leave the frames of an earlier run in --frames as they
// were; a run that starts removes them as before.
#include <sys/stat.h>

#include <string>

#include "platform/live/window.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// A --frames folder holding an earlier run's two frames.
std::string earlier_frames(const char* name) {
  const std::string d = tmp_dir() + "/" + name;
  mkdir(d.c_str(), 0755);
  write_file(d + "/frame-000001.png", "earlier run 1");
  write_file(d + "/frame-000002.ppm", "earlier run 2");
  return d;
}

bool untouched(const std::string& d) {
  return slurp(d + "/frame-000001.png") == "earlier run 1" && slurp(d + "/frame-000002.ppm") == "earlier run 2";
}

}  // namespace

TEST(run_failed_window_leaves_earlier_frames) {
  if (skip()) return;
  const std::string d = earlier_frames("fs-window");
  // No display either way: a GLFW build fails to open it (exit 3), one
  // without GLFW refuses the option before reading anything (exit 2).
  const Result r = run_command("run pocket.ngc -q --size 64x48 --frames " + d + " --window", nullptr, false,
                               "env -u DISPLAY -u WAYLAND_DISPLAY");
  if (dexmill::Window::available()) {
    CHECK_EQ(r.code, 3);
  } else {
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, "--window: this dexmill was built without GLFW"));
    CHECK_EQ(r.err.find("pocket.ngc:"), std::string::npos);  // refused before the program was read
  }
  CHECK(has(r.err, "dexmill: error: "));
  CHECK(untouched(d));
}

TEST(run_failed_fbdev_leaves_earlier_frames) {
  if (skip()) return;
  const std::string d = earlier_frames("fs-fbdev");
  Result r = run("pocket.ngc -q --size 64x48 --frames " + d + " --fbdev %/fs-no-such-device");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "cannot open the framebuffer"));
  CHECK(untouched(d));
  // A file that is there but no framebuffer (its screen info cannot be read).
  write_file(tmp_dir() + "/fs-not-a-device", std::string(4096, '\0'));
  r = run("pocket.ngc -q --size 64x48 --frames " + d + " --fbdev %/fs-not-a-device");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "not a framebuffer device"));
  CHECK(untouched(d));
  // The same folder with a run that starts: the earlier frames go.
  r = run("pocket.ngc --size 64x48 --every 100 --frames " + d);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "removed 2 frames of an earlier run"));
  CHECK(slurp(d + "/frame-000002.ppm").empty());
  CHECK_EQ(slurp(d + "/frame-000001.png").compare(1, 3, "PNG"), 0);
}

TEST(run_failed_setup_leaves_earlier_frames) {
  if (skip()) return;
  // Set-up failures after the files were checked: a design that cannot be
  // read, a grid that cannot be planned.
  const std::string d = earlier_frames("fs-setup");
  Result r = run("pocket.ngc -q --size 64x48 --frames " + d + " --design %/fs-missing.stl");
  CHECK(r.code != 0);
  CHECK(has(r.err, "fs-missing.stl"));
  CHECK(untouched(d));
  r = run("pocket.ngc -q --size 64x48 --frames " + d + " --tool flat:6 --mode stamp --pitch 0.0001");
  CHECK(r.code != 0);
  CHECK(has(r.err, "dexmill: error: "));
  CHECK(untouched(d));
}
