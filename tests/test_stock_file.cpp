// core/stock/stock_file.h: the stock file written and read back whole, in
// pieces of every size, for every height format and layer set; and every
// kind of damage (truncation at every boundary, each byte flipped in the
// header and in a tile, another version, the other byte order, trailing
// bytes, values out of range) refused with its own error, never a stock.
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/math/crc32.h"
#include "core/stock/stock_file.h"
#include "tests/rng.h"
#include <algorithm>
#include <string>
#include "tests/runner.h"

using namespace dexmill;
using t::Rng;

namespace {

struct Image {
  StockMeta meta;
  std::vector<uint32_t> top, bottom, line;  // heights as words, packed per format below
  std::vector<uint8_t> cls, program;
  std::vector<uint8_t> top_bytes, bottom_bytes;  // the heights in the meta's format
};

// A stock of nx x ny with random columns (bottom <= top <= bound).
Image make_image(int bits, uint8_t layers, int32_t nx, int32_t ny, uint32_t tile_rows, uint64_t seed) {
  Image im;
  StockMeta& m = im.meta;
  m.geo = GridGeometry{nx, ny, -12345, 67890, 250000, -20000000, 1000};
  m.height_bits = bits;
  m.layers = layers;
  m.tile_rows = tile_rows;
  m.top_bound_lsb = bits == 8 ? 200 : 20000;
  m.stock_nx = nx - 2;
  m.stock_ny = ny - 2;
  m.top_lsb = m.top_bound_lsb;
  m.stock_lo = PointNm{-12345, 67890, -20000000};
  m.stock_hi = PointNm{1000000, 2000000, 0};
  m.have_position = true;
  m.tool = 3;
  m.position = PointNm{1, -2, 3};
  m.removed_lsb_dexels = 123456789;
  m.sim_us = 4242;
  m.moves = 77;
  stock_name_set(m.material, "aluminium");
  m.material_hash = 0x1122334455667788ull;
  if (layers & kStockLayerClass) {
    m.prov_slots = 7;
    m.prov_ntools = 2;
    m.prov_tool[0] = 1;
    m.prov_tool[1] = 3;
  }
  m.nprograms = 2;
  for (int k = 0; k < 2; ++k) {
    stock_name_set(m.programs[k].name, k ? "second.ngc" : "first.ngc");
    m.programs[k].setup[0] = m.programs[k].setup[4] = m.programs[k].setup[8] = 1;
    m.programs[k].moves = 10 + k;
  }
  const size_t n = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  Rng rng(seed);
  im.top.resize(n);
  im.bottom.resize(n);
  im.cls.resize(n);
  im.line.resize(n);
  im.program.resize(n);
  for (size_t k = 0; k < n; ++k) {
    im.top[k] = static_cast<uint32_t>(rng.range(0, m.top_bound_lsb));
    im.bottom[k] = static_cast<uint32_t>(rng.range(0, im.top[k]));
    im.cls[k] = static_cast<uint8_t>(rng.range(0, 7));
    im.line[k] = static_cast<uint32_t>(rng.next());
    im.program[k] = static_cast<uint8_t>(rng.range(0, 1));
  }
  const int hb = bits / 8;
  im.top_bytes.resize(n * hb);
  im.bottom_bytes.resize(n * hb);
  for (size_t k = 0; k < n; ++k) {
    if (bits == 8) {
      im.top_bytes[k] = static_cast<uint8_t>(im.top[k]);
      im.bottom_bytes[k] = static_cast<uint8_t>(im.bottom[k]);
    } else if (bits == 16) {
      const uint16_t t = static_cast<uint16_t>(im.top[k]), b = static_cast<uint16_t>(im.bottom[k]);
      std::memcpy(&im.top_bytes[2 * k], &t, 2);
      std::memcpy(&im.bottom_bytes[2 * k], &b, 2);
    } else {
      std::memcpy(&im.top_bytes[4 * k], &im.top[k], 4);
      std::memcpy(&im.bottom_bytes[4 * k], &im.bottom[k], 4);
    }
  }
  return im;
}

StockColumns columns_of(Image* im) {
  StockColumns c;
  c.top = im->top_bytes.data();
  c.bottom = im->bottom_bytes.data();
  c.cls = im->cls.data();
  c.line = im->line.data();
  c.program = im->program.data();
  return c;
}

bool to_vector(void* ctx, const uint8_t* p, size_t n) {
  auto* v = static_cast<std::vector<uint8_t>*>(ctx);
  v->insert(v->end(), p, p + n);
  return true;
}

std::vector<uint8_t> write_image(Image* im) {
  std::vector<uint8_t> out;
  CHECK_EQ(stock_write(im->meta, columns_of(im), to_vector, &out), StockError::kOk);
  return out;
}

// Reads bytes in pieces of `piece` into a fresh image of the same shape.
struct ReadResult {
  StockError error = StockError::kOk;
  Image got;
  uint64_t offset = 0;
};
ReadResult read_bytes(const std::vector<uint8_t>& bytes, size_t piece) {
  ReadResult r;
  StockReader rd;
  size_t at = 0;
  while (at < bytes.size()) {
    const size_t n = std::min(piece, bytes.size() - at);
    size_t used = 0;
    r.error = rd.feed(bytes.data() + at, n, &used);
    at += used;
    if (r.error != StockError::kOk) {
      r.offset = rd.offset();
      return r;
    }
    if (rd.header_done() && !rd.bound()) {
      const StockMeta& m = rd.meta();
      r.got.meta = m;
      const size_t cells = static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny);
      r.got.top_bytes.assign(cells * (m.height_bits / 8), 0xAA);
      r.got.bottom_bytes.assign(cells * (m.height_bits / 8), 0xAA);
      r.got.cls.assign(cells, 0xAA);
      r.got.line.assign(cells, 0xAAAAAAAAu);
      r.got.program.assign(cells, 0xAA);
      CHECK(rd.bind(columns_of(&r.got)));
    }
  }
  r.error = rd.finish();
  r.offset = rd.offset();
  return r;
}

}  // namespace

