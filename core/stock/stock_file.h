// The stock file (.dxstock): the engine's stock at a move boundary, to be
// carried into the next program or setup (`--save-stock`, `--stock`), read
// by a panel from flash or SD, measured later. Its layout is in
// core/stock/README.md. Integer only, no heap, no I/O: the writer hands
// bytes to a sink, the reader is fed bytes in pieces of any size and writes
// the layers straight into the caller's grid, so a reader never holds two
// copies of a stock.
//
// A file is a header (fixed size, its own CRC-32), then tiles of whole rows
// (each layer's values for those rows, then the tile's CRC-32), then a
// trailer (its magic and the file's length). Every number is little-endian
// whatever the CPU, so a file is the same bytes everywhere; a reader that
// finds anything else (a truncated or longer file, a flipped bit, another
// version, another byte order, a layer value outside its range) says so and
// where, and the stock it was writing into is not to be used.
#ifndef DEXMILL_CORE_STOCK_STOCK_FILE_H
#define DEXMILL_CORE_STOCK_STOCK_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/math/part_frame.h"
#include "core/point.h"

namespace dexmill {

constexpr uint16_t kStockFileVersion = 1;
constexpr int kStockNameBytes = 64;     // a name with its NUL (longer ones are cut at a UTF-8 boundary)
constexpr int kStockMaxPrograms = 32;   // programs a stock remembers (the chain that made it)
constexpr int kStockMaxTools = 64;      // the provenance's tool order (core/sim/provenance.h kProvenanceMaxTools)
constexpr uint32_t kStockDefaultTileRows = 16;
// The most dexels a stock file holds (the 64 M a run's grid was once capped
// at): what a reader may be asked to allocate for a header it has not yet
// seen the tiles of stays bounded. A run's grid may be larger (its memory
// budget, core/sim/stock_plan.h); `dexmill run --save-stock` refuses one
// beyond this before the cut (tools/run/run_setup.cpp).
constexpr int64_t kStockMaxDexels = int64_t{64} << 20;

// Which optional layers a file holds (a byte per column each, but lines: 4).
enum StockLayer : uint8_t {
  kStockLayerClass = 1,    // the provenance class of the tool that last lowered each top (0 uncut)
  kStockLayerLine = 2,     // the program line that did (0 none)
  kStockLayerProgram = 4,  // and which of the chain's programs it is in (an index into programs)
};

// One program of the chain that made the stock, in the order they ran.
struct StockProgram {
  char name[kStockNameBytes];  // as the report shows it
  uint64_t removed_lsb_dexels;  // what it removed (LSB x dexels)
  int64_t sim_us;               // its estimated machine time
  uint64_t moves;               // its motion records
  int8_t setup[9];              // the setup's turn before it (row-major 3x3 of -1, 0, 1; identity when none)
  int64_t setup_offset_nm[3];   // and its move
};

// Where the part's own frame is, seen from the current setup
// (core/math/part_frame.h): materials and design parts live in the part's
// frame (core/stock/README.md).
using StockFrame = PartFrame;
inline StockFrame stock_frame_identity() { return part_frame_identity(); }

// Everything of a stock but its columns.
struct StockMeta {
  GridGeometry geo{};
  int height_bits = 16;          // m of the heights (8, 16, 32)
  uint8_t layers = 0;            // StockLayer bits
  uint32_t tile_rows = kStockDefaultTileRows;
  bool bottoms_zero = false;     // DexelGrid::bottoms_zero
  int64_t top_bound_lsb = 0;     // DexelGrid::top_bound_lsb
  // The plan the stock was made by (core/sim/stock_plan.h GridPlan).
  int32_t stock_nx = 0, stock_ny = 0;
  int64_t top_lsb = 0;
  PointNm stock_lo{0, 0, 0}, stock_hi{0, 0, 0};
  // The machine when the stock was saved: the tool in the spindle, where its tip was.
  bool have_position = false;
  int32_t tool = 0;
  PointNm position{0, 0, 0};
  // The chain's totals (every program's, this one's included).
  uint64_t removed_lsb_dexels = 0;
  int64_t sim_us = 0;
  uint64_t moves = 0;
  StockFrame frame = stock_frame_identity();
  // What the stock is made of and what it is to become: names as given and
  // a hash of their content (0: none), so that a later run can say when it
  // is given other ones.
  char material[kStockNameBytes] = {};
  uint64_t material_hash = 0;
  char design[kStockNameBytes] = {};
  uint64_t design_hash = 0;
  // The provenance's tool order (core/sim/provenance.h), when kStockLayerClass.
  int32_t prov_slots = 0, prov_ntools = 0, prov_unlisted = 0;
  int32_t prov_current = 0;  // the tool number the provenance lists the spindle's under
  int32_t prov_tool[kStockMaxTools] = {};
  int32_t nprograms = 0;
  StockProgram programs[kStockMaxPrograms] = {};
};

// Copies text into a name field, cut to fit (at a UTF-8 character boundary).
void stock_name_set(char* field, const char* text);

// The columns to write or to read into (row-major nx*ny; the optional ones
// null when the meta's layers leave them out). Heights are of m bits: the
// pointer's type is the meta's height_bits'.
struct StockColumns {
  void* top = nullptr;
  void* bottom = nullptr;
  uint8_t* cls = nullptr;
  uint32_t* line = nullptr;
  uint8_t* program = nullptr;
};

// Why a stock could not be read or written.
enum class StockError : uint8_t {
  kOk = 0,
  kNotStock,       // the first bytes are not a stock file's
  kByteOrder,      // written with the other byte order
  kVersion,        // a version this reader does not know
  kHeaderCrc,      // the header's bytes are not those written
  kHeaderValue,    // a header field out of its range (detail says which)
  kTileCrc,        // a tile's bytes are not those written
  kColumnValue,    // a column's value out of range (a bottom above its top, a class or program past the list)
  kTruncated,      // the file ends early
  kTrailer,        // the trailer is missing or names another length
  kTooLong,        // bytes after the trailer
  kSink,           // the writer's sink refused bytes
  kBadMeta,        // the meta given to the writer is not a stock's
};
const char* stock_error_message(StockError e);

// The header's size (version 1), and the file's for a meta (header, tiles,
// trailer).
constexpr size_t kStockHeaderBytes = 4624;
constexpr size_t kStockTrailerBytes = 16;  // kStockTrailerMagic, then the file's length (8 bytes)
inline constexpr uint8_t kStockTrailerMagic[8] = {'D', 'X', 'S', 'T', 'K', 'E', 'N', 'D'};
// The file's first bytes: a text-mode transfer or a 7-bit channel breaks them visibly.
inline constexpr uint8_t kStockMagic[8] = {0x89, 'D', 'X', 'S', 'T', 'K', '\r', '\n'};
uint64_t stock_file_bytes(const StockMeta& m);
// Bytes a column takes in a tile: its top and bottom, and the layers held.
uint64_t stock_cell_bytes(const StockMeta& m);

// The meta's header bytes, and the meta of header bytes (checked: magic,
// byte order, version, CRC, then every field's range; *detail names the
// field of a kHeaderValue). Used by the writer and the reader.
void stock_header_encode(const StockMeta& m, uint8_t out[kStockHeaderBytes]);
StockError stock_header_decode(const uint8_t in[kStockHeaderBytes], StockMeta* m, const char** detail);
// A meta's fields in range (as stock_header_decode checks them).
StockError stock_meta_check(const StockMeta& m, const char** detail);

// Writes bytes; false stops the writer (kSink).
using StockSink = bool (*)(void* ctx, const uint8_t* p, size_t n);

// Writes the stock: header, tiles, trailer, through a 4 KiB buffer of its
// own (on the stack). The meta is checked as a reader would (kBadMeta).
StockError stock_write(const StockMeta& m, const StockColumns& c, StockSink sink, void* ctx);

// A reader fed the file in pieces. feed() takes what it is given (*used: all
// of it, or up to an error), but stops at the header's end until the
// columns are bound: the caller then looks at meta(), sets its grid up,
// gives the columns to read into (bind()) and feeds the rest. finish() says
// whether the file ended where it should.
class StockReader {
 public:
  StockReader() = default;
  StockError feed(const uint8_t* p, size_t n, size_t* used);
  bool header_done() const { return phase_ > Phase::kHeader; }
  const StockMeta& meta() const { return meta_; }
  // The columns the tiles are written into (after header_done(), before the
  // first tile byte is fed): tops and bottoms; an optional layer the file
  // holds is read past when its array is null.
  bool bind(const StockColumns& c);
  bool bound() const { return bound_; }
  StockError finish();
  // Where the reader is (the byte an error is at) and, for kHeaderValue and
  // kColumnValue, what was wrong (a static text).
  uint64_t offset() const { return offset_; }
  const char* detail() const { return detail_; }
  bool done() const { return phase_ == Phase::kDone; }

 private:
  enum class Phase : uint8_t { kHeader, kTile, kTileCrc, kTrailer, kDone, kFailed };
  StockError fail(StockError e, const char* detail = "");
  StockError header_parsed();
  StockError tile_checked();
  void tile_start();
  void take_tile_bytes(const uint8_t* p, size_t n);

  Phase phase_ = Phase::kHeader;
  StockMeta meta_{};
  StockColumns cols_{};
  bool bound_ = false;
  uint8_t buf_[kStockHeaderBytes] = {};  // the header, then a tile's CRC, then the trailer
  size_t held_ = 0;
  uint64_t offset_ = 0;
  const char* detail_ = "";
  // tiles
  uint32_t tile_ = 0, ntiles_ = 0;
  int32_t row0_ = 0, rows_ = 0;
  uint64_t tile_at_ = 0;  // bytes of the current tile read
  uint32_t crc_ = 0;
  uint32_t partial_ = 0;  // an element split between two feeds
  int have_ = 0;          // its bytes so far
  StockError last_ = StockError::kOk;
};

}  // namespace dexmill

#endif
