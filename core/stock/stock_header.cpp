// The stock file's header, field by field (core/stock/README.md has the
// table): encoded and decoded by one list of fields, so the two cannot
// disagree; every field little-endian.
#include "core/math/crc32.h"
#include "core/stock/stock_file.h"

namespace dexmill {
namespace {

constexpr uint16_t kByteOrderMark = 0xFEFF;  // FF FE when written little-endian

// One walk over the header: Put writes the fields, Get reads them.
struct Put {
  uint8_t* p;
  size_t at = 0;
  void u(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) p[at++] = static_cast<uint8_t>(v >> (8 * i));
  }
  void i32(int32_t v) { u(static_cast<uint32_t>(v), 4); }
  void i64(int64_t v) { u(static_cast<uint64_t>(v), 8); }
  void u8(uint8_t v) { u(v, 1); }
  void s8(int8_t v) { u(static_cast<uint8_t>(v), 1); }
  void name(const char* s) {
    for (int i = 0; i < kStockNameBytes; ++i) p[at++] = static_cast<uint8_t>(s[i]);
  }
};
struct Get {
  const uint8_t* p;
  size_t at = 0;
  uint64_t u(int n) {
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(p[at++]) << (8 * i);
    return v;
  }
  int32_t i32() { return static_cast<int32_t>(static_cast<uint32_t>(u(4))); }
  int64_t i64() { return static_cast<int64_t>(u(8)); }
  uint8_t u8() { return static_cast<uint8_t>(u(1)); }
  int8_t s8() { return static_cast<int8_t>(u8()); }
  // Padding the writer leaves zero: anything else is not a file it wrote.
  bool pad_ok = true;
  void pad(int n) {
    if (u(n) != 0) pad_ok = false;
  }
  void name(char* s) {
    for (int i = 0; i < kStockNameBytes; ++i) s[i] = static_cast<char>(p[at++]);
  }
};

void put_point(Put* w, const PointNm& q) {
  w->i64(q.x_nm);
  w->i64(q.y_nm);
  w->i64(q.z_nm);
}
PointNm get_point(Get* r) {
  PointNm q;
  q.x_nm = r->i64();
  q.y_nm = r->i64();
  q.z_nm = r->i64();
  return q;
}

// Everything after the 16 bytes of magic, version, mark and size, and
// before the CRC.
void put_body(Put* w, const StockMeta& m) {
  w->u8(static_cast<uint8_t>(m.height_bits));
  w->u8(m.layers);
  w->u8(static_cast<uint8_t>((m.bottoms_zero ? 1 : 0) | (m.have_position ? 2 : 0)));
  w->u8(0);
  w->u(m.tile_rows, 4);
  w->i32(m.geo.nx);
  w->i32(m.geo.ny);
  w->i64(m.geo.x0_nm);
  w->i64(m.geo.y0_nm);
  w->i64(m.geo.pitch_nm);
  w->i64(m.geo.z0_nm);
  w->i64(m.geo.lsb_nm);
  w->i64(m.top_bound_lsb);
  w->i32(m.stock_nx);
  w->i32(m.stock_ny);
  w->i64(m.top_lsb);
  put_point(w, m.stock_lo);
  put_point(w, m.stock_hi);
  w->i32(m.tool);
  put_point(w, m.position);
  w->u(m.removed_lsb_dexels, 8);
  w->i64(m.sim_us);
  w->u(m.moves, 8);
  for (int k = 0; k < 9; ++k) w->s8(m.frame.turn[k]);
  w->u(0, 3);
  for (int k = 0; k < 3; ++k) w->i64(m.frame.offset_half_nm[k]);
  w->name(m.material);
  w->u(m.material_hash, 8);
  w->name(m.design);
  w->u(m.design_hash, 8);
  w->i32(m.prov_slots);
  w->i32(m.prov_ntools);
  w->i32(m.prov_unlisted);
  w->i32(m.prov_current);
  for (int k = 0; k < kStockMaxTools; ++k) w->i32(m.prov_tool[k]);
  w->i32(m.nprograms);
  for (int k = 0; k < kStockMaxPrograms; ++k) {
    const StockProgram& g = m.programs[k];
    w->name(g.name);
    w->u(g.removed_lsb_dexels, 8);
    w->i64(g.sim_us);
    w->u(g.moves, 8);
    for (int e = 0; e < 9; ++e) w->s8(g.setup[e]);
    w->u(0, 3);
    for (int e = 0; e < 3; ++e) w->i64(g.setup_offset_nm[e]);
  }
}

void get_body(Get* r, StockMeta* m) {
  m->height_bits = r->u8();
  m->layers = r->u8();
  const uint8_t flags = r->u8();
  m->bottoms_zero = (flags & 1) != 0;
  m->have_position = (flags & 2) != 0;
  if (flags & ~3) r->pad_ok = false;
  r->pad(1);
  m->tile_rows = static_cast<uint32_t>(r->u(4));
  m->geo.nx = r->i32();
  m->geo.ny = r->i32();
  m->geo.x0_nm = r->i64();
  m->geo.y0_nm = r->i64();
  m->geo.pitch_nm = r->i64();
  m->geo.z0_nm = r->i64();
  m->geo.lsb_nm = r->i64();
  m->top_bound_lsb = r->i64();
  m->stock_nx = r->i32();
  m->stock_ny = r->i32();
  m->top_lsb = r->i64();
  m->stock_lo = get_point(r);
  m->stock_hi = get_point(r);
  m->tool = r->i32();
  m->position = get_point(r);
  m->removed_lsb_dexels = r->u(8);
  m->sim_us = r->i64();
  m->moves = r->u(8);
  for (int k = 0; k < 9; ++k) m->frame.turn[k] = r->s8();
  r->pad(3);
  for (int k = 0; k < 3; ++k) m->frame.offset_half_nm[k] = r->i64();
  r->name(m->material);
  m->material_hash = r->u(8);
  r->name(m->design);
  m->design_hash = r->u(8);
  m->prov_slots = r->i32();
  m->prov_ntools = r->i32();
  m->prov_unlisted = r->i32();
  m->prov_current = r->i32();
  for (int k = 0; k < kStockMaxTools; ++k) m->prov_tool[k] = r->i32();
  m->nprograms = r->i32();
  for (int k = 0; k < kStockMaxPrograms; ++k) {
    StockProgram& g = m->programs[k];
    r->name(g.name);
    g.removed_lsb_dexels = r->u(8);
    g.sim_us = r->i64();
    g.moves = r->u(8);
    for (int e = 0; e < 9; ++e) g.setup[e] = r->s8();
    r->pad(3);
    for (int e = 0; e < 3; ++e) g.setup_offset_nm[e] = r->i64();
  }
}

bool name_ok(const char* s) {
  int n = 0;
  while (n < kStockNameBytes && s[n]) ++n;
  if (n == kStockNameBytes) return false;  // no NUL
  for (int k = n; k < kStockNameBytes; ++k)
    if (s[k]) return false;  // bytes after it: the writer pads with zeros
  return true;
}

// A turn of entries -1, 0, 1 with one non-zero in every row and column: a
// rotation or reflection that maps the lattice onto itself.
bool turn_ok(const int8_t* t) {
  int col_count[3] = {0, 0, 0};
  for (int r = 0; r < 3; ++r) {
    int row_count = 0;
    for (int c = 0; c < 3; ++c) {
      const int8_t v = t[3 * r + c];
      if (v < -1 || v > 1) return false;
      if (v) {
        ++row_count;
        ++col_count[c];
      }
    }
    if (row_count != 1) return false;
  }
  return col_count[0] == 1 && col_count[1] == 1 && col_count[2] == 1;
}

constexpr int64_t kCoordMaxNm = 1000LL * 1000 * 1000000;  // 1 km, as a stock box (core/sim/stock_plan.h)

bool point_ok(const PointNm& p) {
  return p.x_nm >= -kCoordMaxNm && p.x_nm <= kCoordMaxNm && p.y_nm >= -kCoordMaxNm && p.y_nm <= kCoordMaxNm &&
         p.z_nm >= -kCoordMaxNm && p.z_nm <= kCoordMaxNm;
}

}  // namespace