TEST(crc32_slicing_equals_the_bitwise_definition) {
  Rng rng(7);
  std::vector<uint8_t> data(1000);
  for (auto& b : data) b = static_cast<uint8_t>(rng.next());
  for (size_t n : {0u, 1u, 3u, 4u, 5u, 17u, 1000u}) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) {
      c ^= data[i];
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    CHECK_EQ(crc32_update(0, data.data(), n), ~c);
    // In two pieces at every split: the same value.
    for (size_t split = 0; split <= n; split += 7) CHECK_EQ(crc32_update(crc32_update(0, data.data(), split), data.data() + split, n - split), ~c);
  }
  CHECK_EQ(crc32_update(0, reinterpret_cast<const uint8_t*>("123456789"), 9), 0xCBF43926u);
}

TEST(stock_file_round_trips_every_format_and_layer_set) {
  const uint8_t layer_sets[] = {0, kStockLayerClass, kStockLayerClass | kStockLayerLine,
                                kStockLayerClass | kStockLayerLine | kStockLayerProgram};
  int runs = 0;
  for (int bits : {8, 16, 32})
    for (uint8_t layers : layer_sets)
      for (uint32_t tile_rows : {1u, 5u, 16u, 100u}) {
        Image im = make_image(bits, layers, 23, 17, tile_rows, 100 + bits + layers + tile_rows);
        const std::vector<uint8_t> bytes = write_image(&im);
        CHECK_EQ(bytes.size(), stock_file_bytes(im.meta));
        for (size_t piece : {size_t{1}, size_t{3}, size_t{4096}, bytes.size()}) {
          ReadResult r = read_bytes(bytes, piece);
          CHECK_EQ(r.error, StockError::kOk);
          CHECK(r.got.top_bytes == im.top_bytes);
          CHECK(r.got.bottom_bytes == im.bottom_bytes);
          const size_t n = im.top.size();
          for (size_t k = 0; k < n; ++k) {
            if (layers & kStockLayerClass) CHECK_EQ(r.got.cls[k], im.cls[k]);
            else CHECK_EQ(r.got.cls[k], 0xAA);  // not written
            if (layers & kStockLayerLine) CHECK_EQ(r.got.line[k], im.line[k]);
            if (layers & kStockLayerProgram) CHECK_EQ(r.got.program[k], im.program[k]);
          }
          // Saved again: the same bytes.
          Image again = r.got;
          CHECK(write_image(&again) == bytes);
          ++runs;
        }
      }
  CHECK_EQ(runs, 3 * 4 * 4 * 4);
}

