// The embedding API's view controls (display/api/dexmill.h): dm_view_zoom
// about a pixel keeps the point drawn there and zooming back out about it
// gives the frame before, byte for byte; an orbit keeps the zoom; bad
// arguments are statuses.
#include <cstring>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "display/api/handles.h"
#include "display/view/pick.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

constexpr int64_t kMm = DM_NM_PER_MM;
constexpr int32_t kW = 160, kH = 120;

// tests/run/pocket.ngc cut on its stock (0..33 x 0..23 x -10..0 mm at
// 0.1 mm, flat:6), with a path or none, viewed iso at kW x kH: the frame's bytes after each render.
struct Cut {
  std::vector<uint64_t> sim_mem, view_mem;
  std::vector<uint32_t> px = std::vector<uint32_t>(kW * kH);
  dm_sim* sim = nullptr;
  dm_view* view = nullptr;
  std::string text = run_cli::slurp(std::string(t::tests_dir()) + "/run/pocket.ngc");
  std::vector<uint64_t> path_mem;
  // path_segments > 0: a path of room for so many pieces, set before the cut.
  explicit Cut(uint32_t flags, uint32_t path_segments = 0) {
    dm_job j;
    CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
    const int64_t lo[3] = {0, 0, -10 * kMm}, hi[3] = {33 * kMm, 23 * kMm, 0};
    std::memcpy(j.stock.lo_nm, lo, sizeof lo);
    std::memcpy(j.stock.hi_nm, hi, sizeof hi);
    j.grid_nx = 330;  // the CLI's --grid 330x230: a 0.1 mm pitch
    j.grid_ny = 230;
    j.tool.spec = "flat:6";
    size_t n = 0, vn = 0;
    CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
    sim_mem.assign(n / 8 + 1, 0);
    CHECK_EQ(dm_create(&j, sim_mem.data(), n, &sim), DM_OK);
    CHECK_EQ(dm_view_bytes_flags(sim, kW, kH, DM_XRGB8888, flags, &vn), DM_OK);
    view_mem.assign(vn / 8 + 1, 0);
    const dm_frame f{px.data(), kW, kH, kW * 4, DM_XRGB8888};
    CHECK_EQ(dm_view_create_flags(sim, &f, nullptr, flags, view_mem.data(), vn, &view), DM_OK);
    if (path_segments) {
      path_mem.assign(dm_path_bytes(path_segments) / 8 + 1, 0);
      CHECK_EQ(dm_view_set_path(view, path_mem.data(), dm_path_bytes(path_segments)), DM_OK);
    }
    CHECK_EQ(dm_feed(sim, text.data(), text.size()), DM_OK);
    int32_t state = DM_READY;
    for (int guard = 0; guard < 1000 && (state == DM_READY || state == DM_NEED_INPUT); ++guard) {
      CHECK_EQ(dm_step(sim, nullptr, &state), DM_OK);
      if (state == DM_NEED_INPUT) CHECK_EQ(dm_end_input(sim), DM_OK);
    }
    CHECK_EQ(state, DM_DONE);
  }
  ~Cut() { dm_destroy(sim); }
  std::vector<uint32_t> frame() {
    int32_t n = 0;
    CHECK_EQ(dm_render(view, nullptr, 0, &n), DM_OK);
    return px;
  }
  dexmill::PickHit pick(int32_t x, int32_t y) const {
    return dexmill::pick_dexel(dexmill::stock_view_picture_view(view->v), sim->sim->grid(), x, y);
  }
};