void stock_name_set(char* field, const char* text) {
  for (int k = 0; k < kStockNameBytes; ++k) field[k] = 0;
  int n = 0;
  while (text[n] && n < kStockNameBytes - 1) ++n;
  // Cut before a UTF-8 continuation byte, so the name stays whole characters.
  if (text[n])
    while (n > 0 && (static_cast<uint8_t>(text[n]) & 0xC0) == 0x80) --n;
  for (int k = 0; k < n; ++k) field[k] = text[k];
}

uint64_t stock_cell_bytes(const StockMeta& m) {
  uint64_t per_cell = 2 * static_cast<uint64_t>(m.height_bits / 8);
  if (m.layers & kStockLayerClass) per_cell += 1;
  if (m.layers & kStockLayerLine) per_cell += 4;
  if (m.layers & kStockLayerProgram) per_cell += 1;
  return per_cell;
}

uint64_t stock_file_bytes(const StockMeta& m) {
  const uint64_t cells = static_cast<uint64_t>(m.geo.nx) * static_cast<uint64_t>(m.geo.ny);
  const uint64_t per_cell = stock_cell_bytes(m);
  const uint64_t tiles = m.tile_rows ? (static_cast<uint64_t>(m.geo.ny) + m.tile_rows - 1) / m.tile_rows : 0;
  return kStockHeaderBytes + cells * per_cell + 4 * tiles + kStockTrailerBytes;
}

