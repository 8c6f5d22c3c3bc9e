// core/stock/stock_transform.h: setups are exact. Flip then flip back,
// four quarter turns, a quarter turn and its inverse give the same bits
// (every height format, every layer); a column lands where the turn about
// the box's centre puts its axis; a flipped column's interval is the
// mirrored one (a hole stays a hole, a floor becomes the new bottom);
// volume is kept; the part's frame maps each new place back to the old
// one; offsets off the lattice are refused with the nearest exact one.
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/stock/stock_transform.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;
using t::Rng;

namespace {

struct Stock {
  StockMeta meta;
  std::vector<uint8_t> top, bottom;  // heights as bytes of the meta's format
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
  size_t cells() const { return static_cast<size_t>(meta.geo.nx) * static_cast<size_t>(meta.geo.ny); }
  uint32_t height(const std::vector<uint8_t>& v, size_t k) const {
    uint32_t h = 0;
    const int hb = meta.height_bits / 8;
    for (int b = 0; b < hb; ++b) h |= static_cast<uint32_t>(v[k * hb + b]) << (8 * b);
    return h;
  }
  void set(std::vector<uint8_t>* v, size_t k, uint32_t h) const {
    const int hb = meta.height_bits / 8;
    // Native order: the columns are the engine's arrays, not file bytes.
    if (hb == 1) (*v)[k] = static_cast<uint8_t>(h);
    if (hb == 2) {
      const uint16_t x = static_cast<uint16_t>(h);
      std::memcpy(&(*v)[2 * k], &x, 2);
    }
    if (hb == 4) std::memcpy(&(*v)[4 * k], &h, 4);
  }
  uint32_t get(const std::vector<uint8_t>& v, size_t k) const {
    const int hb = meta.height_bits / 8;
    if (hb == 1) return v[k];
    if (hb == 2) {
      uint16_t x;
      std::memcpy(&x, &v[2 * k], 2);
      return x;
    }
    uint32_t x;
    std::memcpy(&x, &v[4 * k], 4);
    return x;
  }
};

// A stock like a plan makes it (core/sim/stock_plan.cpp): border holes,
// the box's edges on dexel axes; random cut columns and holes inside.
Stock make_stock(int bits, int32_t ux, int32_t uy, int64_t pitch, uint64_t seed) {
  Stock s;
  StockMeta& m = s.meta;
  m.height_bits = bits;
  m.layers = kStockLayerClass | kStockLayerLine | kStockLayerProgram;
  m.geo = GridGeometry{ux + 2, uy + 2, 1000 - pitch, -3000 - pitch, pitch, -20000000, 1000};
  m.stock_nx = ux;
  m.stock_ny = uy;
  m.top_lsb = bits == 8 ? 200 : 20000;
  m.top_bound_lsb = m.top_lsb;
  m.stock_lo = PointNm{1000, -3000, -20000000};
  m.stock_hi = PointNm{1000 + (ux - 1) * pitch, -3000 + (uy - 1) * pitch, -20000000 + m.top_lsb * 1000};
  m.prov_slots = 7;
  m.nprograms = 2;
  for (int k = 0; k < 2; ++k) m.programs[k].setup[0] = m.programs[k].setup[4] = m.programs[k].setup[8] = 1;
  const size_t n = s.cells();
  s.top.assign(n * (bits / 8), 0);
  s.bottom.assign(n * (bits / 8), 0);
  s.cls.resize(n);
  s.line.resize(n);
  s.program.resize(n);
  Rng rng(seed);
  for (int32_t j = 0; j < m.geo.ny; ++j)
    for (int32_t i = 0; i < m.geo.nx; ++i) {
      const size_t k = static_cast<size_t>(j) * m.geo.nx + i;
      const bool border = i == 0 || j == 0 || i == m.geo.nx - 1 || j == m.geo.ny - 1;
      const int kind = static_cast<int>(rng.range(0, 9));
      uint32_t t = 0, b = 0;
      if (!border && kind > 0) {
        t = static_cast<uint32_t>(rng.range(1, m.top_lsb));
        b = kind == 9 ? static_cast<uint32_t>(rng.range(0, t - 1)) : 0;  // a few raised bottoms
      }
      s.set(&s.top, k, t);
      s.set(&s.bottom, k, b);
      s.cls[k] = static_cast<uint8_t>(rng.range(0, 7));
      s.line[k] = static_cast<uint32_t>(rng.next());
      s.program[k] = static_cast<uint8_t>(rng.range(0, 1));
    }
  return s;
}

bool same_meta(const StockMeta& a, const StockMeta& b) {
  return a.geo.nx == b.geo.nx && a.geo.ny == b.geo.ny && a.geo.x0_nm == b.geo.x0_nm && a.geo.y0_nm == b.geo.y0_nm &&
         a.geo.z0_nm == b.geo.z0_nm && a.stock_nx == b.stock_nx && a.stock_ny == b.stock_ny &&
         a.stock_lo == b.stock_lo && a.stock_hi == b.stock_hi && std::memcmp(a.frame.turn, b.frame.turn, 9) == 0 &&
         a.frame.offset_half_nm[0] == b.frame.offset_half_nm[0] && a.frame.offset_half_nm[1] == b.frame.offset_half_nm[1] &&
         a.frame.offset_half_nm[2] == b.frame.offset_half_nm[2] && a.bottoms_zero == b.bottoms_zero;
}
bool same_columns(const Stock& a, const Stock& b) {
  return a.top == b.top && a.bottom == b.bottom && a.cls == b.cls && a.line == b.line && a.program == b.program;
}

StockSetupError setup(Stock* s, const StockSetup& u, std::vector<uint32_t>* scratch) {
  scratch->assign(stock_setup_scratch_bytes(s->meta, u) / 4 + 1, 0);
  return stock_apply_setup(u, &s->meta, s->cols(), scratch->data(), scratch->size() * 4);
}

StockSetup flip_x() {
  StockSetup u;
  u.flip_x = true;
  return u;
}
StockSetup flip_y() {
  StockSetup u;
  u.flip_y = true;
  return u;
}
StockSetup turns(int n) {
  StockSetup u;
  u.quarter_turns = n;
  return u;
}

// The machine point of column (i, j)'s axis at height h.
PointNm axis_of(const StockMeta& m, int32_t i, int32_t j, uint32_t h) {
  return PointNm{m.geo.x0_nm + i * m.geo.pitch_nm, m.geo.y0_nm + j * m.geo.pitch_nm, m.geo.z0_nm + h * m.geo.lsb_nm};
}
// The part frame's image of a machine point, in half nm.
void part_of(const StockFrame& f, const PointNm& p, int64_t out[3]) {
  const int64_t v[3] = {2 * p.x_nm, 2 * p.y_nm, 2 * p.z_nm};
  for (int r = 0; r < 3; ++r) out[r] = f.turn[3 * r] * v[0] + f.turn[3 * r + 1] * v[1] + f.turn[3 * r + 2] * v[2] + f.offset_half_nm[r];
}

}  // namespace