void check_zoom_round_trip(uint32_t flags) {
  Cut c(flags);
  const std::vector<uint32_t> before = c.frame();
  const dexmill::PickHit at = c.pick(100, 70), corner = c.pick(60, 50);
  CHECK(at.hit && corner.hit);
  CHECK_EQ(dm_view_zoom(c.view, 5, 100, 70), DM_OK);
  const std::vector<uint32_t> in = c.frame();
  CHECK(in != before);
  // The point under the pixel stays (the dexel drawn there, or the one
  // beside it: pick's bound); one 40 px away does not.
  const dexmill::PickHit still = c.pick(100, 70), moved = c.pick(60, 50);
  CHECK(still.hit && still.i - at.i <= 1 && at.i - still.i <= 1 && still.j - at.j <= 1 && at.j - still.j <= 1);
  CHECK(moved.i != corner.i || moved.j != corner.j);
  CHECK_EQ(dm_view_zoom(c.view, -2, 100, 70), DM_OK);
  CHECK_EQ(dm_view_zoom(c.view, -3, 100, 70), DM_OK);
  CHECK(c.frame() == before);
  // Zoom about another pixel, then reset: the frame before.
  CHECK_EQ(dm_view_zoom(c.view, 7, 3, 110), DM_OK);
  CHECK(c.frame() != before);
  CHECK_EQ(dm_view_zoom_reset(c.view), DM_OK);
  CHECK(c.frame() == before);
}

}  // namespace

TEST(api_view_zoom_about_a_pixel_and_back) { check_zoom_round_trip(0); }
TEST(api_view_zoom_antialiased_about_a_pixel_and_back) { check_zoom_round_trip(DM_VIEW_ANTIALIAS); }

// An orbit keeps the zoom: the same angles zoomed, then orbited away and
// back, draw the same frame; the preset with the zoom reset is the first.
TEST(api_view_zoom_kept_by_an_orbit) {
  Cut c(0);
  const std::vector<uint32_t> plain = c.frame();
  CHECK_EQ(dm_view_zoom(c.view, 3, 20, 30), DM_OK);
  const std::vector<uint32_t> zoomed = c.frame();
  const dm_camera away{DM_VIEW_ISO, 1, -10000, 50000}, iso{DM_VIEW_ISO, 0, 0, 0};
  CHECK_EQ(dm_view_set_camera(c.view, &away), DM_OK);
  CHECK(c.frame() != zoomed);
  CHECK_EQ(dm_view_set_camera(c.view, &iso), DM_OK);
  CHECK(c.frame() == zoomed);
  CHECK_EQ(dm_view_zoom_reset(c.view), DM_OK);
  CHECK(c.frame() == plain);
}

