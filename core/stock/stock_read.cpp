// Reading a stock file in pieces (core/stock/stock_file.h): the header
// into a buffer, the tiles straight into the caller's columns (each tile's
// CRC and values checked when it is complete), the trailer last.
#include "core/math/crc32.h"
#include "core/stock/stock_file.h"

namespace dexmill {
namespace {

// Little-endian elements of `es` bytes into dst[e..]; *partial and *have
// carry an element split between two feeds. Returns the next element.
template <class T>
size_t take_elems(T* dst, size_t e, const uint8_t* p, size_t n, int es, uint32_t* partial, int* have) {
  if (!dst) {  // a layer read past: only where its split element stands
    *have = static_cast<int>((static_cast<size_t>(*have) + n) % static_cast<size_t>(es));
    *partial = 0;
    return e;
  }
  size_t k = 0;
  while (k < n && *have) {  // finish the split element
    *partial |= static_cast<uint32_t>(p[k++]) << (8 * *have);
    if (++*have == es) {
      dst[e++] = static_cast<T>(*partial);
      *partial = 0;
      *have = 0;
    }
  }
  switch (es) {
    case 1:
      for (; k < n; ++k) dst[e++] = static_cast<T>(p[k]);
      break;
    case 2:
      for (; k + 2 <= n; k += 2) dst[e++] = static_cast<T>(p[k] | p[k + 1] << 8);
      break;
    default:
      for (; k + 4 <= n; k += 4)
        dst[e++] = static_cast<T>(static_cast<uint32_t>(p[k]) | static_cast<uint32_t>(p[k + 1]) << 8 |
                                  static_cast<uint32_t>(p[k + 2]) << 16 | static_cast<uint32_t>(p[k + 3]) << 24);
      break;
  }
  while (k < n) {  // the start of a split element
    *partial |= static_cast<uint32_t>(p[k++]) << (8 * *have);
    ++*have;
  }
  return e;
}

uint32_t height_at(const void* h, int bits, size_t k) {
  switch (bits) {
    case 8: return static_cast<const uint8_t*>(h)[k];
    case 16: return static_cast<const uint16_t*>(h)[k];
    default: return static_cast<const uint32_t*>(h)[k];
  }
}

uint64_t le64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<uint64_t>(p[i]) << (8 * i);
  return v;
}

}  // namespace

StockError StockReader::fail(StockError e, const char* detail) {
  phase_ = Phase::kFailed;
  detail_ = detail;
  last_ = e;
  return e;
}

bool StockReader::bind(const StockColumns& c) {
  if (phase_ != Phase::kTile || bound_ || !c.top || !c.bottom) return false;
  cols_ = c;
  // A layer the file does not hold is not written; one it holds with no
  // array is read past (checked by its CRC only).
  if (!(meta_.layers & kStockLayerClass)) cols_.cls = nullptr;
  if (!(meta_.layers & kStockLayerLine)) cols_.line = nullptr;
  if (!(meta_.layers & kStockLayerProgram) || !cols_.line) cols_.program = nullptr;
  bound_ = true;
  return true;
}

StockError StockReader::header_parsed() {
  const char* detail = "";
  const StockError e = stock_header_decode(buf_, &meta_, &detail);
  if (e != StockError::kOk) {
    offset_ = e == StockError::kHeaderValue ? offset_ : 0;
    return fail(e, detail);
  }
  ntiles_ = (static_cast<uint32_t>(meta_.geo.ny) + meta_.tile_rows - 1) / meta_.tile_rows;
  tile_ = 0;
  phase_ = Phase::kTile;
  tile_start();
  return StockError::kOk;
}

void StockReader::tile_start() {
  row0_ = static_cast<int32_t>(tile_ * meta_.tile_rows);
  rows_ = static_cast<int32_t>(meta_.tile_rows);
  if (row0_ + rows_ > meta_.geo.ny) rows_ = meta_.geo.ny - row0_;
  tile_at_ = 0;
  crc_ = 0;
  partial_ = 0;
  have_ = 0;
}

// The tile's layers in order: tops, bottoms, then the optional ones.
void StockReader::take_tile_bytes(const uint8_t* p, size_t n) {
  crc_ = crc32_update(crc_, p, n);
  const size_t cells = static_cast<size_t>(rows_) * static_cast<size_t>(meta_.geo.nx);
  const size_t base = static_cast<size_t>(row0_) * static_cast<size_t>(meta_.geo.nx);
  const int hb = meta_.height_bits / 8;
  struct Seg {
    int layer;  // 0 top, 1 bottom, 2 class, 3 line, 4 program
    int es;
  };
  Seg segs[5];
  int nseg = 0;
  segs[nseg++] = Seg{0, hb};
  segs[nseg++] = Seg{1, hb};
  if (meta_.layers & kStockLayerClass) segs[nseg++] = Seg{2, 1};
  if (meta_.layers & kStockLayerLine) segs[nseg++] = Seg{3, 4};
  if (meta_.layers & kStockLayerProgram) segs[nseg++] = Seg{4, 1};
  while (n > 0) {
    uint64_t start = 0;
    int s = 0;
    while (s < nseg && tile_at_ >= start + cells * static_cast<uint64_t>(segs[s].es)) start += cells * segs[s++].es;
    const Seg& g = segs[s];
    const uint64_t off = tile_at_ - start, left = cells * static_cast<uint64_t>(g.es) - off;
    const size_t take = static_cast<size_t>(n < left ? n : left);
    const size_t e = base + static_cast<size_t>(off / static_cast<uint64_t>(g.es));
    void* layer = g.layer == 0 ? cols_.top : g.layer == 1 ? cols_.bottom : nullptr;
    if (g.layer <= 1) {
      switch (meta_.height_bits) {
        case 8: take_elems(static_cast<uint8_t*>(layer), e, p, take, 1, &partial_, &have_); break;
        case 16: take_elems(static_cast<uint16_t*>(layer), e, p, take, 2, &partial_, &have_); break;
        default: take_elems(static_cast<uint32_t*>(layer), e, p, take, 4, &partial_, &have_); break;
      }
    } else if (g.layer == 2) {
      take_elems(cols_.cls, e, p, take, 1, &partial_, &have_);
    } else if (g.layer == 3) {
      take_elems(cols_.line, e, p, take, 4, &partial_, &have_);
    } else {
      take_elems(cols_.program, e, p, take, 1, &partial_, &have_);
    }
    tile_at_ += take;
    p += take;
    n -= take;
  }
}

