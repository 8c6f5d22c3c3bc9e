// web_tools.cpp - the tool table's exports (display/api/dexmill.h
// dm_tool_table_parse): a LinuxCNC table read in the module for the first
// pass (web_scan.cpp) and the job (web_set_tools, between web_job and
// web_create: platform/web/dexmill.js's configure).
#include "display/api/dexmill.h"
#include "platform/web/web_job.h"
#include "platform/web/web_tools.h"

namespace {

dm_job g_table;  // its tools[0, ntools): the table read (none: ntools 0)
uint32_t g_line = 0, g_col = 0;
char g_table_message[256];

}  // namespace

namespace dexmill {
namespace web {

void table_to_job(dm_job* job) {
  for (int32_t k = 0; k < g_table.ntools; ++k) job->tools[k] = g_table.tools[k];
  job->ntools = g_table.ntools;
}

}  // namespace web
}  // namespace dexmill

using namespace dexmill::web;

// The table's text, web_text()[0, n), lengths in inch when inch is non-zero
// (the scan's web_scan_table_units): a status; DM_E_TOOL_TABLE or
// DM_E_TOOL_NUMBER with web_tools_line/col/message. n 0: no table.
WEB_EXPORT(web_tools_parse) int32_t web_tools_parse(int32_t n, int32_t inch) {
  if (n < 0 || static_cast<size_t>(n) > kTextBytes) return DM_E_ARGUMENT;
  return dm_tool_table_parse(g_text, static_cast<size_t>(n), inch, &g_table, &g_line, &g_col, g_table_message,
                             sizeof g_table_message);
}
WEB_EXPORT(web_tools_line) uint32_t web_tools_line() { return g_line; }
WEB_EXPORT(web_tools_col) uint32_t web_tools_col() { return g_col; }
WEB_EXPORT(web_tools_message) const char* web_tools_message() { return g_table_message; }
WEB_EXPORT(web_tools_count) int32_t web_tools_count() { return g_table.ntools; }

// The table's tools into the job being set up (the CLI's --tools).
WEB_EXPORT(web_set_tools) int32_t web_set_tools() {
  table_to_job(&g.job);
  return DM_OK;
}