// The limits: 60 steps in at most; past them nothing changes. Bad
// arguments: a pixel outside the frame, too many steps, no view.
TEST(api_view_zoom_limits_and_bad_arguments) {
  Cut c(0);
  CHECK_EQ(dm_view_zoom(c.view, 60, 80, 60), DM_OK);
  const std::vector<uint32_t> deepest = c.frame();
  CHECK_EQ(dm_view_zoom(c.view, 1, 80, 60), DM_OK);
  CHECK(c.frame() == deepest);
  CHECK_EQ(dm_view_zoom(c.view, 1, -1, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom(c.view, 1, 0, kH), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom(c.view, 1, kW, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom(c.view, 1001, 0, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom(c.view, -1001, 0, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom(nullptr, 1, 0, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_zoom_reset(nullptr), DM_E_ARGUMENT);
  CHECK(c.frame() == deepest);  // refused calls change nothing
}

// The path collected as the simulation cuts draws `dexmill run
// --path-overlay`'s frame, byte for byte; hidden, the frame without a path.
TEST(api_view_path_is_run_path_overlay) {
  if (run_cli::skip()) return;
  Cut with(0, 4096), without(0);
  const std::vector<uint32_t> px = with.frame();
  uint32_t n = 0, cap = 0;
  uint64_t dropped = 0;
  CHECK_EQ(dm_view_path_info(with.view, &n, &cap, &dropped), DM_OK);
  CHECK_EQ(cap, 4096u);
  CHECK_EQ(dropped, 0u);
  CHECK_GT(n, 10u);
  const run_cli::Result r = run_cli::run(
      "pocket.ngc -q --stock 0,0,-10,33,23,0 --tool flat:6 --grid 330x230 --size 160x120 --no-antialias "
      "--no-decorations --path-overlay --image %/path.ppm",
      nullptr, false);
  CHECK_EQ(r.code, 0);
  const std::vector<unsigned char> cli = run_cli::ppm_rgb(run_cli::slurp(run_cli::tmp_dir() + "/path.ppm"));
  CHECK_EQ(cli.size(), px.size() * 3);
  size_t differ = 0;
  for (size_t k = 0; k < px.size() && cli.size() == px.size() * 3; ++k)
    differ += ((px[k] >> 16) & 255) != cli[3 * k] || ((px[k] >> 8) & 255) != cli[3 * k + 1] || (px[k] & 255) != cli[3 * k + 2];
  CHECK_EQ(differ, 0u);
  CHECK(px != without.frame());
  CHECK_EQ(dm_view_show_path(with.view, 0), DM_OK);
  CHECK(with.frame() == without.frame());
}

// A path too small for the program: full, the rest dropped and counted,
// nothing written past it; bad arguments.
TEST(api_view_path_full_and_bad_arguments) {
  Cut c(0, 5);
  (void)c.frame();
  uint32_t n = 0, cap = 0;
  uint64_t dropped = 0;
  CHECK_EQ(dm_view_path_info(c.view, &n, &cap, &dropped), DM_OK);
  CHECK_EQ(n, 5u);
  CHECK_EQ(cap, 5u);
  CHECK_GT(dropped, 0u);
  CHECK_EQ(dm_path_bytes(5), 5 * sizeof(dexmill::PathSegment));
  CHECK_EQ(dm_view_set_path(c.view, reinterpret_cast<char*>(c.path_mem.data()) + 4, 64), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_set_path(nullptr, nullptr, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_path_info(c.view, nullptr, &cap, &dropped), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_show_path(nullptr, 1), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_set_path(c.view, nullptr, 0), DM_OK);  // no path
  CHECK_EQ(dm_view_path_info(c.view, &n, &cap, &dropped), DM_OK);
  CHECK_EQ(n + cap, 0u);
}

// Warnings kept with their lines and columns, their text as `dexmill
// check` prints it; the first 16 kept, all counted; bad indexes.
TEST(api_warnings_kept_with_their_text) {
  std::string text = "G21 G90\nG0 X0 Y0 Z5\n";
  for (int k = 0; k < 20; ++k) text += "$H\n";  // a Grbl command skipped: a warning each
  text += "M2\n";
  const std::string path = run_cli::write_tmp("warned.ngc", text.c_str());
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  j.stock.hi_nm[0] = j.stock.hi_nm[1] = 10 * kMm;
  j.stock.lo_nm[2] = -5 * kMm;
  j.tool.spec = "flat:3";
  size_t n = 0;
  CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
  std::vector<uint64_t> mem(n / 8 + 1);
  dm_sim* sim = nullptr;
  CHECK_EQ(dm_create(&j, mem.data(), n, &sim), DM_OK);
  CHECK_EQ(dm_feed(sim, text.data(), text.size()), DM_OK);
  int32_t state = DM_READY;
  for (int guard = 0; guard < 100 && (state == DM_READY || state == DM_NEED_INPUT); ++guard) {
    CHECK_EQ(dm_step(sim, nullptr, &state), DM_OK);
    if (state == DM_NEED_INPUT) CHECK_EQ(dm_end_input(sim), DM_OK);
  }
  const uint32_t count = dm_warning_count(sim);
  CHECK_GE(count, 17u);
  dm_input_error w{};
  CHECK_EQ(dm_warning_get(sim, 0, &w), DM_OK);
  CHECK_EQ(w.line, 3u);
  CHECK_EQ(w.col, 1u);
  char msg[256];
  CHECK_GT(dm_warning_message(sim, 0, msg, sizeof msg), 0u);
  const run_cli::Result r = run_cli::run_command("check " + path);
  CHECK(run_cli::has(r.err, (path + ":3:1: warning: " + msg).c_str()));
  CHECK_EQ(dm_warning_get(sim, 15, &w), DM_OK);
  CHECK_EQ(w.line, 18u);
  CHECK_EQ(dm_warning_get(sim, 16, &w), DM_E_INDEX);
  CHECK_EQ(dm_warning_message(sim, 16, msg, sizeof msg), 0u);
  CHECK_EQ(dm_warning_get(sim, 0, nullptr), DM_E_ARGUMENT);
  CHECK_EQ(dm_warning_count(nullptr), 0u);
  dm_destroy(sim);
}
