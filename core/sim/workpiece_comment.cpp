// core/sim/workpiece_comment.h: (WORKPIECE,...) comments.
#include "core/sim/workpiece_comment.h"

#include "core/math/decimal.h"
#include "core/math/fixed.h"
#include "core/sim/comment_words.h"

namespace dexmill {
namespace {

struct Fields {
  bool has[9] = {};
  int64_t nm[9] = {};
  char axis = 'Z';
};
// The keys, in the order of Fields' slots.
const char* const kKeys[] = {"XMIN", "YMIN", "ZMIN", "XMAX", "YMAX", "ZMAX", "INNER_DIAMETER", "DIAMETER", "X"};
constexpr int kInner = 6, kDia = 7, kX = 8;  // Y is read into kX's neighbour below

}  // namespace

bool workpiece_comment(const char* s, size_t n, bool inch, WorkpieceBox* out, const char** why) {
  *why = nullptr;
  size_t at = 0;
  while (at < n && !(s[at] == '(' && comment_starts(s, n, at + 1, "WORKPIECE,"))) ++at;
  if (at == n) return false;
  at += 11;
  WorkpieceKind kind;
  if (comment_starts(s, n, at, "BOX")) kind = WorkpieceKind::kBox, at += 3;
  else if (comment_starts(s, n, at, "CYLINDER")) kind = WorkpieceKind::kCylinder, at += 8;
  else if (comment_starts(s, n, at, "TUBE")) kind = WorkpieceKind::kTube, at += 4;
  else return *why = "not BOX, CYLINDER or TUBE", false;
  Fields f;
  bool has_y = false;
  int64_t y_nm = 0;
  while (at < n && s[at] == ',') {
    ++at;
    if (comment_starts(s, n, at, "AXIS=")) {
      at += 5;
      if (at >= n) return *why = "AXIS= without an axis", false;
      f.axis = comment_upper(s[at++]);
      if (f.axis != 'X' && f.axis != 'Y' && f.axis != 'Z') return *why = "AXIS is not X, Y or Z", false;
      continue;
    }
    int key = -1;
    size_t len = 0;
    for (int k = 0; k < 9 && key < 0; ++k) {
      len = 0;
      while (kKeys[k][len]) ++len;
      if (comment_starts(s, n, at, kKeys[k]) && at + len < n && s[at + len] == '=') key = k;
    }
    bool is_y = false;
    if (key < 0 && comment_starts(s, n, at, "Y=")) is_y = true, len = 1;
    if (key < 0 && !is_y) return *why = "an unknown key", false;
    at += len + 1;
    Decimal d;
    if (decimal_parse(s, n, &at, &d) != DecimalParse::kOk) return *why = "a value that is not a number", false;
    const int64_t v = decimal_to_nm(d, inch);
    if (v < -kCommentMaxNm || v > kCommentMaxNm) return *why = "a value beyond 10 m", false;
    if (is_y) has_y = true, y_nm = v;
    else f.has[key] = true, f.nm[key] = v;
  }
  if (at >= n || s[at] != ')') return *why = "no closing parenthesis after its fields", false;
  WorkpieceBox b;
  b.kind = kind;
  if (kind == WorkpieceKind::kBox) {
    for (int k = 0; k < 6; ++k)
      if (!f.has[k]) return *why = "a BOX without XMIN, YMIN, ZMIN, XMAX, YMAX and ZMAX", false;
    b.lo = PointNm{f.nm[0], f.nm[1], f.nm[2]};
    b.hi = PointNm{f.nm[3], f.nm[4], f.nm[5]};
  } else {
    // Along its axis from MIN to MAX; the other two centred on the given
    // coordinates (X, Y for an axis Z), DIAMETER across.
    if (!f.has[kDia] || f.nm[kDia] <= 0) return *why = "a CYLINDER or TUBE without a DIAMETER", false;
    if (kind == WorkpieceKind::kTube && (!f.has[kInner] || f.nm[kInner] <= 0 || f.nm[kInner] >= f.nm[kDia]))
      return *why = "a TUBE without an INNER_DIAMETER below its DIAMETER", false;
    if (f.axis != 'Z') return *why = "a CYLINDER or TUBE along X or Y (a 3-axis stock stands along Z)", false;
    if (!f.has[2] || !f.has[5] || !f.has[kX] || !has_y)
      return *why = "a CYLINDER or TUBE without X, Y, ZMIN and ZMAX", false;
    const int64_t r = f.nm[kDia] / 2;
    b.lo = PointNm{f.nm[kX] - r, y_nm - r, f.nm[2]};
    b.hi = PointNm{f.nm[kX] + r, y_nm + r, f.nm[5]};
  }
  if (b.lo.x_nm >= b.hi.x_nm || b.lo.y_nm >= b.hi.y_nm || b.lo.z_nm >= b.hi.z_nm)
    return *why = "a minimum not below its maximum", false;
  *out = b;
  return true;
}

}  // namespace dexmill
