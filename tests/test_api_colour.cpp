// The embedding API's colour modes (display/api/dexmill.h dm_view_set_colour):
// for each mode the API's frame is `dexmill run --color MODE --image`'s,
// byte for byte, its legend included (display/view/colour_legend.h, the
// one code both draw with); modes the job cannot draw and bad arguments are
// statuses; a mode's memory is what it asked for, and plain again is the
// plain frame.
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

constexpr int64_t mm = DM_NM_PER_MM;
constexpr int32_t kW = 320, kH = 240;

std::string program(const char* name) { return slurp(std::string(t::tests_dir()) + "/run/" + name); }

// pocket.ngc's stock and grid (0..33 x 0..23 x -10..0 mm, 330 x 230 dexels), flat:6.
dm_job base_job() {
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  const int64_t lo[3] = {0, 0, -10 * mm}, hi[3] = {33 * mm, 23 * mm, 0};
  for (int a = 0; a < 3; ++a) {
    j.stock.lo_nm[a] = lo[a];
    j.stock.hi_nm[a] = hi[a];
  }
  j.grid_nx = 330;
  j.grid_ny = 230;
  j.tool.spec = "flat:6";
  return j;
}
const char* kCliBase = " --stock 0,0,-10,33,23,0 --grid 330x230 --tool flat:6 --size 320x240 -q";

// A simulation and an anti-aliased view with decorations, as `dexmill run
// --image` draws.
struct Run {
  std::vector<uint64_t> sim_mem, view_mem, colour_mem;
  std::vector<uint32_t> px;
  dm_sim* sim = nullptr;
  dm_view* view = nullptr;
  explicit Run(const dm_job& j) : px(static_cast<size_t>(kW) * kH, 0) {
    size_t n = 0;
    CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
    sim_mem.assign(n / 8 + 1, 0);
    CHECK_EQ(dm_create(&j, sim_mem.data(), n, &sim), DM_OK);
    const dm_frame f{px.data(), kW, kH, kW * 4, DM_XRGB8888};
    CHECK_EQ(dm_view_bytes_flags(sim, kW, kH, DM_XRGB8888, DM_VIEW_ANTIALIAS, &n), DM_OK);
    view_mem.assign(n / 8 + 1, 0);
    CHECK_EQ(dm_view_create_flags(sim, &f, nullptr, DM_VIEW_ANTIALIAS, view_mem.data(), n, &view), DM_OK);
    CHECK_EQ(dm_view_set_decorations(view, 1), DM_OK);
  }
  ~Run() {
    dm_view_destroy(view);
    dm_destroy(sim);
  }
  dm_status colour(int32_t mode, int64_t thin_nm = 0) {
    dm_colour c{mode, 0, thin_nm};
    size_t n = 0;
    if (const dm_status s = dm_view_colour_bytes(view, &c, &n)) return s;
    colour_mem.assign(n / 8 + 1, 0);
    return dm_view_set_colour(view, &c, n ? colour_mem.data() : nullptr, n);
  }
  void cut(const std::string& text) {
    int32_t state = DM_READY;
    bool fed = false, ended = false;
    for (int guard = 0; guard < 1000000; ++guard) {
      CHECK_EQ(dm_step(sim, nullptr, &state), DM_OK);
      if (state != DM_NEED_INPUT) {
        if (state != DM_READY) break;
        continue;
      }
      if (!fed) CHECK_EQ(dm_feed(sim, text.data(), text.size()), DM_OK);
      else if (!ended) CHECK_EQ(dm_end_input(sim), DM_OK);
      ended = fed;
      fed = true;
    }
    CHECK_EQ(state, DM_DONE);
  }
  // The frame as RGB bytes, after a render.
  std::vector<unsigned char> rgb() {
    int32_t nr = 0;
    CHECK_EQ(dm_render(view, nullptr, 0, &nr), DM_OK);
    std::vector<unsigned char> out;
    for (uint32_t p : px) {
      out.push_back(static_cast<unsigned char>(p >> 16));
      out.push_back(static_cast<unsigned char>(p >> 8));
      out.push_back(static_cast<unsigned char>(p));
    }
    return out;
  }
};

