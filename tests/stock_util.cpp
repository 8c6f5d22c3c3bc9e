#include "tests/stock_util.h"

#include "tests/run_cli_util.h"

namespace t {

StockFileColumns read_stock_file(const std::string& path) {
  using namespace dexmill;
  StockFileColumns c;
  const std::string bytes = run_cli::slurp(path);
  StockReader rd;
  size_t at = 0;
  while (at < bytes.size()) {
    size_t used = 0;
    if (rd.feed(reinterpret_cast<const uint8_t*>(bytes.data()) + at, bytes.size() - at, &used) != StockError::kOk)
      return c;
    at += used;
    if (rd.header_done() && !rd.bound()) {
      c.meta = rd.meta();
      if (c.meta.height_bits != 16) return c;
      const size_t n = static_cast<size_t>(c.meta.geo.nx) * static_cast<size_t>(c.meta.geo.ny);
      c.top.resize(n);
      c.bottom.resize(n);
      c.cls.resize(n);
      c.program.resize(n);
      c.line.resize(n);
      StockColumns cols;
      cols.top = c.top.data();
      cols.bottom = c.bottom.data();
      cols.cls = c.cls.data();
      cols.line = c.line.data();
      cols.program = c.program.data();
      if (!rd.bind(cols)) return c;
    }
  }
  c.ok = rd.finish() == StockError::kOk;
  return c;
}

}  // namespace t
