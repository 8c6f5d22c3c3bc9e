// The verification sheet of `dexmill run --sheet FILE.html`: one
// self-contained HTML page, A4, one or two pages in print, drawn from the
// run's report (platform/report/run_report.h) and the pictures the run
// rendered for it (tools/run/run_sheet.cpp). It computes nothing the
// report does not hold: its figures are the report's JSON text
// (platform/report/report_json.h), its verdict the report's
// (platform/report/verdict.h). No network: pictures are data: URIs (PNG,
// base64), charts inline SVG, no script, no external style or font.
//
// Sections, top to bottom: the verdict line; the part (iso, top and error
// views); the program(s) and setups; the tools with their stick-out and
// lines; the time estimate in total and by tool; the design's assessment
// (figures, histogram of cut - design, the worst gouges with FILE:LINE and a
// crop of each place); collisions, travel, rule and load findings; the load
// plot when engagement was measured. The files: sheet_html.cpp (the page
// and its style), sheet_sections.cpp (the tables), sheet_charts.cpp (the SVG
// charts), sheet_text.cpp (escaping, base64, numbers).
#ifndef DEXMILL_PLATFORM_REPORT_SHEET_HTML_H
#define DEXMILL_PLATFORM_REPORT_SHEET_HTML_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "platform/report/run_report.h"

namespace dexmill {

// The worst gouges the sheet shows, each with a crop.
constexpr size_t kSheetWorstGouges = 6;

// A picture for the sheet: PNG bytes (empty: not drawn) and its caption.
struct SheetPicture {
  std::vector<uint8_t> png;
  std::string caption;
};

struct SheetImages {
  SheetPicture iso, top, error;  // error: only with a design
  // A crop around each of sheet_worst_gouges(), in that order.
  std::vector<SheetPicture> crops;
  // The load plot (platform/report/load_plot.h) as SVG, when engagement
  // was measured (empty: none).
  std::string load_plot_svg;
};

// The indices into r.assessment.gouges of the deepest kSheetWorstGouges,
// deepest first (equal depths: the earlier line first).
std::vector<size_t> sheet_worst_gouges(const ReportAssessment& a);

// The page.
std::string sheet_html_text(const RunReport& r, const SheetImages& im);

namespace sheet_detail {  // what the files of the sheet share, not for callers

// HTML text: & < > " ' escaped; control characters and bytes that are not
// UTF-8 become '?' (platform/report/load_plot.h markup_escape, the SVG's).
std::string html(const std::string& s);
// RFC 4648 base64 of the bytes.
std::string base64(const std::vector<uint8_t>& bytes);
// An <img> of PNG bytes as a data: URI, with its alt text.
std::string img_png(const std::vector<uint8_t>& png, const std::string& alt, const char* css_class);
// Microseconds as "12.345 s" (and, with `clock`, "(3 min 25 s)" past a minute).
std::string seconds_text(int64_t us, bool clock = true);
// The sections (sheet_sections.cpp).
std::string part_section(const RunReport& r, const SheetImages& im);
std::string program_section(const RunReport& r);
std::string tools_section(const RunReport& r);
std::string time_section(const RunReport& r);
std::string assessment_section(const RunReport& r, const SheetImages& im);
std::string findings_section(const RunReport& r);
std::string load_section(const RunReport& r, const SheetImages& im);
// The charts (sheet_charts.cpp): the histogram of d, and the time by tool
// as bars.
std::string histogram_svg(const AssessResult& a);
std::string time_bars_svg(const RunReport& r);

}  // namespace sheet_detail
}  // namespace dexmill

#endif
