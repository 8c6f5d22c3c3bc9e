// core/stock/stock_transform.h: setups as permutations of the columns and
// exact maps of the heights, one step at a time (flip about X, flip about
// Y, each quarter turn, the offset), with the part's frame and the box
// carried along.
#include "core/stock/stock_transform.h"

namespace dexmill {
namespace {

// A 3x3 integer matrix, row-major.
struct Mat3 {
  int8_t a[9];
};
Mat3 mul(const Mat3& x, const Mat3& y) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int v = 0;
      for (int k = 0; k < 3; ++k) v += x.a[3 * i + k] * y.a[3 * k + j];
      r.a[3 * i + j] = static_cast<int8_t>(v);
    }
  return r;
}
Mat3 transpose(const Mat3& x) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.a[3 * i + j] = x.a[3 * j + i];
  return r;
}
void apply(const Mat3& m, const int64_t v[3], int64_t out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = m.a[3 * i] * v[0] + m.a[3 * i + 1] * v[1] + m.a[3 * i + 2] * v[2];
}

// One step's linear part (about the box's centre).
enum class Step : uint8_t { kFlipX, kFlipY, kQuarter };
Mat3 step_matrix(Step s) {
  switch (s) {
    case Step::kFlipX: return Mat3{{1, 0, 0, 0, -1, 0, 0, 0, -1}};
    case Step::kFlipY: return Mat3{{-1, 0, 0, 0, 1, 0, 0, 0, -1}};
    default: return Mat3{{0, -1, 0, 1, 0, 0, 0, 0, 1}};  // counterclockwise seen from above
  }
}

// The part's frame after the machine moved by p' = R (p - c) + c + o
// (all doubled: half nanometres): 2 part = F R^T 2p' + F (2c - R^T (2c + 2o)) + f.
void carry_frame(StockFrame* f, const Mat3& r, const int64_t c2[3], const int64_t o2[3]) {
  Mat3 fm;
  for (int k = 0; k < 9; ++k) fm.a[k] = f->turn[k];
  const Mat3 rt = transpose(r);
  int64_t t[3] = {c2[0] + o2[0], c2[1] + o2[1], c2[2] + o2[2]}, rt_t[3], d[3], fd[3];
  apply(rt, t, rt_t);
  for (int k = 0; k < 3; ++k) d[k] = c2[k] - rt_t[k];
  apply(fm, d, fd);
  const Mat3 nf = mul(fm, rt);
  for (int k = 0; k < 9; ++k) f->turn[k] = nf.a[k];
  for (int k = 0; k < 3; ++k) f->offset_half_nm[k] += fd[k];
}

void box_centre2(const StockMeta& m, int64_t c2[3]) {
  c2[0] = m.stock_lo.x_nm + m.stock_hi.x_nm;
  c2[1] = m.stock_lo.y_nm + m.stock_hi.y_nm;
  c2[2] = m.stock_lo.z_nm + m.stock_hi.z_nm;
}

// The meta after one step (geometry, plan, box, frame).
void meta_step(Step s, StockMeta* m) {
  int64_t c2[3];
  box_centre2(*m, c2);
  const int64_t zero[3] = {0, 0, 0};
  carry_frame(&m->frame, step_matrix(s), c2, zero);
  if (s != Step::kQuarter) return;  // a flip keeps the grid and the box where they are
  GridGeometry& g = m->geo;
  const int64_t p = g.pitch_nm, nx = g.nx, ny = g.ny;
  g.x0_nm += (nx - ny) * p / 2;
  g.y0_nm += (ny - nx) * p / 2;
  g.nx = static_cast<int32_t>(ny);
  g.ny = static_cast<int32_t>(nx);
  const int32_t snx = m->stock_nx;
  m->stock_nx = m->stock_ny;
  m->stock_ny = snx;
  const int64_t hx = m->stock_hi.x_nm - m->stock_lo.x_nm, hy = m->stock_hi.y_nm - m->stock_lo.y_nm;
  m->stock_lo.x_nm += (hx - hy) / 2;
  m->stock_hi.x_nm = m->stock_lo.x_nm + hy;
  m->stock_lo.y_nm += (hy - hx) / 2;
  m->stock_hi.y_nm = m->stock_lo.y_nm + hx;
}