// The pixels where the API's frame and the CLI's image of `name` with the
// options differ: how many, and the box around them.
struct Diff {
  int pixels = -1;
  int x0 = kW, y0 = kH, x1 = -1, y1 = -1;
};
Diff diff_cli(const std::vector<unsigned char>& api, const char* name, const std::string& options) {
  Diff d;
  const std::string ppm = tmp_dir() + "/api_colour.ppm";
  const Result r = run(std::string(name) + kCliBase + " " + options + " --image " + ppm);
  CHECK_EQ(r.code, 0);
  const Image im = read_ppm(ppm);
  CHECK_EQ(im.w, kW);
  CHECK_EQ(im.h, kH);
  if (im.rgb.size() != api.size()) return d;
  d.pixels = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t k = (static_cast<size_t>(y) * kW + x) * 3;
      if (std::memcmp(&im.rgb[k], &api[k], 3) == 0) continue;
      ++d.pixels;
      d.x0 = std::min(d.x0, x);
      d.y0 = std::min(d.y0, y);
      d.x1 = std::max(d.x1, x);
      d.y1 = std::max(d.y1, y);
    }
  std::printf("  %s %s: %d pixels differ", name, options.c_str(), d.pixels);
  if (d.pixels > 0) std::printf(" in x %d..%d, y %d..%d", d.x0, d.x1, d.y0, d.y1);
  std::printf("\n");
  return d;
}
bool same_as_cli(const std::vector<unsigned char>& api, const char* name, const std::string& options) {
  return diff_cli(api, name, options).pixels == 0;
}

// tests/run/NAME's facets as the API's triangles (dm_design_from_stl).
std::vector<dm_triangle> design_triangles(const char* name) {
  const std::string bytes = slurp(std::string(t::tests_dir()) + "/run/" + name);
  uint32_t n = 0;
  CHECK_EQ(dm_design_from_stl(bytes.data(), bytes.size(), nullptr, 0, &n), DM_OK);
  std::vector<dm_triangle> out(n);
  CHECK_EQ(dm_design_from_stl(bytes.data(), bytes.size(), out.data(), n, &n), DM_OK);
  CHECK_EQ(out.size(), n);
  return out;
}

}  // namespace

TEST(api_colour_slope_is_the_cli_image) {
  if (skip()) return;
  Run a(base_job());
  CHECK_EQ(a.colour(DM_COLOUR_SLOPE), DM_OK);
  a.cut(program("pocket.ngc"));
  CHECK(same_as_cli(a.rgb(), "pocket.ngc", "--color slope"));
}

TEST(api_colour_tool_is_the_cli_image) {
  if (skip()) return;
  {  // no tool table: every T is the job's tool, named by it
    dm_job j = base_job();
    j.provenance = 1;
    Run a(j);
    CHECK_EQ(a.colour(DM_COLOUR_TOOL), DM_OK);
    a.cut(program("tool_change.ngc"));
    CHECK(same_as_cli(a.rgb(), "tool_change.ngc", "--color tool"));
  }
  {  // numbered tools, as a table gives them
    dm_job j = base_job();
    j.provenance = 1;
    j.tools[0].spec = "flat:4";
    j.tools[0].number = 1;
    j.tools[1].spec = "ball:6";
    j.tools[1].number = 2;
    j.ntools = 2;
    Run a(j);
    CHECK_EQ(a.colour(DM_COLOUR_TOOL), DM_OK);
    a.cut(program("tool_change.ngc"));
    const std::string table = write_tmp("api_colour.tbl", "T1 P1 D4 ;flat:4\nT2 P2 D6 ;ball:6\n");
    CHECK(same_as_cli(a.rgb(), "tool_change.ngc", "--color tool --tools " + table));
  }
}

