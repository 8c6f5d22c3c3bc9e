// The embedding API's tool tables (dexmill.h dm_tool_table_parse): each
// line read by core/tool/table_row.h, as `dexmill run --tools` reads them
// (platform/format/tool_table.cpp), into the job's numbered tools.
#include "core/tool/table_row.h"
#include "display/api/dexmill.h"

using namespace dexmill;

namespace {

struct Rows {
  const dm_tool* tools;
  const uint32_t* lines;
  int32_t n;
};

// ToolRowDefined over the rows read so far (D0 ones too: a T is defined once).
uint32_t defined_on(const void* ctx, int32_t number) {
  const Rows& r = *static_cast<const Rows*>(ctx);
  for (int32_t k = 0; k < r.n; ++k)
    if (r.tools[k].number == number) return r.lines[k];
  return 0;
}

dm_tool tool_of(const ToolRow& r) {
  dm_tool d{};
  d.spec = nullptr;
  d.shape = static_cast<int32_t>(r.tool.kind);
  d.tip_angle_mdeg = r.tool.tip_angle_mdeg;
  d.diameter_nm = r.tool.diameter_nm;
  d.corner_radius_nm = r.tool.corner_radius_nm;
  d.flute_length_nm = r.tool.flute_length_nm;
  d.stick_out_nm = r.tool.stick_out_nm;
  d.shank_diameter_nm = r.tool.shank_diameter_nm;
  d.not_centre_cutting = r.tool.centre_cutting ? 0 : 1;
  d.number = r.number;
  d.length_offset_nm = r.length_offset_nm;
  return d;
}

void say(char* message, size_t bytes, const ToolRowFault* f, const char* text) {
  if (!message || !bytes) return;
  if (f) {
    (void)tool_row_message(*f, message, bytes);
    return;
  }
  size_t k = 0;
  for (; text[k] && k + 1 < bytes; ++k) message[k] = text[k];
  message[k] = '\0';
}

}  // namespace

extern "C" dm_status dm_tool_table_parse(const char* text, size_t n, int32_t inch, dm_job* job, uint32_t* line,
                                         uint32_t* col, char* message, size_t message_bytes) {
  if ((!text && n) || !job || !line || !col) return DM_E_ARGUMENT;
  *line = 0;
  *col = 0;
  say(message, message_bytes, nullptr, "");
  job->ntools = 0;
  // Every row's T (D0 ones too), for a second definition's message; the
  // tools that cut go to the job.
  dm_tool seen[2 * DM_TOOLS_MAX];
  uint32_t seen_lines[2 * DM_TOOLS_MAX];
  Rows rows{seen, seen_lines, 0};
  uint32_t at_line = 0;
  for (size_t b = 0; b < n;) {
    size_t e = b;
    while (e < n && text[e] != '\n') ++e;
    ++at_line;
    ToolRow r;
    ToolRowFault f;
    if (tool_table_row(text + b, e - b, inch != 0, defined_on, &rows, &r, &f) != ToolRowError::kOk) {
      *line = at_line;
      *col = f.col;
      say(message, message_bytes, &f, nullptr);
      job->ntools = 0;
      return DM_E_TOOL_TABLE;
    }
    b = e + 1;
    if (r.empty) continue;
    if (rows.n == 2 * DM_TOOLS_MAX || (r.tool.diameter_nm != 0 && job->ntools == DM_TOOLS_MAX)) {
      *line = at_line;
      *col = r.t_col;
      say(message, message_bytes, nullptr, "more tools than the job holds (16)");
      job->ntools = 0;
      return DM_E_TOOL_NUMBER;
    }
    seen[rows.n] = tool_of(r);
    seen_lines[rows.n++] = at_line;
    if (r.tool.diameter_nm != 0) job->tools[job->ntools++] = tool_of(r);
  }
  return DM_OK;
}
