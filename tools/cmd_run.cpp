// `dexmill run`: for now the built-in demo only: a block cut by a roughing
// pocket and a ball-end relief pass, written as a 16-bit PGM height image.
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "core/config.h"
#include "core/cutter.h"
#include "core/grid.h"
#include "core/stamp.h"
#include "core/tool.h"
#include "platform/pgm.h"
#include "tools/cli.h"

namespace dexmill {
namespace cli {
namespace {

constexpr int64_t mm(int64_t v) { return v * kNmPerMm; }

struct Demo {
  DexelGrid<height_t> grid;
  std::vector<height_t> top, bottom;
  CutStats stats;
};

bool make_cutter(const Tool& t, const DexelGrid<height_t>& g, std::vector<int32_t>* words, CutterDexels* c) {
  ToolProfile p = tool_profile(t);
  words->resize(cutter_storage_words(cutter_reach_dex(p, g.pitch_nm)));
  return ok(cutter_build(p, g.pitch_nm, g.lsb_nm, words->data(), words->size(), c));
}

// Zig-zag over [x0, x1] x [y0, y1] at depth z(x) given by `relief`.
template <class Relief>
void zigzag(Demo* d, const CutterDexels& c, int64_t x0, int64_t x1, int64_t y0, int64_t y1, int64_t step,
            Relief relief) {
  bool forward = true;
  for (int64_t y = y0; y <= y1; y += step) {
    const int64_t xa = forward ? x0 : x1, xb = forward ? x1 : x0;
    const int64_t n = 40;
    for (int64_t k = 0; k < n; ++k) {
      int64_t xs = xa + (xb - xa) * k / n, xe = xa + (xb - xa) * (k + 1) / n;
      stamp_line(&d->grid, c, PointNm{xs, y, relief(xs, y)}, PointNm{xe, y, relief(xe, y)}, &d->stats);
    }
    forward = !forward;
  }
}

int run_demo(const char* heightmap_path) {
  Demo d;
  const int64_t pitch = mm(1) / 4;
  GridGeometry geo{};
  geo.nx = 60 * 4 + 2;
  geo.ny = 40 * 4 + 2;
  geo.x0_nm = -pitch / 2;
  geo.y0_nm = -pitch / 2;
  geo.pitch_nm = pitch;
  geo.z0_nm = 0;
  geo.lsb_nm = lsb_for_range(mm(25), DEXMILL_HEIGHT_BITS);
  d.top.resize(static_cast<size_t>(geo.nx) * geo.ny);
  d.bottom.resize(d.top.size());
  if (!ok(grid_init(&d.grid, geo, d.top.data(), d.bottom.data(), d.top.size())))
    return fail(kExitUsage, "demo grid rejected");
  grid_block_stock(&d.grid, grid_height_of_z(d.grid, mm(20)));

  Tool flat{ToolKind::kFlat, mm(6), 0, 0, mm(20), mm(40)};
  Tool ball{ToolKind::kBall, mm(6), 0, 0, mm(20), mm(40)};
  std::vector<int32_t> wf, wb;
  CutterDexels cf, cb;
  if (!make_cutter(flat, d.grid, &wf, &cf) || !make_cutter(ball, d.grid, &wb, &cb))
    return fail(kExitUsage, "demo cutters rejected");
  // Roughing: a pocket 6 mm deep, 5 mm stepover.
  zigzag(&d, cf, mm(8), mm(52), mm(8), mm(32), mm(5), [](int64_t, int64_t) { return mm(14); });
  // Finishing: a ball-end bowl, 9 mm deep at its centre, 1 mm stepover.
  zigzag(&d, cb, mm(8), mm(52), mm(8), mm(32), mm(1), [](int64_t x, int64_t y) {
    const int64_t dx_um = (x - mm(30)) / 1000, dy_um = (y - mm(20)) / 1000;
    const int64_t r2_um2 = dx_um * dx_um + dy_um * dy_um;
    return min_of<int64_t>(mm(14), mm(11) + r2_um2 / 60);
  });
  // A through hole.
  stamp_line(&d.grid, cf, PointNm{mm(52), mm(32), mm(25)}, PointNm{mm(52), mm(32), -mm(1)}, &d.stats);

  mkdir("out", 0777);
  std::vector<uint16_t> img(d.top.size());
  for (int32_t j = 0; j < d.grid.ny; ++j)
    for (int32_t i = 0; i < d.grid.nx; ++i)
      img[static_cast<size_t>(d.grid.ny - 1 - j) * d.grid.nx + i] = static_cast<uint16_t>(d.top[d.grid.index(i, j)]);
  char err[512];
  if (!write_pgm16(heightmap_path, d.grid.nx, d.grid.ny, img.data(), err, sizeof err)) return fail(kExitIo, "%s", err);
  std::printf("demo: %dx%d dexels, %llu instances, %llu dexel updates; wrote %s\n", d.grid.nx, d.grid.ny,
              static_cast<unsigned long long>(d.stats.instances),
              static_cast<unsigned long long>(d.stats.dexel_updates), heightmap_path);
  return kExitOk;
}

}  // namespace

int cmd_run(int argc, char** argv) {
  const char* heightmap = "out/heightmap.pgm";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--heightmap") && i + 1 < argc) {
      heightmap = argv[++i];
    } else {
      return fail(kExitUsage, "unknown option '%s'", argv[i]);
    }
  }
  return run_demo(heightmap);
}

}  // namespace cli
}  // namespace dexmill
