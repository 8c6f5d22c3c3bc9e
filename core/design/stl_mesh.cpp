// STL meshes from bytes; see stl_mesh.h.
#include "core/design/stl_mesh.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

uint32_t le32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}

bool space(uint8_t c) { return c == ' ' || (c >= '\t' && c <= '\r'); }  // C's isspace
uint8_t lower(uint8_t c) { return c >= 'A' && c <= 'Z' ? static_cast<uint8_t>(c + 32) : c; }

// A coordinate: q nm (and one more when rounded up), negated, `offset`
// added; or beyond 10 m.
enum class Coord : uint8_t { kOk, kBeyond };

Coord finish_nm(bool negative, uint64_t q, bool up, bool beyond, int64_t offset, int64_t* nm) {
  if (beyond) return Coord::kBeyond;
  const int64_t v = static_cast<int64_t>(q + (up ? 1 : 0));
  *nm = (negative ? -v : v) + offset;
  return Coord::kOk;
}

// A binary facet's float, exactly: its value times 1e6 is an integer
// times a power of two (the hosted reader's double arithmetic is exact too).
Coord float_nm(uint32_t bits, int64_t offset, int64_t* nm, bool* nan) {
  const uint32_t e = bits >> 23 & 0xff;
  uint64_t m = bits & 0x7fffff;
  *nan = false;
  if (e == 0xff) {  // infinite or NaN: "not a number", as the hosted reader said of either
    *nan = true;
    return Coord::kBeyond;
  }
  if (e) m |= 0x800000;
  if (e >= 150) return m ? Coord::kBeyond : finish_nm(false, 0, false, false, offset, nm);  // 2^23 mm and more
  const uint32_t k = 150 - (e ? e : 1);  // value = m / 2^k mm
  const uint64_t scaled = m * 1000000u;  // < 2^44
  if (k >= 64) return finish_nm(bits >> 31, 0, false, false, offset, nm);
  const uint64_t q = scaled >> k, r = scaled & ((uint64_t{1} << k) - 1);
  const bool up = k > 0 && r >= (uint64_t{1} << (k - 1));
  const uint64_t max = static_cast<uint64_t>(kStlMaxCoordNm);
  return finish_nm(bits >> 31, q, up, q > max || (q == max && r > 0), offset, nm);
}

// An ASCII word as strtod reads it whole (decimal: sign, digits, a point,
// an exponent; inf and nan words are beyond), exactly.
enum class Word : uint8_t { kOk, kNotNumber, kBeyond };

bool word_is(const char* w, size_t n, const char* k) {
  size_t i = 0;
  for (; i < n && k[i]; ++i)
    if (lower(static_cast<uint8_t>(w[i])) != k[i]) return false;
  return i == n && !k[i];
}

Word decimal_nm(const char* w, size_t n, int64_t offset, int64_t* nm) {
  size_t i = 0;
  bool negative = false;
  if (i < n && (w[i] == '+' || w[i] == '-')) negative = w[i++] == '-';
  if (word_is(w + i, n - i, "inf") || word_is(w + i, n - i, "infinity") || word_is(w + i, n - i, "nan"))
    return Word::kBeyond;
  uint64_t d = 0;
  int32_t kept = 0, p10 = 0;  // d x 10^p10; significant digits kept
  bool sticky = false, any = false, point = false;
  for (; i < n; ++i) {
    const char c = w[i];
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    any = true;
    if (kept == 0 && c == '0') {  // a leading zero: the point moves, nothing kept
      if (point) --p10;
      continue;
    }
    if (kept < 19) {
      d = d * 10 + static_cast<uint64_t>(c - '0');
      ++kept;
      if (point) --p10;
    } else {
      sticky = sticky || c != '0';
      if (!point) ++p10;
    }
  }
  if (!any) return Word::kNotNumber;
  if (i < n && (w[i] == 'e' || w[i] == 'E')) {
    size_t j = i + 1;
    bool eneg = false;
    if (j < n && (w[j] == '+' || w[j] == '-')) eneg = w[j++] == '-';
    int32_t x = 0;
    const size_t first = j;
    for (; j < n && w[j] >= '0' && w[j] <= '9'; ++j) x = x < 100000 ? x * 10 + (w[j] - '0') : x;
    if (j > first) {  // else "1e" is 1 and the e is left over
      p10 += eneg ? -x : x;
      i = j;
    }
  }
  if (i != n) return Word::kNotNumber;
  if (d == 0) return finish_nm(negative, 0, false, false, offset, nm) == Coord::kOk ? Word::kOk : Word::kBeyond;
  // strtod's ERANGE: beyond the double's range, or under its normal numbers.
  const int32_t magnitude = p10 + kept - 1;
  if (magnitude > 308 || magnitude < -308) return Word::kNotNumber;
  const int32_t p = p10 + 6;  // nm = d x 10^p
  const uint64_t max = static_cast<uint64_t>(kStlMaxCoordNm);
  if (p >= 0) {
    if (p > 10) return Word::kBeyond;
    uint64_t v = d;
    for (int32_t k = 0; k < p; ++k) {
      if (v > max) return Word::kBeyond;
      v *= 10;
    }
    const bool beyond = v > max || (v == max && sticky);
    return finish_nm(negative, v, false, beyond, offset, nm) == Coord::kOk ? Word::kOk : Word::kBeyond;
  }
  if (-p >= 20) return finish_nm(negative, 0, false, false, offset, nm) == Coord::kOk ? Word::kOk : Word::kBeyond;
  uint64_t div = 1;
  for (int32_t k = 0; k < -p; ++k) div *= 10;
  const uint64_t q = d / div, r = d % div;
  const bool up = r >= div - r;  // half or more (a tie goes away from zero)
  const bool beyond = q > max || (q == max && (r > 0 || sticky));
  return finish_nm(negative, q, up, beyond, offset, nm) == Coord::kOk ? Word::kOk : Word::kBeyond;
}