TEST(stock_file_reads_past_layers_it_is_not_given_arrays_for) {
  Image im = make_image(16, kStockLayerClass | kStockLayerLine | kStockLayerProgram, 9, 31, 4, 5);
  const std::vector<uint8_t> bytes = write_image(&im);
  for (size_t piece : {size_t{1}, size_t{7}, bytes.size()}) {
    StockReader rd;
    std::vector<uint8_t> top(im.top_bytes.size()), bottom(im.bottom_bytes.size());
    size_t at = 0;
    StockError e = StockError::kOk;
    while (at < bytes.size() && e == StockError::kOk) {
      size_t used = 0;
      e = rd.feed(bytes.data() + at, std::min(piece, bytes.size() - at), &used);
      at += used;
      if (rd.header_done() && !rd.bound()) {
        StockColumns c;
        c.top = top.data();
        c.bottom = bottom.data();
        CHECK(rd.bind(c));
      }
    }
    CHECK_EQ(e, StockError::kOk);
    CHECK_EQ(rd.finish(), StockError::kOk);
    CHECK(top == im.top_bytes);
    CHECK(bottom == im.bottom_bytes);
  }
}

TEST(stock_file_truncated_anywhere_is_refused) {
  Image im = make_image(16, kStockLayerClass | kStockLayerLine, 11, 9, 4, 9);
  const std::vector<uint8_t> bytes = write_image(&im);
  // Every length short of the whole, in one piece and byte by byte.
  int refused = 0;
  for (size_t len = 0; len < bytes.size(); ++len) {
    std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(len));
    const ReadResult r = read_bytes(cut, len % 2 ? 1 : 4096);
    CHECK_EQ(r.error, StockError::kTruncated);
    if (r.error == StockError::kTruncated) {
      CHECK_EQ(r.offset, len);  // says where it ended
      ++refused;
    }
  }
  CHECK_EQ(static_cast<size_t>(refused), bytes.size());
}

