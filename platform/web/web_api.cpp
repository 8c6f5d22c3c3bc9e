// web_api.cpp - what dexmill.wasm exports to the page (platform/web/dexmill.js):
// one job at a time over the C API (display/api/dexmill.h), its memory the
// arena of web_arena.h, its picture an XRGB8888 frame in linear memory the
// page copies into a canvas. The page passes numbers as int32 and text
// through web_text()'s buffer (the job's values, then the program's pieces),
// so nothing but integers crosses the boundary. No heap, no import: the
// module needs nothing from the page.
#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"

#include <string.h>

using namespace dexmill::web;

namespace dexmill {
namespace web {
alignas(8) char g_text[kTextBytes];
WebJob g;
}  // namespace web
}  // namespace dexmill

namespace {

char g_tool[DM_LINE_MAX + 1];  // the tool's spec, NUL terminated: dm_job.tool.spec
char g_message[256];           // the last message asked for

void end_job() {
  dm_view_destroy(g.view);
  dm_destroy(g.sim);
  g.view = nullptr;
  g.sim = nullptr;
  g.arena_used = 0;
}

}  // namespace

WEB_EXPORT(web_text) char* web_text() { return g_text; }
WEB_EXPORT(web_text_bytes) int32_t web_text_bytes() { return static_cast<int32_t>(kTextBytes); }
WEB_EXPORT(web_memory_bytes) int32_t web_memory_bytes() { return static_cast<int32_t>(dexmill::web::arena_memory_bytes()); }

// A new job, every field the API's default; the last one ended.
WEB_EXPORT(web_job) int32_t web_job() {
  end_job();
  return dm_job_init(&g.job, DEXMILL_API_VERSION);
}

