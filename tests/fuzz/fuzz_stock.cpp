// libFuzzer target: the stock file reader (core/stock/stock_file.h). Input:
// a stock file's bytes. Read whole and read a byte at a time, the reader
// gives the same verdict at the same byte; a file it reads has every column
// in range (a bottom at or below its top, no top above the bound, classes
// and programs within their lists), and written again from what was read
// it is the same bytes. Grids past 1 M dexels are read as far as the
// header (a fuzzer should not make the target allocate gigabytes).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/stock/stock_file.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz_stock {

using namespace dexmill;

struct Read {
  StockError error = StockError::kOk;
  uint64_t offset = 0;
  StockMeta meta;
  std::vector<uint32_t> h32;
  std::vector<uint16_t> h16;
  std::vector<uint8_t> h8, cls, program;
  std::vector<uint32_t> line;
  std::vector<uint32_t> top32, bottom32;  // the heights, whatever m
  bool complete = false;
};

StockColumns bind_columns(Read* r) {
  const StockMeta& m = r->meta;
  const size_t n = static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny);
  StockColumns c;
  if (m.height_bits == 8) {
    r->h8.assign(2 * n, 0);
    c.top = r->h8.data();
    c.bottom = r->h8.data() + n;
  } else if (m.height_bits == 16) {
    r->h16.assign(2 * n, 0);
    c.top = r->h16.data();
    c.bottom = r->h16.data() + n;
  } else {
    r->h32.assign(2 * n, 0);
    c.top = r->h32.data();
    c.bottom = r->h32.data() + n;
  }
  r->cls.assign(n, 0);
  r->line.assign(n, 0);
  r->program.assign(n, 0);
  c.cls = r->cls.data();
  c.line = r->line.data();
  c.program = r->program.data();
  return c;
}

Read read(const uint8_t* data, size_t size, size_t piece) {
  Read r;
  StockReader rd;
  StockColumns cols;
  size_t at = 0;
  while (at < size) {
    size_t used = 0;
    const size_t n = size - at < piece ? size - at : piece;
    r.error = rd.feed(data + at, n, &used);
    FUZZ_REQUIRE(used <= n);
    at += used;
    if (r.error != StockError::kOk) {
      r.offset = rd.offset();
      return r;
    }
    if (rd.header_done() && !rd.bound()) {
      r.meta = rd.meta();
      if (static_cast<uint64_t>(r.meta.geo.nx) * static_cast<uint64_t>(r.meta.geo.ny) > (1u << 20)) return r;
      cols = bind_columns(&r);
      FUZZ_REQUIRE(rd.bind(cols));
    } else if (used == 0) {
      FUZZ_REQUIRE(false);  // no progress and no reason
    }
  }
  r.error = rd.finish();
  r.offset = rd.offset();
  r.complete = r.error == StockError::kOk;
  return r;
}

bool to_vector(void* ctx, const uint8_t* p, size_t n) {
  auto* v = static_cast<std::vector<uint8_t>*>(ctx);
  v->insert(v->end(), p, p + n);
  return true;
}

int fuzz_stock(const uint8_t* data, size_t size) {
  Read whole = read(data, size, size ? size : 1);
  Read bytes = read(data, size, 1);
  FUZZ_REQUIRE(whole.error == bytes.error);
  FUZZ_REQUIRE(whole.offset == bytes.offset);
  if (!whole.complete) return 0;
  FUZZ_REQUIRE(bytes.complete);
  const StockMeta& m = whole.meta;
  const size_t n = static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny);
  for (size_t k = 0; k < n; ++k) {
    const uint32_t t = m.height_bits == 8 ? whole.h8[k] : m.height_bits == 16 ? whole.h16[k] : whole.h32[k];
    const uint32_t b = m.height_bits == 8 ? whole.h8[n + k] : m.height_bits == 16 ? whole.h16[n + k] : whole.h32[n + k];
    FUZZ_REQUIRE(b <= t);
    FUZZ_REQUIRE(static_cast<int64_t>(t) <= m.top_bound_lsb);
    if (m.layers & kStockLayerClass) FUZZ_REQUIRE(whole.cls[k] <= m.prov_slots);
  }
  // Written again: the same bytes.
  StockColumns cols;
  Read again = whole;
  cols = bind_columns(&again);
  // (bind_columns cleared them: copy the read values back)
  again.h8 = whole.h8;
  again.h16 = whole.h16;
  again.h32 = whole.h32;
  again.cls = whole.cls;
  again.line = whole.line;
  again.program = whole.program;
  cols.top = m.height_bits == 8 ? static_cast<void*>(again.h8.data()) : m.height_bits == 16 ? static_cast<void*>(again.h16.data()) : static_cast<void*>(again.h32.data());
  cols.bottom = m.height_bits == 8 ? static_cast<void*>(again.h8.data() + n) : m.height_bits == 16 ? static_cast<void*>(again.h16.data() + n) : static_cast<void*>(again.h32.data() + n);
  cols.cls = again.cls.data();
  cols.line = again.line.data();
  cols.program = again.program.data();
  std::vector<uint8_t> out;
  FUZZ_REQUIRE(stock_write(m, cols, to_vector, &out) == StockError::kOk);
  FUZZ_REQUIRE(out.size() == size);
  for (size_t k = 0; k < size; ++k) FUZZ_REQUIRE(out[k] == data[k]);
  return 0;
}

}  // namespace fuzz_stock

DEXMILL_FUZZ_ENTRY(fuzz_stock::fuzz_stock)