bool read_binary(const uint8_t* b, const PointNm& off, bool (*cb)(void*, const PointNm*), void* ctx, StlScan* s) {
  const uint32_t n = le32(b + 80);
  for (uint32_t k = 0; k < n; ++k) {
    const uint8_t* f = b + 84 + 50 * static_cast<size_t>(k);
    PointNm v[3];
    bool any_nan = false, bad = false;
    for (int i = 0; i < 3; ++i) {
      int64_t* c[3] = {&v[i].x_nm, &v[i].y_nm, &v[i].z_nm};
      const int64_t o[3] = {off.x_nm, off.y_nm, off.z_nm};
      for (int a = 0; a < 3; ++a) {
        bool nan = false;
        bad = float_nm(le32(f + 12 + 12 * i + 4 * a), o[a], c[a], &nan) != Coord::kOk || bad;
        any_nan = any_nan || nan;
      }
      if (bad) break;  // the vertex's three, as the hosted reader judged them
    }
    if (bad) {
      s->fault = any_nan ? StlFault::kNotNumber : StlFault::kBeyond;
      return false;
    }
    ++s->triangles;
    if (!cb(ctx, v)) {
      s->fault = StlFault::kStopped;
      return false;
    }
  }
  return true;
}

// ASCII STL, word by word.
class Ascii {
 public:
  Ascii(const uint8_t* b, size_t n, StlScan* s) : b_(b), n_(n), s_(s) {}

  bool read(const PointNm& off, bool (*cb)(void*, const PointNm*), void* ctx) {
    if (!word() || !is("solid")) return fail(StlFault::kNoSolid);
    skip_line();  // the solid's name
    for (;;) {
      if (!word()) return fail(StlFault::kNoEndsolid);
      if (is("endsolid")) break;
      if (!is("facet")) return expected("facet");
      skip_line();  // normal nx ny nz: recomputed from the vertices where needed
      if (!word() || !is("outer")) return expected("outer loop");
      if (!word() || !is("loop")) return expected("loop");
      PointNm v[3];
      for (int i = 0; i < 3; ++i) {
        if (!word()) return fail(StlFault::kEndsInFacet);
        if (!is("vertex")) return expected("vertex");
        int64_t* c[3] = {&v[i].x_nm, &v[i].y_nm, &v[i].z_nm};
        const int64_t o[3] = {off.x_nm, off.y_nm, off.z_nm};
        for (int a = 0; a < 3; ++a) {
          if (!word()) return fail(StlFault::kNotNumber);
          const Word w = decimal_nm(w_, wn_, o[a], c[a]);
          if (w != Word::kOk) return fail(w == Word::kBeyond ? StlFault::kBeyond : StlFault::kNotNumber);
        }
      }
      if (!word() || !is("endloop")) return expected("endloop");
      if (!word() || !is("endfacet")) return expected("endfacet");
      ++s_->triangles;
      if (!cb(ctx, v)) return fail(StlFault::kStopped);
    }
    return true;
  }

 private:
  bool word() {
    wn_ = 0;
    while (pos_ < n_ && space(b_[pos_])) {
      if (b_[pos_] == '\n') ++s_->line;
      ++pos_;
    }
    while (pos_ < n_ && !space(b_[pos_]) && wn_ < kStlWordMax) w_[wn_++] = static_cast<char>(b_[pos_++]);
    w_[wn_] = 0;
    return wn_ > 0;
  }
  void skip_line() {
    while (pos_ < n_ && b_[pos_] != '\n') ++pos_;
  }
  bool is(const char* k) const { return word_is(w_, wn_, k); }
  bool fail(StlFault f) {
    s_->fault = f;
    return false;
  }
  bool expected(const char* want) {
    s_->expected = want;
    for (size_t k = 0; k <= wn_; ++k) s_->found[k] = w_[k];
    return fail(StlFault::kExpected);
  }
  const uint8_t* b_;
  size_t n_;
  StlScan* s_;
  size_t pos_ = 0;
  char w_[kStlWordMax + 1] = {};
  size_t wn_ = 0;
};

}  // namespace

uint32_t stl_binary_count(const uint8_t* b) { return le32(b + 80); }

bool stl_scan(const uint8_t* b, size_t n, const PointNm& offset, bool (*on_triangle)(void* ctx, const PointNm* v),
              void* ctx, StlScan* out) {
  *out = StlScan{};
  bool ok;
  if (n >= 84 && n == 84 + 50 * static_cast<uint64_t>(le32(b + 80))) {
    out->binary = true;
    ok = read_binary(b, offset, on_triangle, ctx, out);
  } else {
    // ASCII STL is text: a NUL byte means binary STL of the wrong size.
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
      if (b[i] == 0) return (out->fault = StlFault::kNotStl, false);
    while (k < n && space(b[k])) ++k;
    if (n - k < 5 || !word_is(reinterpret_cast<const char*>(b + k), 5, "solid")) return (out->fault = StlFault::kNotStl, false);
    ok = Ascii(b, n, out).read(offset, on_triangle, ctx);
  }
  if (ok && out->triangles == 0) return (out->fault = StlFault::kNoTriangles, false);
  return ok;
}

}  // namespace dexmill