void meta_offset(const PointNm& o, StockMeta* m) {
  int64_t c2[3];
  box_centre2(*m, c2);
  const int64_t o2[3] = {2 * o.x_nm, 2 * o.y_nm, 2 * o.z_nm};
  carry_frame(&m->frame, Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}}, c2, o2);
  m->geo.x0_nm += o.x_nm;
  m->geo.y0_nm += o.y_nm;
  m->geo.z0_nm += o.z_nm;
  m->stock_lo = PointNm{m->stock_lo.x_nm + o.x_nm, m->stock_lo.y_nm + o.y_nm, m->stock_lo.z_nm + o.z_nm};
  m->stock_hi = PointNm{m->stock_hi.x_nm + o.x_nm, m->stock_hi.y_nm + o.y_nm, m->stock_hi.z_nm + o.z_nm};
}

// ---- the columns

// Layer k of the columns (0 tops, 1 bottoms, 2 classes, 3 lines, 4
// programs) and its element size; null when not given.
void* layer_of(const StockColumns& c, int k, int height_bytes, int* es) {
  switch (k) {
    case 0: *es = height_bytes; return c.top;
    case 1: *es = height_bytes; return c.bottom;
    case 2: *es = 1; return c.cls;
    case 3: *es = 4; return c.line;
    default: *es = 1; return c.program;
  }
}

template <class T>
void mirror_rows(T* v, int32_t nx, int32_t ny) {
  for (int32_t j = 0, jj = ny - 1; j < jj; ++j, --jj)
    for (int32_t i = 0; i < nx; ++i) {
      T& a = v[static_cast<size_t>(j) * nx + i];
      T& b = v[static_cast<size_t>(jj) * nx + i];
      const T t = a;
      a = b;
      b = t;
    }
}
template <class T>
void mirror_columns(T* v, int32_t nx, int32_t ny) {
  for (int32_t j = 0; j < ny; ++j) {
    T* row = v + static_cast<size_t>(j) * nx;
    for (int32_t i = 0, ii = nx - 1; i < ii; ++i, --ii) {
      const T t = row[i];
      row[i] = row[ii];
      row[ii] = t;
    }
  }
}
// new(ny - 1 - j, i) = old(i, j): the new grid is ny wide.
template <class T>
void quarter(T* v, int32_t nx, int32_t ny, T* scratch) {
  const size_t n = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  if (nx == ny) {  // in place, four columns at a time
    const int32_t s = nx;
    for (int32_t j = 0; j < s / 2; ++j)
      for (int32_t i = j; i < s - 1 - j; ++i) {
        // (i, j) -> (s-1-j, i) -> (s-1-i, s-1-j) -> (j, s-1-i) -> (i, j)
        T& a = v[static_cast<size_t>(j) * s + i];
        T& b = v[static_cast<size_t>(i) * s + (s - 1 - j)];
        T& c = v[static_cast<size_t>(s - 1 - j) * s + (s - 1 - i)];
        T& d = v[static_cast<size_t>(s - 1 - i) * s + j];
        const T t = d;
        d = c;
        c = b;
        b = a;
        a = t;
      }
    return;
  }
  for (size_t k = 0; k < n; ++k) scratch[k] = v[k];
  for (int32_t j = 0; j < ny; ++j)
    for (int32_t i = 0; i < nx; ++i)
      v[static_cast<size_t>(i) * ny + (ny - 1 - j)] = scratch[static_cast<size_t>(j) * nx + i];
}

template <class T>
void permute(Step s, T* v, int32_t nx, int32_t ny, void* scratch) {
  switch (s) {
    case Step::kFlipX: mirror_rows(v, nx, ny); break;
    case Step::kFlipY: mirror_columns(v, nx, ny); break;
    default: quarter(v, nx, ny, static_cast<T*>(scratch)); break;
  }
}

void permute_layer(Step s, void* v, int es, int32_t nx, int32_t ny, void* scratch) {
  switch (es) {
    case 1: permute(s, static_cast<uint8_t*>(v), nx, ny, scratch); break;
    case 2: permute(s, static_cast<uint16_t*>(v), nx, ny, scratch); break;
    default: permute(s, static_cast<uint32_t*>(v), nx, ny, scratch); break;
  }
}