TEST(api_colour_material_is_the_cli_image) {
  if (skip()) return;
  const char* presets[] = {"wood", "wood-on-aluminium", "marble"};
  for (const char* p : presets) {
    dm_job j = base_job();
    j.material = p;
    Run a(j);
    CHECK_EQ(a.colour(DM_COLOUR_MATERIAL), DM_OK);
    a.cut(program("pocket.ngc"));
    CHECK(same_as_cli(a.rgb(), "pocket.ngc", std::string("--color material --material ") + p));
  }
}

TEST(api_colour_thin_is_the_cli_image) {
  if (skip()) return;
  dm_job j = base_job();
  Run a(j);
  CHECK_EQ(a.colour(DM_COLOUR_THIN, 8 * mm), DM_OK);  // the pocket's floor, 7 mm thick, under 8
  a.cut(program("pocket.ngc"));
  CHECK(same_as_cli(a.rgb(), "pocket.ngc", "--color thin --thin 8"));
  CHECK_EQ(a.colour(DM_COLOUR_THIN), DM_OK);  // 0: the CLI's 1 mm
  CHECK(same_as_cli(a.rgb(), "pocket.ngc", "--color thin"));
}

// A design under the whole cut (tests/run/pocket_floor.stl: a plane from
// 8.9 mm down at x = -1 to 8.06 at x = 34, the pocket's floor 8 deep: no
// gouge, the bands of material left), and pocket_design.stl, which the
// pocket gouges: the gouge's red disc is drawn as the CLI draws it
// (display/api/run_marks.h), byte for byte too.
TEST(api_colour_error_is_the_cli_image) {
  if (skip()) return;
  {
    const std::vector<dm_triangle> plane = design_triangles("pocket_floor.stl");
    CHECK_EQ(plane.size(), 2u);
    CHECK_EQ(plane[0].v_nm[1][2], -8060000);  // to the nm
    dm_job j = base_job();
    j.design = plane.data();
    j.ndesign = static_cast<uint32_t>(plane.size());
    Run a(j);
    CHECK_EQ(a.colour(DM_COLOUR_ERROR), DM_OK);
    a.cut(program("pocket.ngc"));
    CHECK(same_as_cli(a.rgb(), "pocket.ngc", "--color error --design pocket_floor.stl"));
  }
  const std::vector<dm_triangle> tris = design_triangles("pocket_design.stl");
  dm_job j = base_job();
  j.design = tris.data();
  j.ndesign = static_cast<uint32_t>(tris.size());
  Run a(j);
  CHECK_EQ(a.colour(DM_COLOUR_ERROR), DM_OK);
  a.cut(program("pocket.ngc"));
  CHECK(same_as_cli(a.rgb(), "pocket.ngc", "--color error --design pocket_design.stl"));
  // The run found the gouge, so there is a mark to match.
  CHECK_GT(dm_finding_count(a.sim), 0u);
}