StockError stock_meta_check(const StockMeta& m, const char** detail) {
  auto bad = [&](const char* what) {
    *detail = what;
    return StockError::kHeaderValue;
  };
  if (m.height_bits != 8 && m.height_bits != 16 && m.height_bits != 32) return bad("height bits (8, 16 or 32)");
  if (m.layers & ~(kStockLayerClass | kStockLayerLine | kStockLayerProgram)) return bad("layers");
  if ((m.layers & kStockLayerProgram) && !(m.layers & kStockLayerLine)) return bad("layers (programs without lines)");
  if (m.tile_rows < 1 || m.tile_rows > 65535) return bad("tile rows (1 to 65535)");
  if (grid_check_geometry(m.geo) != Status::kOk) return bad("grid geometry");
  if (static_cast<int64_t>(m.geo.nx) * m.geo.ny > kStockMaxDexels) return bad("grid size (64 M dexels)");
  const int64_t hmax = (m.height_bits == 32 ? static_cast<int64_t>(0xFFFFFFFFu) : (static_cast<int64_t>(1) << m.height_bits) - 1);
  if (m.top_bound_lsb < 0 || m.top_bound_lsb > hmax) return bad("top bound");
  if (m.top_lsb < 0 || m.top_lsb > hmax) return bad("stock top");
  if (m.stock_nx < 0 || m.stock_ny < 0 || m.stock_nx > m.geo.nx || m.stock_ny > m.geo.ny) return bad("stock size");
  if (!point_ok(m.stock_lo) || !point_ok(m.stock_hi)) return bad("stock box");
  if (!point_ok(m.position)) return bad("tool position");
  if (m.sim_us < 0) return bad("time");
  if (!turn_ok(m.frame.turn)) return bad("part frame");
  for (int k = 0; k < 3; ++k)
    if (m.frame.offset_half_nm[k] < -4 * kCoordMaxNm || m.frame.offset_half_nm[k] > 4 * kCoordMaxNm) return bad("part frame offset");
  if (!name_ok(m.material) || !name_ok(m.design)) return bad("material or design name");
  if (m.prov_ntools < 0 || m.prov_ntools > kStockMaxTools || m.prov_unlisted < 0) return bad("provenance tools");
  if ((m.layers & kStockLayerClass) ? (m.prov_slots < 1 || m.prov_slots > 255) : m.prov_slots != 0)
    return bad("provenance slots");
  if (m.nprograms < 0 || m.nprograms > kStockMaxPrograms) return bad("program count");
  for (int k = 0; k < kStockMaxPrograms; ++k) {
    const StockProgram& g = m.programs[k];
    if (!name_ok(g.name)) return bad("program name");
    if (k >= m.nprograms) {  // unused: zeros, as written
      bool zero = g.name[0] == 0 && g.removed_lsb_dexels == 0 && g.sim_us == 0 && g.moves == 0;
      for (int e = 0; e < 9; ++e) zero = zero && g.setup[e] == 0;
      for (int e = 0; e < 3; ++e) zero = zero && g.setup_offset_nm[e] == 0;
      if (!zero) return bad("unused program entry");
      continue;
    }
    if (g.sim_us < 0) return bad("program time");
    if (!turn_ok(g.setup)) return bad("program setup");
    for (int e = 0; e < 3; ++e)
      if (g.setup_offset_nm[e] < -kCoordMaxNm || g.setup_offset_nm[e] > kCoordMaxNm) return bad("program setup offset");
  }
  return StockError::kOk;
}

