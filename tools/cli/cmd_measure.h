// The pieces of `dexmill measure` (tools/cli/cmd_measure.cpp): the saved
// stock as a grid, and the queries' writers, split by query.
#ifndef DEXMILL_TOOLS_CLI_CMD_MEASURE_H
#define DEXMILL_TOOLS_CLI_CMD_MEASURE_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/grid/grid.h"
#include "core/measure/measure_at.h"
#include "core/measure/thin_floor.h"
#include "core/measure/thin_wall.h"
#include "core/stock/stock_file.h"
#include "tools/run/run_assess.h"
#include "tools/cli/option_table.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// The command's settings, as its options give them.
struct MeasureArgs {
  std::string file;
  std::vector<std::pair<int64_t, int64_t>> at;  // --at, nm
  bool distance = false;
  int64_t segment_nm[4] = {};  // --distance X0,Y0,X1,Y1
  std::string csv, svg;        // --csv, --svg
  JobOptions job;              // --design and its options (run's: tools/run/run_job_options.cpp)
  bool thickness = false;
  int64_t wall_height_nm = 1000000;  // --wall-height, 1 mm
  std::string image;                 // --image
  int64_t thin_nm = 1000000;         // --thin, 1 mm (as dexmill run's)
  bool scallop = false;
  bool region = false;
  int64_t region_nm[4] = {};  // --scallop X0,Y0,X1,Y1
  bool any() const { return !at.empty() || distance || thickness || scallop; }
};

// The command's options and help (tools/cli/cmd_measure_options.cpp).
const OptionTable<MeasureArgs>& measure_table();

// A stock read from its file, with the layers it kept.
struct MeasuredStock {
  StockMeta meta{};
  std::vector<height_t> top, bottom;
  std::vector<uint32_t> lines;
  std::vector<uint8_t> programs, cls;
  DexelGrid<height_t> grid;
  bool have_design = false;  // --design, on the grid (tools/cli/cmd_measure_read.cpp)
  RunDesign design;
  const int32_t* design_layer() const { return have_design ? design.grid.top_lsb : nullptr; }
  const uint32_t* line_layer() const { return lines.empty() ? nullptr : lines.data(); }
  const uint8_t* program_layer() const { return programs.empty() ? nullptr : programs.data(); }
};

std::string measure_mm(int64_t nm, int decimals = 4);

// Reads the stock file into s; places job.design on its grid. kExitOk, or
// the exit code after saying why.
int read_stock(const std::string& file, MeasuredStock* s);
int read_design(const JobOptions& job, MeasuredStock* s);

// --distance X0,Y0,X1,Y1: the section as CSV (to csv_path, or standard
// output when empty) and as an SVG chart (svg_path, when given).
int measure_section(const MeasuredStock& s, const int64_t seg_nm[4], const std::string& csv_path,
                    const std::string& svg_path);

// The SVG chart of a section's samples (tools/cli/cmd_measure_svg.cpp).
struct SectionChartPoint {
  double along_mm;
  bool material;
  double top_mm, bottom_mm;
  bool have_design;
  double design_mm;
};
std::string section_svg(const std::vector<SectionChartPoint>& p, const std::string& title);

// --thickness: the thinnest floor and wall, printed; drawn into image_path
// (a PNG, when given) with the thin colouring under thin_nm.
int measure_thickness(const MeasuredStock& s, int64_t wall_height_nm, const std::string& image_path, int64_t thin_nm);
int measure_thin_image(const MeasuredStock& s, const std::string& path, int64_t thin_nm, const ThinFloor& floor,
                       const ThinWall& wall);

// --scallop: the highest scallop over the columns whose centres lie in the
// box region_nm (X0,Y0,X1,Y1; the whole grid when null), printed; a
// usage error when the box holds no column.
int measure_scallop(const MeasuredStock& s, const int64_t* region_nm);

}  // namespace cli
}  // namespace dexmill

#endif