// The tile's CRC (in buf_) and then its values: a bottom at or below its
// top, no top above the bound the cut relies on (core/grid/grid.h
// top_bound_lsb), bottoms 0 where the header says so, classes and programs
// within their lists.
StockError StockReader::tile_checked() {
  uint32_t want = 0;
  for (int i = 0; i < 4; ++i) want |= static_cast<uint32_t>(buf_[i]) << (8 * i);
  if (want != crc_) return fail(StockError::kTileCrc);
  const size_t nx = static_cast<size_t>(meta_.geo.nx);
  const size_t a = static_cast<size_t>(row0_) * nx, b = a + static_cast<size_t>(rows_) * nx;
  const uint64_t bound = static_cast<uint64_t>(meta_.top_bound_lsb);
  for (size_t k = a; k < b; ++k) {
    const uint32_t t = height_at(cols_.top, meta_.height_bits, k), w = height_at(cols_.bottom, meta_.height_bits, k);
    if (w > t) return fail(StockError::kColumnValue, "a bottom above its top");
    if (t > bound) return fail(StockError::kColumnValue, "a top above the stock's top bound");
    if (meta_.bottoms_zero && w != 0) return fail(StockError::kColumnValue, "a bottom above 0 where all are 0");
    if (cols_.cls && cols_.cls[k] > meta_.prov_slots) return fail(StockError::kColumnValue, "a tool class past the slots");
    if (cols_.program && cols_.program[k] >= meta_.nprograms && (cols_.line[k] != 0 || cols_.program[k] != 0))
      return fail(StockError::kColumnValue, "a program past the chain's list");
  }
  return StockError::kOk;
}

StockError StockReader::feed(const uint8_t* p, size_t n, size_t* used) {
  size_t k = 0;
  *used = 0;
  while (k < n) {
    switch (phase_) {
      case Phase::kHeader: {
        while (k < n && held_ < kStockHeaderBytes) {
          buf_[held_] = p[k++];
          // Say "not a stock file" at the first byte that is not the magic's.
          if (held_ < 8) {
            if (buf_[held_] != kStockMagic[held_]) {
              offset_ += held_;
              *used = k;
              return fail(StockError::kNotStock);
            }
          }
          ++held_;
        }
        if (held_ < kStockHeaderBytes) break;
        held_ = 0;
        if (const StockError e = header_parsed(); e != StockError::kOk) {
          *used = k;
          return e;
        }
        offset_ = kStockHeaderBytes;
        *used = k;
        if (!bound_) return StockError::kOk;  // the caller binds, then feeds the rest
        break;
      }
      case Phase::kTile: {
        if (!bound_) {
          *used = k;
          return StockError::kOk;
        }
        const uint64_t tile_total =
            static_cast<uint64_t>(rows_) * static_cast<uint64_t>(meta_.geo.nx) * stock_cell_bytes(meta_);
        const uint64_t left = tile_total - tile_at_;
        const size_t take = static_cast<size_t>(n - k < left ? n - k : left);
        take_tile_bytes(p + k, take);
        k += take;
        offset_ += take;
        if (tile_at_ == tile_total) phase_ = Phase::kTileCrc;
        break;
      }
      case Phase::kTileCrc: {
        while (k < n && held_ < 4) buf_[held_++] = p[k++];
        if (held_ < 4) break;
        held_ = 0;
        if (const StockError e = tile_checked(); e != StockError::kOk) {
          *used = k;
          return e;
        }
        offset_ += 4;
        if (++tile_ < ntiles_) {
          phase_ = Phase::kTile;
          tile_start();
        } else {
          phase_ = Phase::kTrailer;
        }
        break;
      }
      case Phase::kTrailer: {
        while (k < n && held_ < kStockTrailerBytes) buf_[held_++] = p[k++];
        if (held_ < kStockTrailerBytes) break;
        held_ = 0;
        for (int i = 0; i < 8; ++i)
          if (buf_[i] != kStockTrailerMagic[i]) {
            *used = k;
            return fail(StockError::kTrailer);
          }
        offset_ += kStockTrailerBytes;
        if (le64(buf_ + 8) != offset_ || offset_ != stock_file_bytes(meta_)) {
          *used = k;
          return fail(StockError::kTrailer);
        }
        phase_ = Phase::kDone;
        break;
      }
      case Phase::kDone:
        *used = k;
        return fail(StockError::kTooLong);
      case Phase::kFailed:
        *used = k;
        return last_;
    }
  }
  *used = k;
  return StockError::kOk;
}

StockError StockReader::finish() {
  if (phase_ == Phase::kFailed) return last_;
  if (phase_ != Phase::kDone) {
    offset_ += held_;
    return fail(StockError::kTruncated);
  }
  return StockError::kOk;
}

}  // namespace dexmill
