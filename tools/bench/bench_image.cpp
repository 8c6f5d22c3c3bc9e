// `dexmill bench png-heightmap`: the heightmap of a realistic cut grid
// (scale-4k, tools/bench/workloads.h: a 4096² relief finish and spiral
// pocket, swept) encoded as PGM and as PNG (platform/format/), in memory
// (pgm_s, png_s) and written to a file in $TMPDIR as `dexmill run
// --heightmap` writes it (pgm_file_s, png_file_s; the file is removed).
// The PNG on the host's threads (threads), png_1thread_s on one (speedup:
// png_1thread_s / png_s; same_bytes=1 when both wrote the same file).
// seconds is png_s; ratio is png_s / pgm_s, file_ratio png_file_s / pgm_file_s; compression
// is pgm_bytes / png_bytes; size_vs_before is png_bytes over
// png_bytes_before, the size this heightmap's PNG had when heightmaps were
// compressed with three-byte hash chains of 128 (DeflateTuning::kGeneral,
// platform/format/deflate.h), so a change of the encoder shows whether the
// ratio got worse.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "platform/format/heightmap.h"
#include "platform/format/image_file.h"
#include "platform/format/pgm.h"
#include "platform/format/png.h"
#include "platform/os/parallel.h"
#include "tools/bench/bench.h"
#include "tools/bench/bench_job.h"

namespace dexmill {
namespace {

// scale-4k's heightmap as a PNG with three-byte chains of 128 (2.6 s then).
constexpr size_t kPngBytesBefore = 8811886;

// The scale-4k job swept as bench scale-4k sweeps it, its heightmap into img.
bool cut_heightmap(const char* name, Job* j, std::vector<uint16_t>* img) {
  if (!setup(name, "scale-4k", j)) return false;
  CutStats st;
  sweep_moves(j, 1, j->w.path.size(), &st);
  img->resize(static_cast<size_t>(j->g.nx) * static_cast<size_t>(j->g.ny));
  heightmap_samples(j->g, img->data());
  return true;
}

// The fastest of writing the image as `path` in `format`, in seconds; a
// negative time when the file cannot be written.
double best_file_s(const std::string& path, ImageFormat format, const Job& j, const std::vector<uint16_t>& img,
                   double min_s) {
  bool ok = true;
  const double s = bench::best_time_s([&] {
    char err[256];
    const double t0 = bench::now_s();
    ok = ok && write_grey16_image(path.c_str(), format, j.g.nx, j.g.ny, img.data(), err, sizeof err);
    return bench::now_s() - t0;
  }, min_s);
  std::remove(path.c_str());
  return ok ? s : -1;
}

void run_png_heightmap(const char* name) {
  Job j;
  std::vector<uint16_t> img;
  if (!cut_heightmap(name, &j, &img)) return;
  std::vector<uint8_t> pgm, png;
  const double min_s = bench::single_run() ? 0.0 : 1.0;
  const double pgm_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    pgm16_encode(j.g.nx, j.g.ny, img.data(), &pgm);
    return bench::now_s() - t0;
  }, min_s);
  const double png_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    png_encode_gray16(img.data(), j.g.nx, j.g.ny, &png);
    return bench::now_s() - t0;
  }, min_s);
  std::vector<uint8_t> png_1t;
  const double png_1t_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    png_encode_gray16(img.data(), j.g.nx, j.g.ny, &png_1t, 1);
    return bench::now_s() - t0;
  }, min_s);
  const char* tmp = std::getenv("TMPDIR");
  const std::string base = std::string(tmp && *tmp ? tmp : "/tmp") + "/dexmill-bench-heightmap";
  const double pgm_file_s = best_file_s(base + ".pgm", ImageFormat::kPgm, j, img, min_s);
  const double png_file_s = best_file_s(base + ".png", ImageFormat::kPng, j, img, min_s);
  bench::result(name, "grid=%dx%d threads=%d pgm_s=%.4f png_s=%.4f ratio=%.2f png_1thread_s=%.4f speedup=%.2f "
                "same_bytes=%d pgm_file_s=%.4f png_file_s=%.4f file_ratio=%.2f pgm_bytes=%zu png_bytes=%zu "
                "compression=%.2f png_bytes_before=%zu size_vs_before=%.4f seconds=%.4f",
                j.g.nx, j.g.ny, host_threads(), pgm_s, png_s, png_s / pgm_s, png_1t_s, png_1t_s / png_s,
                png_1t == png ? 1 : 0, pgm_file_s, png_file_s, png_file_s / pgm_file_s, pgm.size(), png.size(),
                static_cast<double>(pgm.size()) / static_cast<double>(png.size()), kPngBytesBefore,
                static_cast<double>(png.size()) / static_cast<double>(kPngBytesBefore), png_s);
}

}  // namespace
}  // namespace dexmill

BENCH(png_heightmap, "png-heightmap", dexmill::run_png_heightmap);
