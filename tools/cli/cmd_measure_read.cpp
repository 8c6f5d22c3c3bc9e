// `dexmill measure`'s inputs (tools/cli/cmd_measure.h): the saved stock
// read into a grid with its layers, and the design placed on that grid the
// way `dexmill run --design` places it (tools/run/run_assess.h load_design,
// with the stock's plan and the part's frame the stock kept).
#include <cstdio>
#include <string>

#include "core/design/design.h"
#include "core/sim/stock_state.h"
#include "platform/format/stock_io.h"
#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"
#include "tools/run/run_stock.h"

namespace dexmill {
namespace cli {

// Reads the stock file into s: kExitOk or the exit code after saying why.
int read_stock(const std::string& file, MeasuredStock* s) {
  StockFileReader in;
  std::string err;
  if (!in.open(file, &err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return in.io_error() ? kExitIo : kExitInput;
  }
  s->meta = in.meta();
  const StockMeta& m = s->meta;
  if (const int code = stock_heights_fit(m, file)) return code;
  const size_t cells = static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny);
  s->top.assign(cells, 0);
  s->bottom.assign(cells, 0);
  s->lines.assign((m.layers & kStockLayerLine) ? cells : 0, 0);
  s->programs.assign((m.layers & kStockLayerProgram) ? cells : 0, 0);
  s->cls.assign((m.layers & kStockLayerClass) ? cells : 0, 0);
  StockColumns c;
  c.top = s->top.data();
  c.bottom = s->bottom.data();
  c.cls = s->cls.empty() ? nullptr : s->cls.data();
  c.line = s->lines.empty() ? nullptr : s->lines.data();
  c.program = s->programs.empty() ? nullptr : s->programs.data();
  if (!in.read_columns(c, &err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return in.io_error() ? kExitIo : kExitInput;
  }
  if (!ok(grid_init(&s->grid, m.geo, s->top.data(), s->bottom.data(), cells)))
    return fail(kExitInput, "%s: a grid this build cannot hold", file.c_str());
  return kExitOk;
}

int read_design(const JobOptions& job, MeasuredStock* s) {
  if (const int code = load_design(job, sim_plan_of_stock(s->meta), "", &s->design, s->meta.frame)) return code;
  s->have_design = true;
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