// z mirrored about the box's middle: [b, t] -> [T - t, T - b], T the
// stock's top; a hole (or an empty column) stays a hole.
template <class H>
bool mirror_z(H* top, H* bottom, size_t n, int64_t t_lsb) {
  bool bottoms_zero = true;
  for (size_t k = 0; k < n; ++k) {
    const int64_t t = top[k], b = bottom[k];
    if (t == b) {
      top[k] = bottom[k] = 0;
    } else {
      top[k] = static_cast<H>(t_lsb - b);
      bottom[k] = static_cast<H>(t_lsb - t);
    }
    bottoms_zero = bottoms_zero && bottom[k] == 0;
  }
  return bottoms_zero;
}

template <class H>
bool tops_within(const H* top, size_t n, int64_t t_lsb) {
  for (size_t k = 0; k < n; ++k)
    if (static_cast<int64_t>(top[k]) > t_lsb) return false;
  return true;
}

bool heights_within(const StockColumns& c, int bits, size_t n, int64_t t_lsb) {
  switch (bits) {
    case 8: return tops_within(static_cast<const uint8_t*>(c.top), n, t_lsb);
    case 16: return tops_within(static_cast<const uint16_t*>(c.top), n, t_lsb);
    default: return tops_within(static_cast<const uint32_t*>(c.top), n, t_lsb);
  }
}

bool heights_mirror(const StockColumns& c, int bits, size_t n, int64_t t_lsb) {
  switch (bits) {
    case 8: return mirror_z(static_cast<uint8_t*>(c.top), static_cast<uint8_t*>(c.bottom), n, t_lsb);
    case 16: return mirror_z(static_cast<uint16_t*>(c.top), static_cast<uint16_t*>(c.bottom), n, t_lsb);
    default: return mirror_z(static_cast<uint32_t*>(c.top), static_cast<uint32_t*>(c.bottom), n, t_lsb);
  }
}

void columns_step(Step s, StockMeta* m, const StockColumns& c, void* scratch) {
  const size_t n = static_cast<size_t>(m->geo.nx) * static_cast<size_t>(m->geo.ny);
  for (int k = 0; k < 5; ++k) {
    int es = 0;
    if (void* v = layer_of(c, k, m->height_bits / 8, &es)) permute_layer(s, v, es, m->geo.nx, m->geo.ny, scratch);
  }
  if (s != Step::kQuarter) {
    m->bottoms_zero = heights_mirror(c, m->height_bits, n, m->top_lsb);
    if (m->top_bound_lsb < m->top_lsb) m->top_bound_lsb = m->top_lsb;
  }
}

}  // namespace

const char* stock_setup_message(StockSetupError e) {
  switch (e) {
    case StockSetupError::kOk: return "ok";
    case StockSetupError::kOffsetNotExact:
      return "a setup's offset must be whole dexels in X and Y and whole height steps in Z (anything else would "
             "resample the stock)";
    case StockSetupError::kCentreNotExact:
      return "a quarter turn of this stock puts its dexels between nanometres (its X and Y sizes differ by an odd "
             "number of nanometres)";
    case StockSetupError::kScratch: return "a quarter turn of a grid that is not square needs scratch memory";
    case StockSetupError::kTopAboveStock: return "the stock has a top above its box, which a flip cannot mirror";
    case StockSetupError::kOutOfRange: return "the setup moves the stock out of the grid's range";
  }
  return "unknown setup error";
}

size_t stock_setup_scratch_bytes(const StockMeta& m, const StockSetup& s) {
  if (s.quarter_turns % 4 == 0 || m.geo.nx == m.geo.ny) return 0;
  return static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny) * 4;  // the widest layer: lines, 32-bit heights
}

StockSetupError stock_setup_meta(const StockSetup& s, StockMeta* m, PointNm* nearest) {
  const int turns = ((s.quarter_turns % 4) + 4) % 4;
  const int64_t p = m->geo.pitch_nm, lsb = m->geo.lsb_nm;
  const PointNm& o = s.offset_nm;
  if (o.x_nm % p || o.y_nm % p || o.z_nm % lsb) {
    if (nearest)
      *nearest = PointNm{div_round(o.x_nm, p) * p, div_round(o.y_nm, p) * p, div_round(o.z_nm, lsb) * lsb};
    return StockSetupError::kOffsetNotExact;
  }
  if (turns % 2 && ((static_cast<int64_t>(m->geo.nx) - m->geo.ny) * p) % 2) return StockSetupError::kCentreNotExact;
  StockMeta after = *m;
  if (s.flip_x) meta_step(Step::kFlipX, &after);
  if (s.flip_y) meta_step(Step::kFlipY, &after);
  for (int k = 0; k < turns; ++k) meta_step(Step::kQuarter, &after);
  meta_offset(o, &after);
  const char* detail = "";
  if (stock_meta_check(after, &detail) != StockError::kOk) return StockSetupError::kOutOfRange;
  // A flip leaves no bottom at 0 in general and tops up to the box's top.
  if (s.flip_x != s.flip_y) {
    after.bottoms_zero = false;
    if (after.top_bound_lsb < after.top_lsb) after.top_bound_lsb = after.top_lsb;
  }
  *m = after;
  return StockSetupError::kOk;
}

