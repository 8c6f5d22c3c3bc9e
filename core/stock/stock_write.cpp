// Writing a stock file (core/stock/stock_file.h): the header, the tiles
// layer by layer, each tile's CRC, the trailer; through one buffer on the
// stack, so a panel can write its stock to SD with no heap.
#include "core/math/crc32.h"
#include "core/stock/stock_file.h"

namespace dexmill {
namespace {

class Out {
 public:
  Out(StockSink sink, void* ctx) : sink_(sink), ctx_(ctx) {}
  void byte(uint8_t b) {
    buf_[n_++] = b;
    if (n_ == sizeof buf_) flush();
  }
  void uint_le(uint64_t v, int bytes) {
    if (n_ + static_cast<size_t>(bytes) > sizeof buf_) flush();  // a value never straddles a flush
    for (int i = 0; i < bytes; ++i) buf_[n_++] = static_cast<uint8_t>(v >> (8 * i));
  }
  // The CRC of what was written since the last crc_restart.
  void crc_restart() {
    crc_from_ = n_;
    crc_ = 0;
  }
  uint32_t crc() {
    crc_ = crc32_update(crc_, buf_ + crc_from_, n_ - crc_from_);
    crc_from_ = n_;
    return crc_;
  }
  bool flush() {
    crc_ = crc32_update(crc_, buf_ + crc_from_, n_ - crc_from_);
    if (n_ && ok_) ok_ = sink_(ctx_, buf_, n_);
    n_ = crc_from_ = 0;
    return ok_;
  }
  bool ok() const { return ok_; }

 private:
  StockSink sink_;
  void* ctx_;
  uint8_t buf_[4096];
  size_t n_ = 0, crc_from_ = 0;
  uint32_t crc_ = 0;
  bool ok_ = true;
};

// The values of one layer for cells [a, b), `bytes` each.
template <class T>
void put_layer(Out* o, const T* v, size_t a, size_t b, int bytes) {
  for (size_t k = a; k < b; ++k) o->uint_le(v[k], bytes);
}

void put_heights(Out* o, const void* h, int bits, size_t a, size_t b) {
  switch (bits) {
    case 8: put_layer(o, static_cast<const uint8_t*>(h), a, b, 1); break;
    case 16: put_layer(o, static_cast<const uint16_t*>(h), a, b, 2); break;
    default: put_layer(o, static_cast<const uint32_t*>(h), a, b, 4); break;
  }
}

}  // namespace

StockError stock_write(const StockMeta& m, const StockColumns& c, StockSink sink, void* ctx) {
  const char* detail = "";
  if (stock_meta_check(m, &detail) != StockError::kOk || !c.top || !c.bottom ||
      ((m.layers & kStockLayerClass) && !c.cls) || ((m.layers & kStockLayerLine) && !c.line) ||
      ((m.layers & kStockLayerProgram) && !c.program))
    return StockError::kBadMeta;
  Out o(sink, ctx);
  {
    uint8_t header[kStockHeaderBytes];
    stock_header_encode(m, header);
    for (uint8_t b : header) o.byte(b);
  }
  const size_t nx = static_cast<size_t>(m.geo.nx), ny = static_cast<size_t>(m.geo.ny);
  for (size_t j0 = 0; j0 < ny && o.ok(); j0 += m.tile_rows) {
    const size_t j1 = j0 + m.tile_rows < ny ? j0 + m.tile_rows : ny;
    const size_t a = j0 * nx, b = j1 * nx;
    o.crc_restart();
    put_heights(&o, c.top, m.height_bits, a, b);
    put_heights(&o, c.bottom, m.height_bits, a, b);
    if (m.layers & kStockLayerClass) put_layer(&o, c.cls, a, b, 1);
    if (m.layers & kStockLayerLine) put_layer(&o, c.line, a, b, 4);
    if (m.layers & kStockLayerProgram) put_layer(&o, c.program, a, b, 1);
    o.uint_le(o.crc(), 4);
  }
  for (uint8_t b : kStockTrailerMagic) o.byte(b);
  o.uint_le(stock_file_bytes(m), 8);
  return o.flush() ? StockError::kOk : StockError::kSink;
}

}  // namespace dexmill
