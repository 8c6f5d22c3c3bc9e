// core/sim/blk_form_comment.h: (BLK FORM ...) comments.
#include "core/sim/blk_form_comment.h"

#include "core/math/decimal.h"
#include "core/sim/comment_words.h"

namespace dexmill {
namespace {

void blanks(const char* s, size_t n, size_t* at) {
  while (*at < n && (s[*at] == ' ' || s[*at] == '\t')) ++*at;
}

// The X, Y and Z words up to the closing parenthesis: each once, an I
// before the letter marking an increment (allowed only when `incremental`).
const char* coordinates(const char* s, size_t n, size_t* at, bool inch, bool incremental, int64_t nm[3], bool inc[3]) {
  bool has[3] = {false, false, false};
  for (;;) {
    blanks(s, n, at);
    if (*at >= n) return "no closing parenthesis";
    if (s[*at] == ')') break;
    bool i = false;
    if (comment_upper(s[*at]) == 'I') i = true, ++*at;
    if (i && !incremental) return "an increment (I) in the MIN point";
    const char c = *at < n ? comment_upper(s[*at]) : 0;
    const int axis = c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : -1;
    if (axis < 0) return "a word that is not X, Y or Z";
    if (has[axis]) return "an axis given twice";
    ++*at;
    Decimal d;
    if (decimal_parse(s, n, at, &d) != DecimalParse::kOk) return "a value that is not a number";
    nm[axis] = decimal_to_nm(d, inch);
    if (nm[axis] < -kCommentMaxNm || nm[axis] > kCommentMaxNm) return "a value beyond 10 m";
    has[axis] = true;
    inc[axis] = i;
  }
  if (!has[0] || !has[1] || !has[2]) return "a point without X, Y and Z";
  return nullptr;
}

}  // namespace

bool blk_form_comment(const char* s, size_t n, bool inch, BlkForm* st, WorkpieceBox* out, const char** why) {
  *why = nullptr;
  size_t at = 0;
  while (at < n && !(s[at] == '(' && comment_starts(s, n, at + 1, "BLK FORM "))) ++at;
  if (at == n) return false;
  at += 10;
  blanks(s, n, &at);
  const bool form_end = at + 3 >= n || s[at + 3] == ' ' || s[at + 3] == '\t';
  const bool min = form_end && comment_starts(s, n, at, "0.1"), max = form_end && comment_starts(s, n, at, "0.2");
  if (!min && !max) return *why = "a BLK FORM other than 0.1 and 0.2 (a box)", false;
  at += 3;
  int64_t nm[3] = {0, 0, 0};
  bool inc[3] = {false, false, false};
  if (min) {
    blanks(s, n, &at);
    const char axis = at < n ? comment_upper(s[at]) : 0;
    if (axis != 'X' && axis != 'Y' && axis != 'Z') return *why = "a BLK FORM 0.1 without its spindle axis", false;
    if (axis != 'Z') return *why = "a BLK FORM along X or Y (a 3-axis stock stands along Z)", false;
    ++at;
    if (at < n && s[at] != ' ' && s[at] != '\t') return *why = "a BLK FORM 0.1 without its spindle axis", false;
    if ((*why = coordinates(s, n, &at, inch, false, nm, inc))) return false;
    st->have_min = true;
    st->min = PointNm{nm[0], nm[1], nm[2]};
    return false;
  }
  if (!st->have_min) return *why = "a BLK FORM 0.2 without its 0.1 before it", false;
  if ((*why = coordinates(s, n, &at, inch, true, nm, inc))) return false;
  const PointNm& lo = st->min;
  const PointNm hi{inc[0] ? lo.x_nm + nm[0] : nm[0], inc[1] ? lo.y_nm + nm[1] : nm[1], inc[2] ? lo.z_nm + nm[2] : nm[2]};
  st->have_min = false;
  if (lo.x_nm >= hi.x_nm || lo.y_nm >= hi.y_nm || lo.z_nm >= hi.z_nm)
    return *why = "a MIN point not below its MAX point", false;
  out->kind = WorkpieceKind::kBox;
  out->lo = lo;
  out->hi = hi;
  return true;
}

}  // namespace dexmill