TEST(stock_setups_undone_give_the_same_bits) {
  int runs = 0;
  for (int bits : {8, 16, 32})
    for (int shape = 0; shape < 2; ++shape) {
      const Stock orig = make_stock(bits, shape ? 17 : 13, 13, 250000, 40 + bits + shape);
      std::vector<uint32_t> scratch;
      const StockSetup pairs[][2] = {{flip_x(), flip_x()}, {flip_y(), flip_y()}, {turns(1), turns(3)},
                                     {turns(2), turns(2)}, {turns(3), turns(1)}};
      for (const auto& pr : pairs) {
        Stock s = orig;
        CHECK_EQ(setup(&s, pr[0], &scratch), StockSetupError::kOk);
        CHECK(!same_columns(s, orig));  // it moved something
        CHECK_EQ(setup(&s, pr[1], &scratch), StockSetupError::kOk);
        CHECK(same_columns(s, orig));
        CHECK(same_meta(s.meta, orig.meta));
        ++runs;
      }
      // Four quarter turns, one at a time; and both flips are half a turn.
      Stock s = orig;
      for (int k = 0; k < 4; ++k) CHECK_EQ(setup(&s, turns(1), &scratch), StockSetupError::kOk);
      CHECK(same_columns(s, orig));
      CHECK(same_meta(s.meta, orig.meta));
      Stock a = orig, b = orig;
      StockSetup both;
      both.flip_x = both.flip_y = true;
      CHECK_EQ(setup(&a, both, &scratch), StockSetupError::kOk);
      CHECK_EQ(setup(&b, turns(2), &scratch), StockSetupError::kOk);
      CHECK(same_columns(a, b));
      ++runs;
    }
  CHECK_EQ(runs, 3 * 2 * 6);
}

