// `dexmill measure STOCK --distance X0,Y0,X1,Y1 [--csv FILE] [--svg FILE]`
// (tools/CLI.md): the section along a segment (core/measure/section.h) as
// CSV, one row a sample, and as a chart.
#include <cstdio>
#include <string>
#include <vector>

#include "core/math/fixed.h"
#include "core/math/wide.h"
#include "core/measure/section.h"
#include "platform/os/output_file.h"
#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"

namespace dexmill {
namespace cli {

namespace {

// At most this many samples: a 65535-column diagonal is 92682 pitches.
constexpr int32_t kSectionMaxSteps = 100000;

double to_mm(int64_t nm) { return static_cast<double>(nm) / 1e6; }

int write_text(const std::string& path, const std::string& text, const char* what) {
  if (path.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return kExitOk;
  }
  char err[1400];
  if (!write_output(path.c_str(), text.data(), text.size(), err, sizeof err)) return fail(kExitIo, "%s: %s", what, err);
  return kExitOk;
}

}  // namespace

int measure_section(const MeasuredStock& s, const int64_t seg_nm[4], const std::string& csv_path,
                    const std::string& svg_path) {
  const DexelGrid<height_t>& g = s.grid;
  const SectionSegment seg = section_segment(seg_nm[0], seg_nm[1], seg_nm[2], seg_nm[3], g.pitch_nm, kSectionMaxSteps);
  std::string csv = "along_mm,x_mm,y_mm,column_x_mm,column_y_mm,material,top_mm,bottom_mm,design_mm,line\n";
  std::vector<SectionChartPoint> chart;
  for (int32_t k = 0; k <= seg.steps; ++k) {
    const SectionSample p = section_sample(g, seg, k, s.line_layer(), s.program_layer(), s.design_layer());
    if (!p.at.on_grid)
      return fail(kExitUsage, "--distance: X%s Y%s is off the stock's grid", measure_mm(p.x_nm, 3).c_str(),
                  measure_mm(p.y_nm, 3).c_str());
    csv += measure_mm(p.along_nm, 4) + "," + measure_mm(p.x_nm, 4) + "," + measure_mm(p.y_nm, 4) + "," +
           measure_mm(p.at.column_x_nm, 4) + "," + measure_mm(p.at.column_y_nm, 4) + "," + (p.at.material ? "1" : "0") +
           "," + (p.at.material ? measure_mm(p.at.top_nm) : "") + "," + (p.at.material ? measure_mm(p.at.bottom_nm) : "") +
           "," + (p.have_design ? measure_mm(p.design_nm) : "") + "," + std::to_string(p.at.line) + "\n";
    chart.push_back(SectionChartPoint{to_mm(p.along_nm), p.at.material, to_mm(p.at.top_nm), to_mm(p.at.bottom_nm),
                                      p.have_design, to_mm(p.design_nm)});
  }
  const std::string title = "X" + measure_mm(seg.x0_nm, 3) + " Y" + measure_mm(seg.y0_nm, 3) + " to X" +
                            measure_mm(seg.x1_nm, 3) + " Y" + measure_mm(seg.y1_nm, 3);
  if (const int code = write_text(csv_path, csv, "--csv")) return code;
  if (!svg_path.empty())
    if (const int code = write_text(svg_path, section_svg(chart, title), "--svg")) return code;
  // Where the CSV went to a file, the section's summary on standard output.
  if (!csv_path.empty())
    std::printf("section %s: %d samples over %s mm (heights within %s mm; each sample's column within %s mm of its "
                "point)\n",
                title.c_str(), seg.steps + 1, measure_mm(seg.length_nm, 3).c_str(), measure_mm(g.lsb_nm).c_str(),
                measure_mm(div_ceil(hypot_floor(g.pitch_nm, g.pitch_nm) + 1, 2), 3).c_str());
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
