// Tool specification text <-> Tool; see spec.h.
#include "core/tool/spec.h"

#include "core/math/decimal.h"
#include "core/math/fixed.h"

namespace dexmill {
namespace {

bool same_word(const char* s, size_t n, const char* w) {
  size_t k = 0;
  for (; k < n && w[k]; ++k) {
    char c = s[k];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != w[k]) return false;
  }
  return k == n && !w[k];
}

// One decimal field s[0, n) scaled by `scale` (nm per mm, or mdeg per deg);
// positive values only.
bool parse_field(const char* s, size_t n, int64_t scale, int64_t* out) {
  if (n == 0) return false;
  Decimal d;
  size_t pos = 0;
  if (decimal_parse(s, n, &pos, &d) != DecimalParse::kOk || pos != n || d.mant <= 0) return false;
  *out = decimal_scale(d, scale);
  return true;
}

// Appends v / 10^6 with the decimals it needs (at most 6) to buf.
size_t put_millis(char* buf, size_t at, size_t n, int64_t v) {
  char tmp[40];
  size_t k = 0;
  uint64_t a = abs_u64(v);
  uint64_t ip = a / 1000000, fp = a % 1000000;
  char digits[24];
  int nd = 0;
  do { digits[nd++] = static_cast<char>('0' + ip % 10); ip /= 10; } while (ip);
  if (v < 0) tmp[k++] = '-';
  while (nd) tmp[k++] = digits[--nd];
  if (fp) {
    tmp[k++] = '.';
    for (uint64_t p = 100000; p && fp; p /= 10) {
      tmp[k++] = static_cast<char>('0' + fp / p);
      fp %= p;
    }
  }
  for (size_t i = 0; i < k && at + 1 < n; ++i) buf[at++] = tmp[i];
  return at;
}

size_t put_text(char* buf, size_t at, size_t n, const char* s) {
  while (*s && at + 1 < n) buf[at++] = *s++;
  return at;
}

}  // namespace

const char* tool_spec_message(ToolSpecError e) {
  switch (e) {
    case ToolSpecError::kOk: return "ok";
    case ToolSpecError::kUnknownShape: return "unknown tool shape (use ball:D, flat:D, bull:D:R or vbit:D:ANGLE)";
    case ToolSpecError::kBadNumber: return "tool sizes must be positive numbers (mm, degrees)";
    case ToolSpecError::kFieldCount: return "wrong number of fields (ball:D, flat:D, bull:D:R, vbit:D:ANGLE)";
    case ToolSpecError::kBadOption:
      return "after the shape: len=L, stick=S, shank=D, holder=DxH[,DxH...], flutes=N or nocentre";
    case ToolSpecError::kBadHolder:
      return "a holder is up to 4 pieces DxH (a cylinder) or D1-D2xH (a cone), mm";
    case ToolSpecError::kOutOfRange:
      return "tool out of range (diameter 0.001..1000 mm, corner radius 0.000001..D/2, angle 1..179.999 degrees, "
             "stick-out and flutes up to 10 m and at least the cutting shape's height)";
  }
  return "unknown tool spec error";
}

int64_t tool_default_length_nm(const Tool& t) {
  if (t.stick_out_nm > 0) return t.stick_out_nm;
  Tool probe = t;
  probe.length_nm = 0;
  const int64_t full = profile_full_height_nm(tool_profile(probe));
  int64_t len = max_of<int64_t>(30 * kNmPerMm, sat_mul_i64(t.diameter_nm, 2));
  len = max_of(len, full);
  return max_of(len, t.flute_length_nm);
}

