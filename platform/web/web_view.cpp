// web_view.cpp - the page's view controls and findings over the C API
// (display/api/dexmill.h): the zoom about a pixel, the toolpath overlay in
// the arena behind the job (sized by the page before the cut), the safety
// checks, the warnings, the findings and a marker at one of them.
#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"

using namespace dexmill::web;

namespace {
dm_finding g_finding;        // the finding web_finding read last
dm_input_error g_warning;    // the warning web_warning read last
char g_warning_text[256];    // and its message, NUL terminated
}  // namespace

WEB_EXPORT(web_zoom) int32_t web_zoom(int32_t steps, int32_t x_px, int32_t y_px) {
  return dm_view_zoom(g.view, steps, x_px, y_px);
}
WEB_EXPORT(web_zoom_reset) int32_t web_zoom_reset() { return dm_view_zoom_reset(g.view); }

// Room for `segments` pieces of the toolpath behind the job's memory, the
// arena grown now (before the cut: nothing grows while cutting); 0: none.
WEB_EXPORT(web_path) int32_t web_path(int32_t segments) {
  if (segments < 0) return DM_E_ARGUMENT;
  if (!g.view) return DM_E_STATE;
  const size_t bytes = dm_path_bytes(static_cast<uint32_t>(segments));
  char* mem = static_cast<char*>(arena_reserve(g.arena_used + bytes));
  if (!mem) return DM_E_MEMORY;
  const dm_status s = dm_view_set_path(g.view, segments ? mem + g.arena_used : nullptr, bytes);
  if (s == DM_OK) g.arena_used += round8(bytes);
  return s;
}
WEB_EXPORT(web_path_show) int32_t web_path_show(int32_t on) { return dm_view_show_path(g.view, on); }
// The pieces held and dropped (once full), for the status line.
WEB_EXPORT(web_path_count) uint32_t web_path_count() {
  uint32_t n = 0, cap = 0;
  uint64_t dropped = 0;
  return dm_view_path_info(g.view, &n, &cap, &dropped) == DM_OK ? n : 0;
}
WEB_EXPORT(web_path_dropped) uint64_t web_path_dropped() {
  uint32_t n = 0, cap = 0;
  uint64_t dropped = 0;
  return dm_view_path_info(g.view, &n, &cap, &dropped) == DM_OK ? dropped : 0;
}

// The safety checks (DM_CHECK_* bits, the CLI's --check), before web_create.
WEB_EXPORT(web_set_checks) int32_t web_set_checks(uint32_t checks) {
  if (checks & ~static_cast<uint32_t>(DM_CHECK_ALL)) return DM_E_ARGUMENT;
  g.job.checks = checks;
  return DM_OK;
}

// Findings: how many are kept; finding k read into place (its status),
// then its fields.
WEB_EXPORT(web_finding_count) uint32_t web_finding_count() { return dm_finding_count(g.sim); }
WEB_EXPORT(web_finding) int32_t web_finding(uint32_t k) { return dm_finding_get(g.sim, k, &g_finding); }
WEB_EXPORT(web_finding_kind) int32_t web_finding_kind() { return g_finding.kind; }
WEB_EXPORT(web_finding_line) uint32_t web_finding_line() { return g_finding.line; }
WEB_EXPORT(web_finding_last_line) uint32_t web_finding_last_line() { return g_finding.last_line; }
WEB_EXPORT(web_finding_at_nm) int64_t web_finding_at_nm(int32_t axis) {
  return axis >= 0 && axis < 3 ? g_finding.at_nm[axis] : 0;
}
WEB_EXPORT(web_finding_depth_nm) int64_t web_finding_depth_nm() { return g_finding.depth_nm; }
WEB_EXPORT(web_finding_name) const char* web_finding_name(int32_t kind) { return dm_finding_name(kind); }
// A marker at finding k's place (k < 0: none); drawn by the next render.
WEB_EXPORT(web_mark_finding) int32_t web_mark_finding(int32_t k) {
  if (k < 0) return dm_view_set_mark(g.view, nullptr);
  dm_finding f{};
  if (const dm_status s = dm_finding_get(g.sim, static_cast<uint32_t>(k), &f)) return s;
  return dm_view_set_mark(g.view, f.at_nm);
}

// Warning k kept: its message's length (0 past the kept ones), the line,
// column and text (NUL terminated) read after it.
WEB_EXPORT(web_warning) int32_t web_warning(uint32_t k) {
  g_warning = dm_input_error{};
  g_warning_text[0] = '\0';
  if (dm_warning_get(g.sim, k, &g_warning) != DM_OK) return 0;
  return static_cast<int32_t>(dm_warning_message(g.sim, k, g_warning_text, sizeof g_warning_text));
}
WEB_EXPORT(web_warning_line) uint32_t web_warning_line() { return g_warning.line; }
WEB_EXPORT(web_warning_col) uint32_t web_warning_col() { return g_warning.col; }
WEB_EXPORT(web_warning_text) const char* web_warning_text() { return g_warning_text; }