// Plain again is the plain frame; a mode the job lacks what it needs for
// is DM_E_COLOUR; unknown modes, thin limits out of range, short or
// misaligned memory and dead handles are refused.
TEST(api_colour_refusals_and_plain_again) {
  Run plain(base_job());
  plain.cut(program("pocket.ngc"));
  const std::vector<unsigned char> want = plain.rgb();
  Run a(base_job());
  CHECK_EQ(a.colour(DM_COLOUR_SLOPE), DM_OK);
  a.cut(program("pocket.ngc"));
  CHECK(a.rgb() != want);
  CHECK_EQ(dm_view_set_colour(a.view, nullptr, nullptr, 0), DM_OK);
  CHECK(a.rgb() == want);
  CHECK_EQ(a.colour(DM_COLOUR_PLAIN), DM_OK);
  CHECK(a.rgb() == want);
  size_t n = 1;
  dm_colour c{DM_COLOUR_PLAIN, 0, 0};
  CHECK_EQ(dm_view_colour_bytes(a.view, &c, &n), DM_OK);
  CHECK_EQ(n, 0u);
  CHECK_EQ(a.colour(DM_COLOUR_TOOL), DM_E_COLOUR);      // no provenance
  CHECK_EQ(a.colour(DM_COLOUR_MATERIAL), DM_E_COLOUR);  // no material
  CHECK_EQ(a.colour(DM_COLOUR_ERROR), DM_E_COLOUR);     // no design
  CHECK_EQ(a.colour(6), DM_E_ARGUMENT);
  CHECK_EQ(a.colour(-1), DM_E_ARGUMENT);
  CHECK_EQ(a.colour(DM_COLOUR_THIN, 999), DM_E_ARGUMENT);
  CHECK_EQ(a.colour(DM_COLOUR_THIN, 1000 * mm + 1), DM_E_ARGUMENT);
  CHECK_EQ(a.colour(DM_COLOUR_THIN, -1), DM_E_ARGUMENT);
  c = dm_colour{DM_COLOUR_SLOPE, 1, 0};
  CHECK_EQ(dm_view_colour_bytes(a.view, &c, &n), DM_E_ARGUMENT);  // reserved not 0
  c = dm_colour{DM_COLOUR_SLOPE, 0, 0};
  CHECK_EQ(dm_view_colour_bytes(a.view, &c, &n), DM_OK);
  std::printf("  slope's memory for 330 x 230 dexels: %zu bytes\n", n);
  CHECK_GT(n, static_cast<size_t>(332 * 232));
  std::vector<uint64_t> mem(n / 8 + 2, 0);
  CHECK_EQ(dm_view_set_colour(a.view, &c, mem.data(), n - 1), DM_E_MEMORY);
  CHECK_EQ(dm_view_set_colour(a.view, &c, nullptr, n), DM_E_MEMORY);
  CHECK_EQ(dm_view_set_colour(a.view, &c, reinterpret_cast<char*>(mem.data()) + 4, n), DM_E_MEMORY);
  CHECK(a.rgb() == want);  // refused: still plain
  CHECK_EQ(dm_view_colour_bytes(nullptr, &c, &n), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_colour_bytes(a.view, &c, nullptr), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_set_colour(nullptr, &c, mem.data(), n), DM_E_ARGUMENT);
  CHECK_EQ(dm_struct_bytes(DM_STRUCT_COLOUR), sizeof(dm_colour));
  uint32_t count = 9;
  dm_triangle one;
  CHECK_EQ(dm_design_from_stl("solid a\nendsolid a\n", 20, nullptr, 0, &count), DM_E_DESIGN);
  CHECK_EQ(count, 0u);
  CHECK_EQ(dm_design_from_stl("not an stl", 10, nullptr, 0, &count), DM_E_DESIGN);
  CHECK_EQ(dm_design_from_stl(nullptr, 0, nullptr, 0, &count), DM_E_DESIGN);
  CHECK_EQ(dm_design_from_stl(nullptr, 5, nullptr, 0, &count), DM_E_ARGUMENT);
  CHECK_EQ(dm_design_from_stl("x", 1, nullptr, 0, nullptr), DM_E_ARGUMENT);
  const std::string two = slurp(std::string(t::tests_dir()) + "/run/pocket_design.stl");
  CHECK_EQ(dm_design_from_stl(two.data(), two.size(), &one, 1, &count), DM_E_INDEX);
  CHECK_GT(count, 1u);
  int32_t presets = 0;
  while (dm_material_preset_name(presets)) ++presets;
  CHECK_EQ(presets, 7);
  CHECK(dm_material_preset_name(-1) == nullptr);
  CHECK_EQ(std::string(dm_material_preset_name(2)), "wood");
  CHECK(std::strlen(dm_status_message(DM_E_COLOUR)) > 10);
  dm_destroy(a.sim);
  CHECK_EQ(dm_view_set_colour(a.view, &c, mem.data(), n), DM_E_STATE);
  CHECK_EQ(dm_view_colour_bytes(a.view, &c, &n), DM_E_STATE);
  a.sim = nullptr;
}
