// A benchmark's job; see bench_job.h.
#include "tools/bench/bench_job.h"

#include <algorithm>
#include <cstdio>

namespace dexmill {
namespace {

bool prepare(const char* name, Job* j) {
  if (!make_workload(name, &j->w)) return false;
  const size_t n = static_cast<size_t>(j->w.geo.nx) * j->w.geo.ny;
  j->top.assign(n, 0);
  j->bottom.assign(n, 0);
  if (!ok(grid_init(&j->g, j->w.geo, j->top.data(), j->bottom.data(), n))) return false;
  grid_block_stock(&j->g, grid_height_of_z(j->g, j->w.stock_top_nm));
  j->stock = j->top;
  ToolProfile p = tool_profile(j->w.tool);
  j->cutter_words.resize(cutter_storage_words(cutter_reach_dex(p, j->g.pitch_nm)));
  if (!ok(cutter_build(p, j->g.pitch_nm, j->g.lsb_nm, j->cutter_words.data(), j->cutter_words.size(), &j->cutter)))
    return false;
  return ok(sweep_tool_prepare(p, j->g.lsb_nm, &j->sweep_tool));
}

}  // namespace

bool setup(const char* bench, const char* name, Job* j) {
  if (prepare(name, j)) return true;
  std::fprintf(stderr, "dexmill: error: bench %s: set-up failed\n", bench);
  return false;
}

void sweep_moves(Job* j, size_t from, size_t to, CutStats* st) {
  const std::vector<PointNm>& path = j->w.path;
  SweepChain chain;
  for (size_t k = from; k < to; ++k) sweep_chain_line(&j->g, j->sweep_tool, path[k - 1], path[k], st, &chain);
  sweep_chain_end(&j->g, j->sweep_tool, st, &chain);
}

void reset(Job* j) {
  j->top = j->stock;
  std::fill(j->bottom.begin(), j->bottom.end(), 0);
  j->g.dirty = GridRect::none();
}

}  // namespace dexmill