namespace {

// One holder piece: DxH or D1-D2xH.
bool parse_holder_piece(const char* s, size_t n, HolderSegment* out) {
  size_t x = n, dash = n;
  for (size_t k = 0; k < n; ++k) {
    if ((s[k] == 'x' || s[k] == 'X') && x == n) x = k;
    if (s[k] == '-' && dash == n && k > 0) dash = k;
  }
  if (x == n) return false;
  if (dash > x) dash = x;
  HolderSegment h;
  if (!parse_field(s, dash, kNmPerMm, &h.bottom_diameter_nm)) return false;
  h.top_diameter_nm = h.bottom_diameter_nm;
  if (dash < x && !parse_field(s + dash + 1, x - dash - 1, kNmPerMm, &h.top_diameter_nm)) return false;
  if (!parse_field(s + x + 1, n - x - 1, kNmPerMm, &h.height_nm)) return false;
  *out = h;
  return true;
}

// The options after the shape, s[0, n) without its leading ','.
ToolSpecError parse_options(const char* s, size_t n, Tool* t) {
  bool in_holder = false;
  size_t b = 0;
  for (size_t k = 0; k <= n; ++k) {
    if (k < n && s[k] != ',') continue;
    const char* o = s + b;
    const size_t on = k - b;
    b = k + 1;
    size_t eq = on;
    for (size_t m = 0; m < on; ++m)
      if (o[m] == '=') { eq = m; break; }
    if (eq == on && (same_word(o, on, "nocentre") || same_word(o, on, "nocenter"))) {
      t->centre_cutting = false;
      in_holder = false;
      continue;
    }
    if (eq == on && in_holder) {  // the holder's next piece
      if (t->holder_segments >= kHolderSegmentsMax || !parse_holder_piece(o, on, &t->holder[t->holder_segments]))
        return ToolSpecError::kBadHolder;
      ++t->holder_segments;
      continue;
    }
    in_holder = false;
    if (eq == on) return ToolSpecError::kBadOption;
    const char* v = o + eq + 1;
    const size_t vn = on - eq - 1;
    int64_t* field = nullptr;
    if (same_word(o, eq, "flutes")) {  // a whole count
      int64_t count = 0;
      if (vn == 0 || vn > 3) return vn == 0 ? ToolSpecError::kBadNumber : ToolSpecError::kOutOfRange;
      for (size_t m = 0; m < vn; ++m) {
        if (v[m] < '0' || v[m] > '9') return ToolSpecError::kBadNumber;
        count = count * 10 + (v[m] - '0');
      }
      if (count < 1 || count > kToolFlutesMax) return ToolSpecError::kOutOfRange;
      t->flutes = static_cast<int32_t>(count);
      continue;
    }
    if (same_word(o, eq, "len")) field = &t->flute_length_nm;
    else if (same_word(o, eq, "stick")) field = &t->stick_out_nm;
    else if (same_word(o, eq, "shank")) field = &t->shank_diameter_nm;
    else if (same_word(o, eq, "holder")) {
      if (t->holder_segments > 0 || !parse_holder_piece(v, vn, &t->holder[0])) return ToolSpecError::kBadHolder;
      t->holder_segments = 1;
      in_holder = true;
      continue;
    } else {
      return ToolSpecError::kBadOption;
    }
    if (!parse_field(v, vn, kNmPerMm, field)) return ToolSpecError::kBadNumber;
  }
  return ToolSpecError::kOk;
}

}  // namespace

ToolSpecError tool_spec_parse(const char* s, size_t n, Tool* out) {
  size_t comma = n;
  for (size_t k = 0; k < n; ++k) {
    if (s[k] == ',') { comma = k; break; }
  }
  Tool t;
  // Fields separated by ':'.
  size_t start[4], len[4];
  int nf = 0;
  size_t b = 0;
  for (size_t k = 0; k <= comma; ++k) {
    if (k == comma || s[k] == ':') {
      if (nf == 4) return ToolSpecError::kFieldCount;
      start[nf] = b;
      len[nf] = k - b;
      ++nf;
      b = k + 1;
    }
  }
  int want;
  const char* name = s + start[0];
  if (same_word(name, len[0], "ball")) { t.kind = ToolKind::kBall; want = 2; }
  else if (same_word(name, len[0], "flat")) { t.kind = ToolKind::kFlat; want = 2; }
  else if (same_word(name, len[0], "bull")) { t.kind = ToolKind::kBullNose; want = 3; }
  else if (same_word(name, len[0], "vbit")) { t.kind = ToolKind::kVBit; want = 3; }
  else return ToolSpecError::kUnknownShape;
  if (nf != want) return ToolSpecError::kFieldCount;
  if (!parse_field(s + start[1], len[1], kNmPerMm, &t.diameter_nm)) return ToolSpecError::kBadNumber;
  if (t.kind == ToolKind::kBullNose && !parse_field(s + start[2], len[2], kNmPerMm, &t.corner_radius_nm))
    return ToolSpecError::kBadNumber;
  if (t.kind == ToolKind::kVBit) {
    int64_t mdeg = 0;
    if (!parse_field(s + start[2], len[2], 1000, &mdeg)) return ToolSpecError::kBadNumber;
    if (mdeg < kVBitAngleMinMdeg || mdeg > kVBitAngleMaxMdeg) return ToolSpecError::kOutOfRange;
    t.tip_angle_mdeg = static_cast<int32_t>(mdeg);
  }
  if (comma < n) {
    const ToolSpecError e = parse_options(s + comma + 1, n - comma - 1, &t);
    if (e != ToolSpecError::kOk) return e;
  }
  const ToolSpecError e = tool_spec_complete(&t);
  if (e == ToolSpecError::kOk) *out = t;
  return e;
}