TEST(stock_setup_puts_each_column_where_the_turn_takes_its_axis) {
  for (int turn = 0; turn < 4; ++turn)
    for (int flips = 0; flips < 3; ++flips) {
      const Stock orig = make_stock(16, 21, 12, 500000, 7 + turn);
      Stock s = orig;
      StockSetup u = turns(turn);
      u.flip_x = flips == 1;
      u.flip_y = flips == 2;
      std::vector<uint32_t> scratch;
      CHECK_EQ(setup(&s, u, &scratch), StockSetupError::kOk);
      // The box keeps its centre; a quarter turn swaps its extents.
      const StockMeta& a = orig.meta;
      const StockMeta& b = s.meta;
      CHECK_EQ(a.stock_lo.x_nm + a.stock_hi.x_nm, b.stock_lo.x_nm + b.stock_hi.x_nm);
      CHECK_EQ(a.stock_lo.y_nm + a.stock_hi.y_nm, b.stock_lo.y_nm + b.stock_hi.y_nm);
      const bool swapped = turn % 2 == 1;
      CHECK_EQ(b.stock_hi.x_nm - b.stock_lo.x_nm, swapped ? a.stock_hi.y_nm - a.stock_lo.y_nm : a.stock_hi.x_nm - a.stock_lo.x_nm);
      CHECK_EQ(b.geo.nx, swapped ? a.geo.ny : a.geo.nx);
      // Every column: the frame maps its new axis (and its interval's ends)
      // back to the old machine place, and the heights are the old ones,
      // mirrored in z for a flip.
      size_t wrong = 0;
      uint64_t vol_a = 0, vol_b = 0;
      for (int32_t j = 0; j < b.geo.ny; ++j)
        for (int32_t i = 0; i < b.geo.nx; ++i) {
          const size_t k = static_cast<size_t>(j) * b.geo.nx + i;
          const uint32_t t = s.get(s.top, k), w = s.get(s.bottom, k);
          vol_b += t - w;
          const uint32_t probe = t == w ? 0 : t;  // a hole: the axis at the bottom of the box
          int64_t part[3];
          part_of(b.frame, axis_of(b, i, j, probe), part);
          // The old column under that part point.
          const int64_t oi2 = part[0] - 2 * a.geo.x0_nm, oj2 = part[1] - 2 * a.geo.y0_nm;
          if (oi2 % (2 * a.geo.pitch_nm) || oj2 % (2 * a.geo.pitch_nm)) { ++wrong; continue; }
          const int32_t oi = static_cast<int32_t>(oi2 / (2 * a.geo.pitch_nm)), oj = static_cast<int32_t>(oj2 / (2 * a.geo.pitch_nm));
          if (oi < 0 || oj < 0 || oi >= a.geo.nx || oj >= a.geo.ny) { ++wrong; continue; }
          const size_t ok_ = static_cast<size_t>(oj) * a.geo.nx + oi;
          const uint32_t ot = orig.get(orig.top, ok_), ob = orig.get(orig.bottom, ok_);
          if (s.cls[k] != orig.cls[ok_] || s.line[k] != orig.line[ok_] || s.program[k] != orig.program[ok_]) ++wrong;
          if (ot == ob) {
            if (t != 0 || w != 0) ++wrong;  // a hole stays a hole
            continue;
          }
          // The new top's z is the old column's top or, flipped, its bottom.
          const int64_t want_z2 = 2 * (a.geo.z0_nm + static_cast<int64_t>(flips ? ob : ot) * a.geo.lsb_nm);
          if (part[2] != want_z2) ++wrong;
        }
      for (size_t k = 0; k < orig.cells(); ++k) vol_a += orig.get(orig.top, k) - orig.get(orig.bottom, k);
      CHECK_EQ(wrong, 0u);
      CHECK_EQ(vol_a, vol_b);
    }
}

TEST(stock_setup_flip_shows_the_first_side_from_below) {
  // One column cut 3 mm down from a 20 mm top, one drilled through.
  Stock s = make_stock(16, 5, 5, 1000000, 3);
  for (size_t k = 0; k < s.cells(); ++k) {
    s.set(&s.top, k, 20000);
    s.set(&s.bottom, k, 0);
  }
  const size_t pocket = 2 * 7 + 2, hole = 3 * 7 + 4;
  s.set(&s.top, pocket, 17000);
  s.set(&s.top, hole, 0);
  s.meta.bottoms_zero = true;
  std::vector<uint32_t> scratch;
  CHECK_EQ(setup(&s, flip_x(), &scratch), StockSetupError::kOk);
  // flip-x mirrors rows: row j goes to 6 - j.
  const size_t pocket_after = (6 - 2) * 7 + 2, hole_after = (6 - 3) * 7 + 4;
  CHECK_EQ(s.get(s.top, pocket_after), 20000u);
  CHECK_EQ(s.get(s.bottom, pocket_after), 3000u);  // the first side's floor is the new bottom
  CHECK_EQ(s.get(s.top, hole_after), 0u);
  CHECK_EQ(s.get(s.bottom, hole_after), 0u);
  CHECK(!s.meta.bottoms_zero);
}

