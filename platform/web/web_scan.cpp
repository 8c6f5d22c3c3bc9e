// web_scan.cpp - the first pass's exports (display/api/dexmill.h dm_scan_*):
// the program read once before the job, for the stock and pitch `dexmill
// run FILE` chooses when it is given neither (platform/web/page_scan.js),
// and the job's --pitch. The scan lives in the arena behind the job there
// is (the page may still show it); the next job takes the arena back, so
// a scan is ended once its result is read, and one left unfinished (a new
// job made meanwhile: dexmill.js's generation) is forgotten, never touched.
#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"
#include "platform/web/web_tools.h"

#include <string.h>

using namespace dexmill::web;

namespace {

dm_job g_scan_job;
dm_scan* g_scan = nullptr;
dm_scan_result g_result;
char g_scan_tool[DM_LINE_MAX + 1];  // the scan job's tool spec, NUL terminated

}  // namespace

// A scan with the tool whose spec (the CLI's --tool text) is web_text()[0, n),
// and the tool table's tools when `table` is non-zero (web_tools.cpp).
WEB_EXPORT(web_scan_begin) int32_t web_scan_begin(int32_t n, int32_t table) {
  g_scan = nullptr;  // its memory may be a job's now
  if (n < 0 || n > DM_LINE_MAX) return DM_E_ARGUMENT;
  memcpy(g_scan_tool, g_text, static_cast<size_t>(n));
  g_scan_tool[n] = '\0';
  if (const dm_status s = dm_job_init(&g_scan_job, DEXMILL_API_VERSION)) return s;
  g_scan_job.tool.spec = g_scan_tool;
  if (table) table_to_job(&g_scan_job);
  size_t bytes = 0;
  if (const dm_status s = dm_scan_bytes(&g_scan_job, &bytes)) return s;
  const size_t at = round8(g.arena_used);
  char* base = static_cast<char*>(arena_reserve(at + bytes));
  if (!base) return DM_E_MEMORY;
  return dm_scan_create(&g_scan_job, base + at, bytes, &g_scan);
}

// Program text: web_text()[0, n), lent until the next step says DM_NEED_INPUT.
WEB_EXPORT(web_scan_feed) int32_t web_scan_feed(int32_t n) {
  if (n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  return dm_scan_feed(g_scan, g_text, static_cast<size_t>(n));
}
WEB_EXPORT(web_scan_end_input) int32_t web_scan_end_input() { return dm_scan_end_input(g_scan); }

// One step of at most `lines` lines: the state (DM_READY, DM_NEED_INPUT,
// DM_DONE, DM_IO_ERROR), or minus a status.
WEB_EXPORT(web_scan_step) int32_t web_scan_step(int32_t lines) {
  dm_budget budget{};
  budget.lines = lines > 0 ? static_cast<uint32_t>(lines) : 0;
  int32_t state = DM_READY;
  if (const dm_status s = dm_scan_step(g_scan, &budget, &state)) return -s;
  return state;
}

// The stock given (the form's --stock), value k (0..2 lo x, y, z; 3..5
// hi) from web_text()[0, n): mm text; none given: the scan's.
WEB_EXPORT(web_scan_set_stock) int32_t web_scan_set_stock(int32_t k, int32_t n) {
  if (k < 0 || k > 5 || n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  int64_t* v = k < 3 ? &g_scan_job.stock.lo_nm[k] : &g_scan_job.stock.hi_nm[k - 3];
  return dm_mm_to_nm(g_text, static_cast<size_t>(n), v);
}

// What the scan found (read field by field below), the scan ended: the
// job's stock (as given, or the scan's) and its pitch (dm_scan_apply);
// a status (DM_E_GRID: a stock no grid holds, the rest filled).
WEB_EXPORT(web_scan_result) int32_t web_scan_result() {
  dm_status s = dm_scan_get_result(g_scan, &g_result);
  if (s == DM_OK || s == DM_E_GRID) {
    const dm_status a = dm_scan_apply(g_scan, &g_scan_job);
    if (a != DM_OK) s = a;
  }
  dm_scan_destroy(g_scan);
  g_scan = nullptr;
  return s;
}
// The job's stock value k (0..2 lo x, y, z; 3..5 hi), nm.
WEB_EXPORT(web_scan_stock_nm) int64_t web_scan_stock_nm(int32_t k) {
  if (k < 0 || k > 5) return 0;
  return k < 3 ? g_scan_job.stock.lo_nm[k] : g_scan_job.stock.hi_nm[k - 3];
}
WEB_EXPORT(web_scan_stock_from) int32_t web_scan_stock_from() { return g_result.stock_from; }
WEB_EXPORT(web_scan_pitch_nm) int64_t web_scan_pitch_nm() { return g_scan_job.pitch_nm; }
// The default stock's grid at the default pitch, dexels (not a given stock's).
WEB_EXPORT(web_scan_grid_nx) int32_t web_scan_grid_nx() { return g_result.grid_nx; }
WEB_EXPORT(web_scan_grid_ny) int32_t web_scan_grid_ny() { return g_result.grid_ny; }
WEB_EXPORT(web_scan_units) int32_t web_scan_units() { return g_result.units; }
WEB_EXPORT(web_scan_lines) uint32_t web_scan_lines() { return g_result.lines; }
WEB_EXPORT(web_scan_moves) uint64_t web_scan_moves() { return g_result.rapids + g_result.feeds + g_result.arcs; }
WEB_EXPORT(web_scan_tools) int32_t web_scan_tools() { return g_result.ntools; }
WEB_EXPORT(web_scan_table_units) int32_t web_scan_table_units() { return g_result.table_units; }
// The M6 of a T the job's tools lack (0: none), and that T.
WEB_EXPORT(web_scan_bad_tool_line) uint32_t web_scan_bad_tool_line() { return g_result.bad_tool_line; }

// The job's pitch (the CLI's --pitch MM) from web_text()[0, n): mm text;
// set after web_set_grid, before web_create (platform/web/dexmill.js).
WEB_EXPORT(web_set_pitch) int32_t web_set_pitch(int32_t n) {
  if (n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  int64_t pitch_nm = 0;
  if (const dm_status s = dm_mm_to_nm(g_text, static_cast<size_t>(n), &pitch_nm)) return s;
  if (pitch_nm <= 0) return DM_E_GRID;
  g.job.pitch_nm = pitch_nm;
  g.job.grid_nx = 0;
  g.job.grid_ny = 0;
  return DM_OK;
}
