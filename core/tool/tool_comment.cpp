// Tools described in comments; see tool_comment.h. The structured forms
// (a spec, Fusion's list, APT's TOOL/MILL, tool table rows, CamBam, PyCAM)
// are here, the free-text ones in tool_comment_named.cpp.
#include "core/tool/tool_comment.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/tool/comment_text.h"
#include "core/tool/spec.h"
#include "core/tool/tool_comment_named.h"

namespace dexmill {
namespace {

constexpr int64_t kE9 = 1000000000;
constexpr int64_t kE6 = 1000000;

// A leading T<digits> followed by a non-word byte; -1 when there is none.
int32_t leading_t(const char* s, size_t n, size_t* after) {
  size_t p = text_skip_spaces(s, n, 0);
  if (p >= n || (s[p] != 'T' && s[p] != 't')) return -1;
  ++p;
  int digits = 0;
  const int32_t num = text_read_digits(s, n, &p, &digits);
  if (digits == 0 || (p < n && (text_is_letter(s[p]) || text_is_digit(s[p]) || s[p] == '.'))) return -1;
  *after = p;
  return num;
}

// The shape of a mill from its corner radius: flat, bull nose, or ball
// when the corner is half the diameter (to 1 %: posts round both).
void mill_shape(ToolComment* c) {
  if (c->corner_e9 <= 0) c->kind = ToolKind::kFlat;
  else if (200 * c->corner_e9 >= 99 * c->diameter_e9) c->kind = ToolKind::kBall;
  else c->kind = ToolKind::kBullNose;
  if (c->kind != ToolKind::kBullNose) c->corner_e9 = 0;
}

// A word of the comment that is a --tool spec (T1 ball:3.175).
bool read_spec(const char* s, size_t n, ToolComment* out) {
  size_t after = 0;
  const int32_t number = leading_t(s, n, &after);
  for (size_t p = 0; p < n;) {
    while (p < n && text_is_space(s[p])) ++p;
    size_t e = p;
    while (e < n && !text_is_space(s[e])) ++e;
    const bool shaped = text_has_at(s, n, p, "ball:") || text_has_at(s, n, p, "flat:") ||
                        text_has_at(s, n, p, "bull:") || text_has_at(s, n, p, "vbit:");
    Tool t;
    if (shaped && tool_spec_parse(s + p, e - p, &t) == ToolSpecError::kOk) {
      ToolComment c;
      c.form = ToolCommentForm::kSpec;
      c.number = number;
      c.kind = t.kind;
      c.unit = CommentUnit::kMm;
      c.diameter_e9 = t.diameter_nm * 1000;
      c.corner_e9 = t.corner_radius_nm * 1000;
      c.tip_angle_mdeg = t.tip_angle_mdeg;
      c.spec = t;
      *out = c;
      return true;
    }
    p = e;
  }
  return false;
}

// Fusion's tool type, the words after " - " that follow D, CR, TAPER and ZMIN.
enum class FusionType : uint8_t { kOther, kFlat, kFace, kBall, kBull, kChamfer, kDrill };

FusionType fusion_type(const char* s, size_t n, size_t p) {
  for (;;) {  // skip the "- ZMIN=-1.5" and "- ZMAX=+15" segments
    p = text_skip_spaces(s, n, p);
    if (p < n && s[p] == '-') p = text_skip_spaces(s, n, p + 1);
    if (!text_has_at(s, n, p, "zmin=") && !text_has_at(s, n, p, "zmax=")) break;
    p += 5;
    int64_t z = 0;
    if (!text_read_signed(s, n, &p, &z)) return FusionType::kOther;
  }
  static const struct {
    const char* name;
    FusionType type;
  } kTypes[] = {{"flat end mill", FusionType::kFlat},      {"face mill", FusionType::kFace},
                {"ball end mill", FusionType::kBall},      {"bullnose end mill", FusionType::kBull},
                {"bull nose end mill", FusionType::kBull}, {"chamfer mill", FusionType::kChamfer},
                {"center drill", FusionType::kDrill},      {"centre drill", FusionType::kDrill},
                {"spot drill", FusionType::kDrill},        {"drill block", FusionType::kOther},
                {"drill", FusionType::kDrill},             {"reamer", FusionType::kFlat}};
  for (const auto& t : kTypes)
    if (text_has_at(s, n, p, t.name)) return t.type;
  return FusionType::kOther;  // taps, thread, tapered, lollipop, dovetail, slot, form mills, probes...
}

// (T1 D=3.175 CR=0. TAPER=45deg - ZMIN=-1 - chamfer mill): the T first,
// maybe a description, then D= and CR= (TAPER=) and the type.
bool read_fusion(const char* s, size_t n, ToolComment* out) {
  size_t p = 0;
  const int32_t number = leading_t(s, n, &p);
  if (number < 0) return false;
  const size_t d_at = text_find(s, n, "d=", false, p);
  if (d_at >= n || (d_at > 0 && !text_is_space(s[d_at - 1]))) return false;
  p = d_at + 2;
  ToolComment c;
  c.form = ToolCommentForm::kFusion;
  c.number = number;
  if (!text_read_amount(s, n, &p, &c.diameter_e9) || c.diameter_e9 <= 0) return false;
  p = text_skip_spaces(s, n, p);
  if (!text_has_at(s, n, p, "cr=")) return false;
  p += 3;
  if (!text_read_amount(s, n, &p, &c.corner_e9)) return false;
  int64_t taper_e9 = 0;
  const size_t t = text_skip_spaces(s, n, p);
  if (text_has_at(s, n, t, "taper=")) {
    p = t + 6;
    if (!text_read_amount(s, n, &p, &taper_e9) || !text_read_degrees(s, n, &p)) return false;
  }
  switch (fusion_type(s, n, p)) {
    case FusionType::kFlat:
    case FusionType::kBall:
    case FusionType::kBull:
      if (taper_e9 != 0) return false;  // a tapered mill
      mill_shape(&c);
      break;
    case FusionType::kFace:  // a taper is its inserts' lead angle; the face cuts flat
      mill_shape(&c);
      break;
    case FusionType::kChamfer:  // TAPER is its half angle
      if (c.corner_e9 != 0 || taper_e9 <= 0 || taper_e9 >= 90 * kE9) return false;
      c.kind = ToolKind::kVBit;
      c.tip_angle_mdeg = static_cast<int32_t>(2 * (taper_e9 / kE6));
      break;
    case FusionType::kDrill:  // TAPER is its point angle
      if (c.corner_e9 != 0 || taper_e9 >= 180 * kE9) return false;
      c.kind = ToolKind::kVBit;
      c.tip_angle_mdeg = taper_e9 > 0 ? static_cast<int32_t>(taper_e9 / kE6) : kDrillPointMdeg;
      break;
    case FusionType::kOther: return false;
  }
  *out = c;
  return true;
}

// Up to `max` comma-separated signed amounts after s[p]; how many.
int read_fields(const char* s, size_t n, size_t p, int64_t* v, int max) {
  int k = 0;
  while (k < max) {
    p = text_skip_spaces(s, n, p);
    if (p >= n || s[p] != ',') break;
    p = text_skip_spaces(s, n, p + 1);
    if (!text_read_signed(s, n, &p, &v[k])) return -1;
    ++k;
  }
  p = text_skip_spaces(s, n, p);
  return p == n ? k : -1;
}

// (TOOL/MILL, D, CR, H, A) and (TOOL/DRILL, D, ANGLE).
bool read_apt(const char* s, size_t n, ToolComment* out) {
  size_t p = text_skip_spaces(s, n, 0);
  const bool mill = text_has_at(s, n, p, "tool/mill");
  if (!mill && !text_has_at(s, n, p, "tool/drill")) return false;
  int64_t f[4] = {0, 0, 0, 0};
  const int k = read_fields(s, n, p + (mill ? 9 : 10), f, 4);
  if (k < 1 || f[0] <= 0 || f[1] < 0 || f[2] < 0 || f[3] < 0) return false;
  ToolComment c;
  c.form = ToolCommentForm::kApt;
  c.diameter_e9 = f[0];
  if (!mill) {  // D, point angle
    if (f[1] >= 180 * kE9) return false;
    c.kind = ToolKind::kVBit;
    c.tip_angle_mdeg = f[1] > 0 ? static_cast<int32_t>(f[1] / kE6) : kDrillPointMdeg;
    *out = c;
    return true;
  }
  c.corner_e9 = f[1];
  const int64_t height_e9 = f[2], taper_e9 = f[3];
  if (taper_e9 == 0) {
    mill_shape(&c);
    *out = c;
    return true;
  }
  // A cone from its tip (D) at the half angle A up to the height H: a V-bit
  // when the tip is small beside the top; a tapered end mill is not one.
  if (c.corner_e9 != 0 || height_e9 <= 0 || taper_e9 >= 90 * kE9) return false;
  const int64_t half_mdeg = taper_e9 / kE6;
  const SinCosQ30 sc = sincos_bam(bam_from_mdeg(half_mdeg));
  const int64_t top_e9 = sat_add_i64(c.diameter_e9, muldiv_round(2 * height_e9, sc.sin_q30, sc.cos_q30));
  if (10 * c.diameter_e9 > top_e9) return false;
  c.kind = ToolKind::kVBit;
  c.diameter_e9 = top_e9;
  c.corner_e9 = 0;
  c.tip_angle_mdeg = static_cast<int32_t>(2 * half_mdeg);
  *out = c;
  return true;
}

// (T1 P1 D6.0 Z+30 ;ball nose): words of a LinuxCNC tool table line.
bool read_table_line(const char* s, size_t n, ToolComment* out) {
  size_t p = 0;
  const int32_t number = leading_t(s, n, &p);
  if (number < 0) return false;
  int64_t d = -1;
  for (;;) {
    p = text_skip_spaces(s, n, p);
    if (p >= n || s[p] == ';') break;
    const char letter = text_lower(s[p]);
    static const char kWords[] = "pdxyzabcuvwijq";
    bool known = false;
    for (const char* w = kWords; *w; ++w) known = known || *w == letter;
    if (!known || p + 1 >= n) return false;
    ++p;
    int64_t v = 0;
    size_t q = p;
    const bool sign = s[q] == '-' || s[q] == '+';
    if (sign) ++q;
    if (!text_read_amount_here(s, n, &q, &v)) return false;
    if (letter == 'd') d = sign && s[p] == '-' ? -1 : v;
    p = q;
  }
  if (d <= 0) return false;
  const size_t r = p < n ? p + 1 : n;
  ToolComment c;
  c.form = ToolCommentForm::kTable;
  c.number = number;
  c.diameter_e9 = d;
  ToolComment shaped;
  if (read_spec(s + r, n - r, &shaped)) {
    c.kind = shaped.kind;
    c.corner_e9 = shaped.corner_e9;
    c.tip_angle_mdeg = shaped.tip_angle_mdeg;
    if (c.kind == ToolKind::kBullNose && 2 * c.corner_e9 > c.diameter_e9) return false;
  } else if (!named_shape_of(named_kind(s + r, n - r), s + r, n - r, &c)) {
    return false;
  }
  *out = c;
  return true;
}

// (1 1 -1.1901 0.250 3/4 center drill): the columns T P Z D, then a remark
// that names the tool's kind.
bool read_table_columns(const char* s, size_t n, ToolComment* out) {
  size_t p = text_skip_spaces(s, n, 0);
  int64_t v[4];
  for (int k = 0; k < 4; ++k) {
    p = text_skip_spaces(s, n, p);
    const bool ok = k == 2 ? text_read_signed(s, n, &p, &v[k]) : text_read_amount(s, n, &p, &v[k]);
    if (!ok || p >= n || !text_is_space(s[p])) return false;
    if (k < 2 && (v[k] % kE9 != 0 || v[k] / kE9 > 99999)) return false;
  }
  if (v[3] <= 0) return false;
  const NamedKind kind = named_kind(s + p, n - p);
  if (kind == NamedKind::kNone) return false;
  ToolComment c;
  c.form = ToolCommentForm::kTable;
  c.number = static_cast<int32_t>(v[0] / kE9);
  c.diameter_e9 = v[3];
  if (!named_shape_of(kind, s + p, n - p, &c)) return false;
  *out = c;
  return true;
}

// ( T0 : 1.0 ): CamBam's number and diameter.
bool read_cambam(const char* s, size_t n, ToolComment* out) {
  size_t p = 0;
  const int32_t number = leading_t(s, n, &p);
  if (number < 0) return false;
  p = text_skip_spaces(s, n, p);
  if (p >= n || s[p] != ':') return false;
  p = text_skip_spaces(s, n, p + 1);
  ToolComment c;
  if (!text_read_amount(s, n, &p, &c.diameter_e9) || c.diameter_e9 <= 0) return false;
  if (text_skip_spaces(s, n, p) != n) return false;
  c.form = ToolCommentForm::kCamBam;
  c.number = number;
  *out = c;
  return true;
}

// PyCAM's settings: shape = ...Cutter, torus_radius = R, tool_radius = R.
bool read_pycam(const char* s, size_t n, ToolCommentState* st, ToolComment* out) {
  size_t p = text_skip_spaces(s, n, 0);
  static const char* const kKeys[] = {"shape", "torus_radius", "tool_radius"};
  int key = -1;
  for (int k = 0; k < 3 && key < 0; ++k) {
    if (!text_has_at(s, n, p, kKeys[k])) continue;
    size_t q = p;
    while (kKeys[k][q - p]) ++q;
    q = text_skip_spaces(s, n, q);
    if (q < n && s[q] == '=') {
      key = k;
      p = text_skip_spaces(s, n, q + 1);
    }
  }
  if (key == 0) {
    st->pycam_shape = true;
    if (text_has_at(s, n, p, "sphericalcutter")) st->pycam_kind = ToolKind::kBall;
    else if (text_has_at(s, n, p, "toroidalcutter")) st->pycam_kind = ToolKind::kBullNose;
    else if (text_has_at(s, n, p, "cylindricalcutter")) st->pycam_kind = ToolKind::kFlat;
    else st->pycam_shape = false;
    return false;
  }
  int64_t v = 0;
  if (key < 1 || !text_read_amount(s, n, &p, &v) || text_skip_spaces(s, n, p) != n) return false;
  if (key == 1) {
    st->pycam_corner_e9 = v;
    return false;
  }
  if (v <= 0) return false;
  ToolComment c;
  c.form = ToolCommentForm::kPycam;
  c.diameter_e9 = 2 * v;
  c.kind = st->pycam_shape ? st->pycam_kind : ToolKind::kFlat;
  if (c.kind == ToolKind::kBullNose) {
    if (st->pycam_corner_e9 <= 0 || st->pycam_corner_e9 > v) return false;
    c.corner_e9 = st->pycam_corner_e9;
  }
  *out = c;
  return true;
}

int64_t to_nm(int64_t e9, CommentUnit u, bool inch) {
  const bool in = u == CommentUnit::kInch || (u == CommentUnit::kProgram && inch);
  return in ? muldiv_round(e9, 254, 10000) : div_round(e9, 1000);
}

}  // namespace

const char* tool_comment_form_name(ToolCommentForm f) {
  switch (f) {
    case ToolCommentForm::kNone: return "none";
    case ToolCommentForm::kSpec: return "spec";
    case ToolCommentForm::kFusion: return "fusion";
    case ToolCommentForm::kApt: return "apt";
    case ToolCommentForm::kTable: return "table";
    case ToolCommentForm::kCamBam: return "cambam";
    case ToolCommentForm::kPcb2gcode: return "pcb2gcode";
    case ToolCommentForm::kPycam: return "pycam";
    case ToolCommentForm::kNamed: return "named";
  }
  return "none";
}

bool tool_comment_read(const char* s, size_t n, ToolCommentState* state, ToolComment* out) {
  while (n > 0 && text_is_space(s[n - 1])) --n;
  const size_t b = text_skip_spaces(s, n, 0);
  s += b;
  n -= b;
  if (n == 0) return false;
  ToolComment c;
  const bool found = read_pycam(s, n, state, &c) || read_spec(s, n, &c) || read_fusion(s, n, &c) ||
                     read_apt(s, n, &c) || read_table_line(s, n, &c) || read_table_columns(s, n, &c) ||
                     read_cambam(s, n, &c) || read_pcb2gcode(s, n, &c) || read_named(s, n, &c);
  if (found) *out = c;
  return found;
}

bool tool_comment_tool(const ToolComment& c, bool inch, Tool* out) {
  if (c.form == ToolCommentForm::kSpec) {
    *out = c.spec;
    return true;
  }
  Tool t;
  t.kind = c.kind;
  t.diameter_nm = to_nm(c.diameter_e9, c.unit, inch);
  if (t.kind == ToolKind::kBullNose) t.corner_radius_nm = to_nm(c.corner_e9, c.unit, inch);
  if (t.kind == ToolKind::kVBit) t.tip_angle_mdeg = c.tip_angle_mdeg;
  if (tool_spec_complete(&t) != ToolSpecError::kOk) return false;
  *out = t;
  return true;
}

RemarkShape tool_remark_shape(const char* s, size_t n, ToolKind* kind, int32_t* tip_angle_mdeg) {
  const NamedKind k = named_kind(s, n);
  if (k == NamedKind::kNone) return RemarkShape::kNone;
  ToolComment c;
  if (!named_shape_of(k, s, n, &c)) return RemarkShape::kUnusable;
  *kind = c.kind;
  *tip_angle_mdeg = c.tip_angle_mdeg;
  return RemarkShape::kNamed;
}

}  // namespace dexmill