TEST(stock_setup_refuses_what_is_not_exact) {
  const Stock orig = make_stock(16, 9, 6, 250000, 5);
  std::vector<uint32_t> scratch;
  {  // an offset off the lattice: the nearest exact one, nothing changed
    Stock s = orig;
    StockSetup u;
    u.offset_nm = PointNm{300000, -100000, 1500};
    PointNm nearest{0, 0, 0};
    CHECK_EQ(stock_apply_setup(u, &s.meta, s.cols(), nullptr, 0, &nearest), StockSetupError::kOffsetNotExact);
    CHECK(nearest == (PointNm{250000, 0, 2000}));
    CHECK(same_columns(s, orig));
    CHECK(same_meta(s.meta, orig.meta));
    u.offset_nm = nearest;  // that one moves the grid, exactly
    CHECK_EQ(stock_apply_setup(u, &s.meta, s.cols(), nullptr, 0), StockSetupError::kOk);
    CHECK_EQ(s.meta.geo.x0_nm, orig.meta.geo.x0_nm + 250000);
    CHECK_EQ(s.meta.geo.z0_nm, orig.meta.geo.z0_nm + 2000);
    CHECK(same_columns(s, orig));
  }
  {  // a quarter turn of a non-square grid without scratch
    Stock s = orig;
    CHECK_EQ(stock_apply_setup(turns(1), &s.meta, s.cols(), nullptr, 0), StockSetupError::kScratch);
    CHECK(same_columns(s, orig));
  }
  {  // a quarter turn whose lattice falls on half nanometres
    Stock s = make_stock(16, 10, 7, 333, 6);
    const Stock before = s;
    CHECK_EQ(setup(&s, turns(1), &scratch), StockSetupError::kCentreNotExact);
    CHECK(same_columns(s, before));
  }
  {  // a top above the box
    Stock s = orig;
    s.set(&s.top, 10, static_cast<uint32_t>(s.meta.top_lsb + 1));
    s.meta.top_bound_lsb = s.meta.top_lsb + 1;
    const Stock before = s;
    CHECK_EQ(setup(&s, flip_y(), &scratch), StockSetupError::kTopAboveStock);
    CHECK(same_columns(s, before));
  }
}

TEST(stock_setup_record_composes_setups_as_one) {
  // Two setups in a row, recorded as the chain records a program's, and
  // read back as one setup: that one setup does to the stock exactly what
  // the two did, columns and meta, for every pair of the eight turns.
  int pairs = 0;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      StockSetup sa = turns(a % 4), sb = turns(b % 4);
      sa.flip_x = a >= 4;
      sb.flip_y = b >= 4;
      sa.offset_nm = PointNm{250000, 0, 3000};
      sb.offset_nm = PointNm{-500000, 250000, 0};
      int8_t turn[9] = {};
      int64_t offset[3] = {0, 0, 0};
      stock_setup_record(sa, turn, offset);
      stock_setup_record(sb, turn, offset);
      StockSetup one;
      CHECK(stock_setup_of_record(turn, offset, &one));
      Stock two_steps = make_stock(16, 13, 13, 250000, 7 + a), one_step = two_steps;
      std::vector<uint32_t> scratch;
      CHECK(setup(&two_steps, sa, &scratch) == StockSetupError::kOk);
      CHECK(setup(&two_steps, sb, &scratch) == StockSetupError::kOk);
      CHECK(setup(&one_step, one, &scratch) == StockSetupError::kOk);
      CHECK(same_meta(two_steps.meta, one_step.meta));
      CHECK(same_columns(two_steps, one_step));
      ++pairs;
    }
  CHECK_EQ(pairs, 64);
  // Identity records as no setup; a matrix no setup makes is refused.
  int8_t id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, odd[9] = {0, 0, 1, 0, 1, 0, 1, 0, 0};
  const int64_t zero[3] = {0, 0, 0};
  StockSetup s;
  CHECK(stock_setup_of_record(id, zero, &s) && s.identity());
  CHECK(!stock_setup_of_record(odd, zero, &s));
}