StockSetupError stock_apply_setup(const StockSetup& s, StockMeta* m, const StockColumns& c, void* scratch,
                                  size_t scratch_bytes, PointNm* nearest) {
  const int turns = ((s.quarter_turns % 4) + 4) % 4;
  // The meta first, on a copy: exact and in range before any column moves.
  StockMeta after = *m;
  if (const StockSetupError e = stock_setup_meta(s, &after, nearest); e != StockSetupError::kOk) return e;
  if (stock_setup_scratch_bytes(*m, s) > 0 && (!scratch || scratch_bytes < stock_setup_scratch_bytes(*m, s)))
    return StockSetupError::kScratch;
  const size_t n = static_cast<size_t>(m->geo.nx) * static_cast<size_t>(m->geo.ny);
  if ((s.flip_x || s.flip_y) && !heights_within(c, m->height_bits, n, m->top_lsb)) return StockSetupError::kTopAboveStock;
  if (s.flip_x) columns_step(Step::kFlipX, m, c, scratch);
  if (s.flip_y) columns_step(Step::kFlipY, m, c, scratch);
  for (int k = 0; k < turns; ++k) {
    columns_step(Step::kQuarter, m, c, scratch);
    meta_step(Step::kQuarter, m);  // the next turn's grid is this one's turned
  }
  after.bottoms_zero = m->bottoms_zero;
  after.top_bound_lsb = m->top_bound_lsb;
  *m = after;
  return StockSetupError::kOk;
}

namespace {

// The setup's linear part: the flips first, then the quarter turns.
Mat3 setup_matrix(const StockSetup& s) {
  Mat3 m{{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  if (s.flip_x) m = mul(step_matrix(Step::kFlipX), m);
  if (s.flip_y) m = mul(step_matrix(Step::kFlipY), m);
  for (int k = 0; k < ((s.quarter_turns % 4) + 4) % 4; ++k) m = mul(step_matrix(Step::kQuarter), m);
  return m;
}

bool same(const Mat3& x, const Mat3& y) {
  for (int k = 0; k < 9; ++k)
    if (x.a[k] != y.a[k]) return false;
  return true;
}

}  // namespace

void stock_setup_record(const StockSetup& s, int8_t turn[9], int64_t offset_nm[3]) {
  Mat3 t;
  bool zero = true;
  for (int k = 0; k < 9; ++k) zero = zero && turn[k] == 0;
  for (int k = 0; k < 9; ++k) t.a[k] = zero ? static_cast<int8_t>(k % 4 == 0) : turn[k];
  const Mat3 r = mul(setup_matrix(s), t);
  for (int k = 0; k < 9; ++k) turn[k] = r.a[k];
  offset_nm[0] += s.offset_nm.x_nm;
  offset_nm[1] += s.offset_nm.y_nm;
  offset_nm[2] += s.offset_nm.z_nm;
}

bool stock_setup_of_record(const int8_t turn[9], const int64_t offset_nm[3], StockSetup* out) {
  Mat3 t;
  for (int k = 0; k < 9; ++k) t.a[k] = turn[k];
  StockSetup s;
  s.offset_nm = PointNm{offset_nm[0], offset_nm[1], offset_nm[2]};
  // The fewest words: flip-y alone before flip-x and a half turn.
  const bool flips[2][2] = {{true, false}, {false, true}};
  for (int q = 0; q < 4; ++q)
    for (const auto& f : flips) {
      s.flip_x = turn[8] < 0 && f[0];
      s.flip_y = turn[8] < 0 && f[1];
      s.quarter_turns = q;
      if (same(setup_matrix(s), t)) return *out = s, true;
    }
  return false;
}

}  // namespace dexmill