// Stock value k (0..2 lo x, y, z; 3..5 hi) from web_text()[0, n): mm text.
WEB_EXPORT(web_set_stock) int32_t web_set_stock(int32_t k, int32_t n) {
  if (k < 0 || k > 5 || n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  int64_t* v = k < 3 ? &g.job.stock.lo_nm[k] : &g.job.stock.hi_nm[k - 3];
  return dm_mm_to_nm(g_text, static_cast<size_t>(n), v);
}

// The tool's spec (the CLI's --tool text) from web_text()[0, n).
WEB_EXPORT(web_set_tool) int32_t web_set_tool(int32_t n) {
  if (n < 0 || n > DM_LINE_MAX) return DM_E_ARGUMENT;
  memcpy(g_tool, g_text, static_cast<size_t>(n));
  g_tool[n] = '\0';
  g.job.tool.spec = g_tool;
  return DM_OK;
}

// The grid as the CLI's --grid NXxNY (0 x 0: the API's default).
WEB_EXPORT(web_set_grid) int32_t web_set_grid(int32_t nx, int32_t ny) {
  g.job.grid_nx = nx;
  g.job.grid_ny = ny;
  return DM_OK;
}

// The simulation and a w x h view of it (camera a DM_VIEW_* preset; flags
// DM_VIEW_ANTIALIAS or 0; decorations the CLI's triad and scale bar), all
// in the arena, grown to their size now: nothing grows while cutting.
WEB_EXPORT(web_create) int32_t web_create(int32_t w, int32_t h, int32_t preset, int32_t flags, int32_t decorations) {
  end_job();
  size_t sim_bytes = 0, view_bytes = 0;
  if (const dm_status s = dm_required_bytes(&g.job, &sim_bytes)) return s;
  if (w < 1 || h < 1 || w > DM_FRAME_MAX_SIDE || h > DM_FRAME_MAX_SIDE) return DM_E_FRAME;
  const size_t frame_bytes = static_cast<size_t>(w) * static_cast<size_t>(h) * 4;
  // The view's size needs the simulation: sized after it, in the same arena.
  char* mem = static_cast<char*>(dexmill::web::arena_reserve(round8(sim_bytes) + round8(frame_bytes)));
  if (!mem) return DM_E_MEMORY;
  if (const dm_status s = dm_create(&g.job, mem, sim_bytes, &g.sim)) return s;
  if (const dm_status s =
          dm_view_bytes_flags(g.sim, w, h, DM_XRGB8888, static_cast<uint32_t>(flags), &view_bytes)) return s;
  // Growing moves nothing: the arena's start stays, the simulation in it too.
  if (!dexmill::web::arena_reserve(round8(sim_bytes) + round8(frame_bytes) + view_bytes)) return DM_E_MEMORY;
  char* pixels = mem + round8(sim_bytes);
  g.frame = dm_frame{pixels, w, h, w * 4, DM_XRGB8888};
  const dm_camera camera{preset, 0, 0, 0};
  if (const dm_status s = dm_view_create_flags(g.sim, &g.frame, &camera, static_cast<uint32_t>(flags),
                                               pixels + round8(frame_bytes), view_bytes, &g.view)) return s;
  g.arena_used = round8(sim_bytes) + round8(frame_bytes) + round8(view_bytes);
  return dm_view_set_decorations(g.view, decorations);
}

// The camera: a DM_VIEW_* preset, or (angles non-zero) the eye's azimuth
// around +z from +x and elevation, in millidegrees (the page's orbit); the
// next web_render draws the whole frame.
WEB_EXPORT(web_set_camera) int32_t web_set_camera(int32_t preset, int32_t angles, int32_t azimuth_mdeg,
                                                  int32_t elevation_mdeg) {
  const dm_camera camera{preset, angles, azimuth_mdeg, elevation_mdeg};
  return dm_view_set_camera(g.view, &camera);
}

// Program text: web_text()[0, n), lent until web_input_taken() is 1.
WEB_EXPORT(web_feed) int32_t web_feed(int32_t n) {
  if (n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  return dm_feed(g.sim, g_text, static_cast<size_t>(n));
}
WEB_EXPORT(web_input_taken) int32_t web_input_taken() { return dm_input_taken(g.sim); }
WEB_EXPORT(web_end_input) int32_t web_end_input() { return dm_end_input(g.sim); }

// One step of at most `moves` motion records (0: no limit): the state
// (DM_READY, DM_NEED_INPUT, ...), or minus a status.
WEB_EXPORT(web_step) int32_t web_step(int32_t moves) {
  dm_budget budget{};
  budget.moves = moves > 0 ? static_cast<uint64_t>(moves) : 0;
  int32_t state = DM_READY;
  if (const dm_status s = dm_step(g.sim, &budget, &state)) return -s;
  return state;
}

// Draws what changed: the rectangles' count, or minus a status.
WEB_EXPORT(web_render) int32_t web_render() {
  int32_t n = 0;
  if (const dm_status s = dm_render(g.view, nullptr, 0, &n)) return -s;
  return n;
}
WEB_EXPORT(web_pixels) void* web_pixels() { return g.frame.pixels; }

// The progress now, read field by field (web_progress_get) after this.
WEB_EXPORT(web_progress) int32_t web_progress() { return dm_get_progress(g.sim, &g.progress); }
WEB_EXPORT(web_state) int32_t web_state() { return g.progress.state; }
WEB_EXPORT(web_stop_reason) int32_t web_stop_reason() { return g.progress.stop_reason; }
WEB_EXPORT(web_line) uint32_t web_line() { return g.progress.line; }
WEB_EXPORT(web_lines_read) uint32_t web_lines_read() { return g.progress.lines_read; }
WEB_EXPORT(web_moves) uint64_t web_moves() { return g.progress.moves; }
WEB_EXPORT(web_errors) uint32_t web_errors() { return g.progress.errors; }
WEB_EXPORT(web_warnings) uint32_t web_warnings() { return g.progress.warnings; }
WEB_EXPORT(web_removed_um3) uint64_t web_removed_um3() { return g.progress.removed_um3; }
WEB_EXPORT(web_machine_time_us) int64_t web_machine_time_us() { return g.progress.machine_time_us; }

// Input error k: its line and column, and its message (NUL terminated) at
// web_message(); the message's length, 0 past the kept errors.
WEB_EXPORT(web_error_line) uint32_t web_error_line(uint32_t k) {
  dm_input_error e{};
  return dm_error_get(g.sim, k, &e) == DM_OK ? e.line : 0;
}
WEB_EXPORT(web_error_col) uint32_t web_error_col(uint32_t k) {
  dm_input_error e{};
  return dm_error_get(g.sim, k, &e) == DM_OK ? e.col : 0;
}
WEB_EXPORT(web_error_message) int32_t web_error_message(uint32_t k) {
  return static_cast<int32_t>(dm_error_message(g.sim, k, g_message, sizeof g_message));
}
WEB_EXPORT(web_message) const char* web_message() { return g_message; }

// A status's sentence (NUL terminated) for the page's status line.
WEB_EXPORT(web_status_message) const char* web_status_message(int32_t s) { return dm_status_message(s); }
