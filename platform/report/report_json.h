// The JSON report of `dexmill run --report FILE.json`: the writer of a
// run's result (platform/report/run_report.h). Keys always come in
// the order below; lengths are millimetres with 4 decimals, volumes mm^3
// with 3, simulated times seconds with 3, all printed from integers (the
// same bytes on every machine). Only `timing` (wall-clock seconds per stage)
// and `run` differ between two runs of the same job, and they come last.
//
//   dexmill_report  1 (the format's version)
//   program         file, lines (blocks run: a loop's or subroutine's lines each
//                   time they run; the summary says "blocks run"), units (what its moves were written in:
//                   mm|inch|mixed; a program with no move: the units it started in),
//                   moves {rapid, feed, arc, dwell, tool_change}
//   status          "ok", or "error" when the program has an input error
//   stopped         null, or {reason, line}: "gouge" where --stop-at stopped the
//                   cut, "error" at the bad block a partial run stopped before
//   errors          [{line, column, message}]          input errors
//   warnings        [{line, column, message}], warnings_total (all, also those past 100 kept);
//                   a warning that came more than once is one entry (the first
//                   100 distinct are kept) with "count" and "last_line" after
//                   its message; warnings_total counts every one
//   messages        [{line, kind, text}]: the program's DEBUG, PRINT and MSG comments
//                   (kind "debug"|"print"|"message"; the first 100)
//   stock           {min_mm [x,y,z], max_mm [x,y,z], source "option"|"program"|"demo"}
//   grid            {nx, ny, pitch_mm, lsb_mm, height_bits}
//   mode            "sweep"|"stamp"
//   tool            {default, table (file or null), used [{number, spec, source,
//                   line, form}]}: each T loaded (number null: the tool before
//                   any M6, listed when it cut), where its tool comes from
//                   ("option" --tool, "table" --tools, "comment" of the program
//                   at line in form, "default" a guess), line and form null
//                   unless a comment
//   removed_mm3     material removed: (sum of dexel heights before - after) x lsb x pitch^2
//   estimated_time_s  feeds at F, rapids at rapid_mm_per_min, dwells added,
//                     no acceleration unless --accel; time_model holds the parts
//   time_model      {rapid_mm_per_min, accel_mm_per_s2 (null: none), feed_s, rapid_s, dwell_s}
//   bounds_mm       {min [x,y,z], max [x,y,z]} of all motion (null: none)
//   cut             {instances, dexel_updates}
//   assessment      null without --design; else (paper §2.5; d = cut top -
//                   design top, > 0 material left, < 0 a gouge):
//                   design {file, kind "stl"|"pgm", triangles, columns},
//                   tolerance_mm, tolerance_boxes, E_mm2 (sum d^2 x pitch^0:
//                   eq. 2, mm^2 with 6 decimals), E_rel (E / sum of design
//                   tops above the stock bottom, eq. 3, mm, 9 decimals),
//                   rms_mm, max_gouge and max_leftover ({mm, x_mm, y_mm}
//                   or null), gouged and leftover ({area_mm2, volume_mm3}
//                   beyond tolerance), within_tolerance_percent (of the
//                   design's columns), outside_design ({area_mm2,
//                   volume_mm3}: material where the design has none), and
//                   histogram {edges_mm [14], columns [15]} of d,
//                   gouges [{line, x_mm, y_mm, depth_mm, design_z_mm,
//                   cut_z_mm, tool_mm [x,y,z], columns}] (one per line that
//                   first took a column below its tolerance; the first 64),
//                   gouges_total
//   collisions      null without safety checks (--check, --table); else
//                   {total, rapid_removed_mm3, list [{kind "rapid"|
//                   "spindle_stopped"|"below_stock"|"table", line, x_mm,
//                   y_mm, z_mm, depth_mm, volume_mm3, message}]} (the first
//                   64 kept; total counts all)
//   tool_use        [{number (null: the tool before any M6), stick_out_mm,
//                   first_line, last_line}] per tool of tool.used: its
//                   stick-out and the lines it cut on, the M6 that first
//                   loaded it to its last feed or arc move (null: it cut
//                   nothing); the sheet's tool table (--sheet)
//   verdict         {pass, errors, gouges, collisions, travel, rules, load,
//                   stopped}: the counts of findings by kind from the totals
//                   above (platform/report/verdict.h), pass when all are 0
//                   and the run was not stopped; the sheet's top line
//   timing          {STAGE_s: seconds, ...}
//   run             {started (UTC), pid, outputs [{option, file, bytes} or
//                   {option "--frames", folder, files}]}: the run that wrote
//                   the report and the other files it wrote; the report is
//                   renamed into place after them, so a report that is
//                   there names the run every listed file is from
#ifndef DEXMILL_PLATFORM_REPORT_REPORT_JSON_H
#define DEXMILL_PLATFORM_REPORT_REPORT_JSON_H

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/safety/safety.h"
#include "platform/report/run_report.h"

namespace dexmill {

// One safety event as text: "rapid into material: 0.123 mm3 removed, 0.400
// mm deep at X.. Y.. Z.." (the warning's message, the report's "message").
std::string safety_event_text(const SafetyEvent& e, int64_t lsb_nm, int64_t pitch_nm);

// The report as text.
std::string report_json_text(const RunReport& r);
// Writes it atomically; false with a message on failure.
bool write_report_json(const char* path, const RunReport& r, char* err, std::size_t errn);

// The assessment's figures as `assessment` writes them (empty: null), for
// the sheet (platform/report/sheet_html.h), which shows the same text.
struct AssessmentTexts {
  std::string e_mm2, e_rel, rms_mm, max_gouge_mm, max_leftover_mm;
  std::string gouged_area_mm2, gouged_volume_mm3, leftover_area_mm2, leftover_volume_mm3;
  std::string within_percent, outside_area_mm2, outside_volume_mm3;
};
AssessmentTexts assessment_texts(const RunReport& r);

// Microseconds as seconds with 3 decimals, rounded to nearest (negative: 0).
std::string seconds_of_us(int64_t us);
// removed_lsb x lsb x pitch^2 in mm^3 with 3 decimals, exactly rounded.
std::string volume_mm3_text(uint64_t removed_lsb, int64_t lsb_nm, int64_t pitch_nm);
// nm as mm with `decimals` (<= 6) decimals, rounded to nearest.
std::string nm_to_mm_text(int64_t nm, int decimals);

}  // namespace dexmill

#endif