void stock_header_encode(const StockMeta& m, uint8_t out[kStockHeaderBytes]) {
  Put w{out};
  for (uint8_t b : kStockMagic) w.u8(b);
  w.u(kStockFileVersion, 2);
  w.u(kByteOrderMark, 2);
  w.u(kStockHeaderBytes, 4);
  put_body(&w, m);
  w.u(crc32_update(0, out, w.at), 4);
}

StockError stock_header_decode(const uint8_t in[kStockHeaderBytes], StockMeta* m, const char** detail) {
  *detail = "";
  for (int k = 0; k < 8; ++k)
    if (in[k] != kStockMagic[k]) return StockError::kNotStock;
  Get r{in, 8};
  const uint64_t version = r.u(2), mark = r.u(2), size = r.u(4);
  if (mark == 0xFFFE) return StockError::kByteOrder;
  if (mark != kByteOrderMark) return StockError::kNotStock;
  if (version != kStockFileVersion || size != kStockHeaderBytes) return StockError::kVersion;
  Get crc{in, kStockHeaderBytes - 4};
  if (crc.u(4) != crc32_update(0, in, kStockHeaderBytes - 4)) return StockError::kHeaderCrc;
  *m = StockMeta{};
  get_body(&r, m);
  if (r.at != kStockHeaderBytes - 4 || !r.pad_ok) {
    *detail = "header padding";
    return StockError::kHeaderValue;
  }
  return stock_meta_check(*m, detail);
}

const char* stock_error_message(StockError e) {
  switch (e) {
    case StockError::kOk: return "ok";
    case StockError::kNotStock: return "not a dexmill stock file (.dxstock)";
    case StockError::kByteOrder: return "a stock file of the other byte order (this reader reads little-endian files only)";
    case StockError::kVersion: return "a stock file of a version this dexmill does not read (it reads version 1)";
    case StockError::kHeaderCrc: return "the stock file's header is corrupt (CRC mismatch)";
    case StockError::kHeaderValue: return "the stock file's header holds a value out of range";
    case StockError::kTileCrc: return "the stock file's columns are corrupt (a tile's CRC mismatch)";
    case StockError::kColumnValue: return "the stock file holds a column out of range";
    case StockError::kTruncated: return "the stock file is truncated";
    case StockError::kTrailer: return "the stock file's end is not where its header says";
    case StockError::kTooLong: return "the stock file has bytes after its end";
    case StockError::kSink: return "the stock could not be written";
    case StockError::kBadMeta: return "the stock to write is not a valid stock";
  }
  return "unknown stock error";
}

}  // namespace dexmill
