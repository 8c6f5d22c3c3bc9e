// The embedding API: its messages, names and version (dexmill.h).
#include "core/safety/material_limits.h"
#include "core/safety/safety.h"
#include "core/math/decimal.h"
#include "display/api/dexmill.h"

using namespace dexmill;

extern "C" {

const char* dm_status_message(dm_status s) {
  switch (s) {
    case DM_OK: return "ok";
    case DM_E_ARGUMENT: return "a null pointer or handle, or a value outside its range";
    case DM_E_VERSION: return "the job was not set up by dm_job_init of this library's API version";
    case DM_E_MEMORY: return "the memory is null, not 8-byte aligned, or smaller than its query said";
    case DM_E_STOCK: return "the stock box is empty on an axis or lies more than 1 km from the origin";
    case DM_E_GRID:
      return "the grid cannot be made: under 4 x 4 dexels, over 65535 a side or 64 M dexels, or out of range";
    case DM_E_TOOL_SPEC: return "a tool's spec text does not parse (ball:D, flat:D, bull:D:R, vbit:D:ANGLE, options)";
    case DM_E_TOOL: return "a tool is out of range, or cannot cut this grid in this mode";
    case DM_E_TOOL_NUMBER: return "a library tool's number is negative or used twice, or there are too many tools";
    case DM_E_FIXTURES: return "too many fixtures, or they hold no column of the stock's lattice";
    case DM_E_MATERIAL: return "not the name of a material preset";
    case DM_E_DESIGN: return "the design lies beyond 1.07 m of the grid's corner, or not over the stock";
    case DM_E_STATE: return "not now: input after its end, or a view of a destroyed simulation";
    case DM_E_BUSY: return "the text fed before is not taken yet";
    case DM_E_LINE: return "the line is longer than DM_LINE_MAX bytes";
    case DM_E_OUTSIDE: return "the point is outside the grid, or its column holds no material";
    case DM_E_FRAME: return "the frame cannot be drawn into (size, stride or pixel format)";
    case DM_E_INDEX: return "past the end of the list";
    case DM_E_IO: return "the file could not be written";
    case DM_E_TOOL_TABLE: return "a line of the tool table does not read";
    case DM_E_COLOUR: return "the job cannot draw this colour mode (tool: no provenance; material: none; error: no design)";
    default: return "unknown status";
  }
}

uint32_t dm_version(void) { return DEXMILL_API_VERSION; }

const char* dm_finding_name(int32_t kind) {
  if (kind == DM_FIND_GOUGE) return "gouge";
  if (kind >= DM_FIND_RAPID && kind <= DM_FIND_PLUNGE) return safety_kind_name(static_cast<SafetyKind>(kind - DM_FIND_RAPID));
  if (kind >= DM_FIND_FEED && kind <= DM_FIND_COOLANT) return process_rule_name(static_cast<ProcessRule>(kind - DM_FIND_FEED));
  return "unknown";
}

dm_status dm_mm_to_nm(const char* text, size_t n, int64_t* nm) {
  if (!text || !nm) return DM_E_ARGUMENT;
  size_t pos = 0;
  Decimal d;
  if (decimal_parse(text, n, &pos, &d) != DecimalParse::kOk) return DM_E_ARGUMENT;
  while (pos < n && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
  if (pos != n) return DM_E_ARGUMENT;
  *nm = decimal_to_nm(d, false);
  return DM_OK;
}

size_t dm_struct_bytes(int32_t which) {
  switch (which) {
    case DM_STRUCT_JOB: return sizeof(dm_job);
    case DM_STRUCT_SCAN_RESULT: return sizeof(dm_scan_result);
    case DM_STRUCT_SCAN_TOOL: return sizeof(dm_scan_tool);
    case DM_STRUCT_TOOL: return sizeof(dm_tool);
    case DM_STRUCT_BOX: return sizeof(dm_box);
    case DM_STRUCT_TRIANGLE: return sizeof(dm_triangle);
    case DM_STRUCT_BUDGET: return sizeof(dm_budget);
    case DM_STRUCT_PROGRESS: return sizeof(dm_progress);
    case DM_STRUCT_GRID_INFO: return sizeof(dm_grid_info);
    case DM_STRUCT_COLUMN: return sizeof(dm_column);
    case DM_STRUCT_FINDING: return sizeof(dm_finding);
    case DM_STRUCT_INPUT_ERROR: return sizeof(dm_input_error);
    case DM_STRUCT_FRAME: return sizeof(dm_frame);
    case DM_STRUCT_CAMERA: return sizeof(dm_camera);
    case DM_STRUCT_RECT: return sizeof(dm_rect);
    case DM_STRUCT_COLOUR: return sizeof(dm_colour);
    default: return 0;
  }
}

}  // extern "C"