ToolSpecError tool_spec_complete(Tool* t) {
  // Range checks before the length rule, which evaluates the profile.
  if (t->diameter_nm < kToolDiameterMinNm || t->diameter_nm > kToolDiameterMaxNm ||
      t->flute_length_nm > kToolLengthMaxNm || t->stick_out_nm > kToolLengthMaxNm)
    return ToolSpecError::kOutOfRange;
  if (t->kind == ToolKind::kBullNose && t->corner_radius_nm > t->diameter_nm / 2) return ToolSpecError::kOutOfRange;
  t->length_nm = tool_default_length_nm(*t);
  return ok(tool_check(*t)) ? ToolSpecError::kOk : ToolSpecError::kOutOfRange;
}

size_t tool_spec_format(const Tool& t, char* buf, size_t n) {
  if (n == 0) return 0;
  size_t at = 0;
  switch (t.kind) {
    case ToolKind::kFlat: at = put_text(buf, at, n, "flat:"); break;
    case ToolKind::kBall: at = put_text(buf, at, n, "ball:"); break;
    case ToolKind::kBullNose: at = put_text(buf, at, n, "bull:"); break;
    case ToolKind::kVBit: at = put_text(buf, at, n, "vbit:"); break;
  }
  at = put_millis(buf, at, n, t.diameter_nm);
  if (t.kind == ToolKind::kBullNose) {
    at = put_text(buf, at, n, ":");
    at = put_millis(buf, at, n, t.corner_radius_nm);
  } else if (t.kind == ToolKind::kVBit) {
    at = put_text(buf, at, n, ":");
    at = put_millis(buf, at, n, static_cast<int64_t>(t.tip_angle_mdeg) * 1000);
  }
  if (t.flute_length_nm) {
    at = put_text(buf, at, n, ",len=");
    at = put_millis(buf, at, n, t.flute_length_nm);
  }
  if (t.stick_out_nm) {
    at = put_text(buf, at, n, ",stick=");
    at = put_millis(buf, at, n, t.stick_out_nm);
  }
  if (t.shank_diameter_nm) {
    at = put_text(buf, at, n, ",shank=");
    at = put_millis(buf, at, n, t.shank_diameter_nm);
  }
  for (int k = 0; k < t.holder_segments; ++k) {
    const HolderSegment& h = t.holder[k];
    at = put_text(buf, at, n, k ? "," : ",holder=");
    at = put_millis(buf, at, n, h.bottom_diameter_nm);
    if (h.top_diameter_nm != h.bottom_diameter_nm) {
      at = put_text(buf, at, n, "-");
      at = put_millis(buf, at, n, h.top_diameter_nm);
    }
    at = put_text(buf, at, n, "x");
    at = put_millis(buf, at, n, h.height_nm);
  }
  if (!t.centre_cutting) at = put_text(buf, at, n, ",nocentre");
  if (t.flutes) {
    char num[16];
    int k = 0;
    for (int32_t v = t.flutes; v > 0; v /= 10) num[k++] = static_cast<char>('0' + v % 10);
    at = put_text(buf, at, n, ",flutes=");
    while (k > 0 && at + 1 < n) buf[at++] = num[--k];
  }
  buf[at] = 0;
  return at;
}

}  // namespace dexmill
