// `dexmill bench stock-2k`: a 2048 x 2048 stock (16-bit heights, every
// layer a saved run keeps: classes, lines, programs) written as a stock
// file to memory, read back in 1 MiB pieces, and turned: flipped about X,
// a quarter turn in place (core/stock/). The costs a job in several
// setups pays between its programs; disk time is the OS's and not in them.
#include <cstdint>
#include <vector>

#include "core/stock/stock_file.h"
#include "core/stock/stock_transform.h"
#include "tools/bench/bench.h"

namespace dexmill {
namespace {

struct Stock {
  StockMeta meta;
  std::vector<uint16_t> top, bottom;
  std::vector<uint8_t> cls, program;
  std::vector<uint32_t> line;
  StockColumns cols() {
    StockColumns c;
    c.top = top.data();
    c.bottom = bottom.data();
    c.cls = cls.data();
    c.line = line.data();
    c.program = program.data();
    return c;
  }
};

Stock make(int32_t n) {
  Stock s;
  StockMeta& m = s.meta;
  m.geo = GridGeometry{n, n, -100000, -100000, 100000, -20000000, 1000};
  m.height_bits = 16;
  m.layers = kStockLayerClass | kStockLayerLine | kStockLayerProgram;
  m.top_bound_lsb = m.top_lsb = 20000;
  m.stock_nx = m.stock_ny = n - 2;
  m.stock_lo = PointNm{0, 0, -20000000};
  m.stock_hi = PointNm{(n - 3) * 100000LL, (n - 3) * 100000LL, 0};
  m.prov_slots = 7;
  m.nprograms = 1;
  m.programs[0].setup[0] = m.programs[0].setup[4] = m.programs[0].setup[8] = 1;
  const size_t cells = static_cast<size_t>(n) * static_cast<size_t>(n);
  s.top.resize(cells);
  s.bottom.assign(cells, 0);
  s.cls.resize(cells);
  s.line.resize(cells);
  s.program.assign(cells, 0);
  uint32_t x = 12345;
  for (size_t k = 0; k < cells; ++k) {  // a milled look: terraces with noise, as a CAM part's tops
    x = x * 1664525u + 1013904223u;
    s.top[k] = static_cast<uint16_t>(15000 + ((k / 97) % 50) * 100 + (x >> 28));
    s.cls[k] = static_cast<uint8_t>(1 + (k / 4096) % 3);
    s.line[k] = static_cast<uint32_t>(100 + k / 2048);
  }
  return s;
}

bool to_vector(void* ctx, const uint8_t* p, size_t n) {
  auto* v = static_cast<std::vector<uint8_t>*>(ctx);
  v->insert(v->end(), p, p + n);
  return true;
}

void run_stock(const char* name) {
  Stock s = make(2048);
  std::vector<uint8_t> file;
  file.reserve(static_cast<size_t>(stock_file_bytes(s.meta)));
  const double save_s = bench::best_time_s([&] {
    file.clear();
    const double t0 = bench::now_s();
    (void)stock_write(s.meta, s.cols(), to_vector, &file);
    return bench::now_s() - t0;
  });
  Stock back = s;
  const double load_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    StockReader rd;
    size_t at = 0;
    while (at < file.size()) {
      size_t used = 0;
      const size_t piece = file.size() - at < (size_t{1} << 20) ? file.size() - at : (size_t{1} << 20);
      if (rd.feed(file.data() + at, piece, &used) != StockError::kOk) break;
      at += used;
      if (rd.header_done() && !rd.bound()) (void)rd.bind(back.cols());
    }
    (void)rd.finish();
    return bench::now_s() - t0;
  });
  StockSetup flip;
  flip.flip_x = true;
  StockSetup quarter;
  quarter.quarter_turns = 1;
  const double flip_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    (void)stock_apply_setup(flip, &back.meta, back.cols(), nullptr, 0);
    return bench::now_s() - t0;
  });
  const double turn_s = bench::best_time_s([&] {
    const double t0 = bench::now_s();
    (void)stock_apply_setup(quarter, &back.meta, back.cols(), nullptr, 0);
    return bench::now_s() - t0;
  });
  bench::result(name, "grid=2048x2048 bytes=%zu save_s=%.4f load_s=%.4f flip_s=%.4f quarter_turn_s=%.4f seconds=%.4f",
                file.size(), save_s, load_s, flip_s, turn_s, save_s + load_s);
}

}  // namespace
}  // namespace dexmill

BENCH(stock_2k, "stock-2k", dexmill::run_stock);