TEST(stock_file_damage_is_refused_by_its_kind) {
  Image im = make_image(16, kStockLayerClass | kStockLayerLine | kStockLayerProgram, 13, 12, 5, 11);
  const std::vector<uint8_t> bytes = write_image(&im);
  // Every single bit flipped in the header, and a byte in every tile: never
  // read as a stock.
  for (size_t at = 0; at < kStockHeaderBytes; ++at) {
    std::vector<uint8_t> bad = bytes;
    bad[at] ^= static_cast<uint8_t>(1u << (at % 8));
    const StockError e = read_bytes(bad, 4096).error;
    CHECK(e != StockError::kOk);
    if (at >= 16) CHECK_EQ(e, StockError::kHeaderCrc);  // past magic, version, mark and size
  }
  for (size_t at = kStockHeaderBytes; at < bytes.size() - kStockTrailerBytes; at += 37) {
    std::vector<uint8_t> bad = bytes;
    bad[at] ^= 0x10;
    CHECK_EQ(read_bytes(bad, 4096).error, StockError::kTileCrc);
  }
  {  // the trailer's length
    std::vector<uint8_t> bad = bytes;
    bad[bad.size() - 3] ^= 1;
    CHECK_EQ(read_bytes(bad, 4096).error, StockError::kTrailer);
  }
  {  // bytes after the end
    std::vector<uint8_t> bad = bytes;
    bad.push_back(0);
    CHECK_EQ(read_bytes(bad, 4096).error, StockError::kTooLong);
  }
  {  // not a stock file at all: says so at its first byte
    std::vector<uint8_t> text = {'G', '0', ' ', 'X', '1', '\n'};
    const ReadResult r = read_bytes(text, 4096);
    CHECK_EQ(r.error, StockError::kNotStock);
    CHECK_EQ(r.offset, 0u);
  }
  // Another version, and the other byte order (the mark swapped), each
  // with a valid CRC: refused for what they are.
  auto recrc = [](std::vector<uint8_t>* b) {
    const uint32_t c = crc32_update(0, b->data(), kStockHeaderBytes - 4);
    for (int i = 0; i < 4; ++i) (*b)[kStockHeaderBytes - 4 + i] = static_cast<uint8_t>(c >> (8 * i));
  };
  {
    std::vector<uint8_t> bad = bytes;
    bad[8] = 2;
    recrc(&bad);
    CHECK_EQ(read_bytes(bad, 4096).error, StockError::kVersion);
  }
  {
    std::vector<uint8_t> bad = bytes;
    bad[10] = 0xFE;
    bad[11] = 0xFF;
    recrc(&bad);
    CHECK_EQ(read_bytes(bad, 4096).error, StockError::kByteOrder);
  }
}

TEST(stock_file_values_out_of_range_are_refused) {
  // Written by a writer that was given a bad stock: the writer refuses it.
  Image im = make_image(16, kStockLayerClass, 8, 8, 4, 13);
  {
    Image bad = im;
    bad.meta.height_bits = 12;
    std::vector<uint8_t> out;
    CHECK_EQ(stock_write(bad.meta, columns_of(&bad), to_vector, &out), StockError::kBadMeta);
  }
  {
    Image bad = im;
    bad.meta.frame.turn[0] = 2;
    std::vector<uint8_t> out;
    CHECK_EQ(stock_write(bad.meta, columns_of(&bad), to_vector, &out), StockError::kBadMeta);
  }
  // A column's values past what the header allows, with valid CRCs (a
  // writer of another program): the reader checks them.
  auto column_case = [&](auto change) {
    Image bad = im;
    change(&bad);
    std::vector<uint8_t> out;
    CHECK_EQ(stock_write(bad.meta, columns_of(&bad), to_vector, &out), StockError::kOk);
    CHECK_EQ(read_bytes(out, 4096).error, StockError::kColumnValue);
  };
  column_case([](Image* b) { b->bottom_bytes[2] = 0xFF; b->bottom_bytes[3] = 0x7F; });  // a bottom above its top
  column_case([](Image* b) { b->top_bytes[0] = 0xFF; b->top_bytes[1] = 0xFF; });        // a top above the bound
  column_case([](Image* b) { b->cls[5] = 9; });                                         // a class past the slots
  column_case([](Image* b) {  // a bottom above 0 where all are 0
    b->meta.bottoms_zero = true;
    for (auto& v : b->bottom_bytes) v = 0;
    b->bottom_bytes[8] = 1;
  });
}

TEST(stock_name_set_cuts_at_a_character_boundary) {
  char field[kStockNameBytes];
  std::string long_name(62, 'a');
  long_name += "\xC3\xA9\xC3\xA9";  // two é
  stock_name_set(field, long_name.c_str());
  CHECK_EQ(std::strlen(field), 62u);  // not half an é
  stock_name_set(field, "short");
  CHECK_EQ(std::string(field), std::string("short"));
  for (int k = 5; k < kStockNameBytes; ++k) CHECK_EQ(field[k], 0);
}
