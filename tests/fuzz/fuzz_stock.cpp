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
  std::vector<uint32_t> h32;  // tops then bottoms, in the arrays of the meta's m
  std::vector<uint16_t> h16;
  std::vector<uint8_t> h8, cls, program;
  std::vector<uint32_t> line;
  bool complete = false;
};

// The columns of r's arrays (sized by bind_columns).
StockColumns columns(Read* r) {
  const size_t n = r->cls.size();
  StockColumns c;
  switch (r->meta.height_bits) {
    case 8: c.top = r->h8.data(), c.bottom = r->h8.data() + n; break;
    case 16: c.top = r->h16.data(), c.bottom = r->h16.data() + n; break;
    default: c.top = r->h32.data(), c.bottom = r->h32.data() + n; break;
  }
  c.cls = r->cls.data();
  c.line = r->line.data();
  c.program = r->program.data();
  return c;
}

// Arrays for the meta's grid, zeroed, and their columns.
StockColumns bind_columns(Read* r) {
  const size_t n = static_cast<size_t>(r->meta.geo.nx) * static_cast<size_t>(r->meta.geo.ny);
  const int bits = r->meta.height_bits;
  r->h8.assign(bits == 8 ? 2 * n : 0, 0);
  r->h16.assign(bits == 16 ? 2 * n : 0, 0);
  r->h32.assign(bits == 32 ? 2 * n : 0, 0);
  r->cls.assign(n, 0);
  r->line.assign(n, 0);
  r->program.assign(n, 0);
  return columns(r);
}

uint32_t height(const Read& r, size_t k) {
  const int bits = r.meta.height_bits;
  return bits == 8 ? r.h8[k] : bits == 16 ? r.h16[k] : r.h32[k];
}

Read read(const uint8_t* data, size_t size, size_t piece) {
  Read r;
  StockReader rd;
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
      FUZZ_REQUIRE(rd.bind(bind_columns(&r)));
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
    const uint32_t t = height(whole, k), b = height(whole, n + k);
    FUZZ_REQUIRE(b <= t);
    FUZZ_REQUIRE(static_cast<int64_t>(t) <= m.top_bound_lsb);
    if (m.layers & kStockLayerClass) FUZZ_REQUIRE(whole.cls[k] <= m.prov_slots);
  }
  // Written again from what was read: the same bytes.
  std::vector<uint8_t> out;
  FUZZ_REQUIRE(stock_write(m, columns(&whole), to_vector, &out) == StockError::kOk);
  FUZZ_REQUIRE(out.size() == size);
  for (size_t k = 0; k < size; ++k) FUZZ_REQUIRE(out[k] == data[k]);
  return 0;
}

}  // namespace fuzz_stock

DEXMILL_FUZZ_ENTRY(fuzz_stock::fuzz_stock)
