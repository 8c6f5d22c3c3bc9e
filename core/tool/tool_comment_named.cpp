// Tools named in free text; see tool_comment_named.h and the rules in
// tool_comment.h.
#include "core/tool/tool_comment_named.h"

#include "core/tool/comment_text.h"

namespace dexmill {
namespace {

constexpr int kNamedWordsMax = 10;
constexpr int kWeakWordsMax = 6;  // a size without its unit: a short name only
constexpr int64_t kE9 = 1000000000;

struct Word {
  const char* text;
  bool whole;  // not followed by a letter
};

bool any_of(const char* s, size_t n, const Word* words, size_t count) {
  for (size_t k = 0; k < count; ++k)
    if (text_find(s, n, words[k].text, words[k].whole) < n) return true;
  return false;
}

// "tap" as a tool, not the "tap drill" that drills for one.
bool names_tap(const char* s, size_t n) {
  for (size_t at = text_find(s, n, "tap", true); at < n; at = text_find(s, n, "tap", true, at + 1)) {
    const size_t after = text_skip_spaces(s, n, at + 3);
    if (!text_has_at(s, n, after, "drill")) return true;
  }
  return text_has_prefix(s, n, "tapping");
}

const Word kRejectKinds[] = {
    {"thread", false}, {"probe", false},    {"boring", true},   {"bore", true},      {"dovetail", false},
    {"lollipop", false}, {"taper", false},  {"t-slot", false},  {"slitting", false}, {"saw", true},
    {"keyseat", false}, {"knife", false},   {"drag", true},     {"laser", false},    {"plasma", false},
    {"torch", true},    {"chamfer", false}, {"form mill", true}, {"form tool", true}, {"radius mill", true},
    {"corner round", false}, {"corner-round", false},
};
const Word kBallWords[] = {{"ball", false}, {"spheric", false}};
const Word kBullWords[] = {{"bull", false}, {"toroid", false}, {"corner radius", true}};
const Word kVBitWords[] = {{"v-bit", false},  {"vbit", false},    {"v bit", false}, {"v-carve", false},
                           {"vcarve", false}, {"v-groove", false}, {"v-cutter", false}, {"vee", true},
                           {"engrav", false}, {"countersink", false}, {"conical", false}, {"cone", true}};
const Word kFlatWords[] = {{"end mill", false}, {"endmill", false},  {"end-mill", false}, {"flat", true},
                           {"straight", true},  {"upcut", false},    {"up-cut", false},   {"up cut", false},
                           {"downcut", false},  {"down-cut", false}, {"down cut", false}, {"compression", false},
                           {"cylindric", false}, {"reamer", false},  {"router bit", false}, {"fraeser", false},
                           {"fr\xc3\xa4ser", false}, {"bit", true},  {"cutter", false}};
// Words that make a size in the same comment something other than the
// tool's diameter.
const Word kNotDiameter[] = {
    {"depth", false},  {"deep", true},      {"stock", false},    {"safe", false},   {"height", false},
    {"step", false},   {"pass", false},     {"offset", false},   {"allowance", false}, {"retract", false},
    {"thick", false},  {"feed", false},     {"speed", false},    {"plunge", false}, {"rpm", true},
    {"toleran", false}, {"material", false}, {"width", false},   {"length", false}, {"hole", false},
    {"size", false},   {"clearance", false}, {"zmin", false},    {"zmax", false},   {"travel", false},
    {"flute length", false}, {"loc", true}, {"oal", true},
};

template <size_t N>
bool any_of(const char* s, size_t n, const Word (&w)[N]) {
  return any_of(s, n, w, N);
}

// A size the text gives: an amount with its length unit.
struct Size {
  int64_t e9;
  CommentUnit unit;
};

bool same_size(const Size& a, const Size& b) { return a.e9 == b.e9 && a.unit == b.unit; }

CommentUnit comment_unit(TextUnit u) {
  return u == TextUnit::kMm ? CommentUnit::kMm : u == TextUnit::kInch ? CommentUnit::kInch : CommentUnit::kProgram;
}

// The text's sizes and angles: amounts followed by a length unit (not a
// rate such as mm/min, not a shank's size) and amounts in degrees. With
// `r_prefix`, R1mm and CR=1mm count too (a bull nose's corner).
struct Sizes {
  Size size[4];
  int nsizes = 0;      // distinct sizes (more than 4: 5, and the list holds the first 4)
  int64_t angle_mdeg[2];
  int nangles = 0;
};

void add_size(Sizes* z, const Size& v) {
  for (int k = 0; k < z->nsizes && k < 4; ++k)
    if (same_size(z->size[k], v)) return;
  if (z->nsizes < 4) z->size[z->nsizes] = v;
  if (z->nsizes < 5) ++z->nsizes;
}

bool shank_next_to(const char* s, size_t n, size_t start, size_t end) {
  size_t after = text_skip_spaces(s, n, end);
  if (after < n && (s[after] == '}' || s[after] == ']')) after = text_skip_spaces(s, n, after + 1);
  if (text_has_at(s, n, after, "shank")) return true;
  size_t b = start;
  while (b > 0 && text_is_space(s[b - 1])) --b;
  return b >= 5 && text_has_at(s, n, b - 5, "shank");
}

Sizes find_sizes(const char* s, size_t n, bool r_prefix) {
  Sizes z;
  for (size_t p = 0; p < n;) {
    int64_t v = 0;
    size_t e = p;
    bool amount = text_read_amount(s, n, &e, &v);
    if (!amount && r_prefix && (p == 0 || !text_is_letter(s[p - 1]))) {
      size_t q = p;
      if (text_has_at(s, n, q, "cr=")) q += 3;
      else if (text_has_at(s, n, q, "r=")) q += 2;
      else if (text_has_at(s, n, q, "r")) q += 1;
      e = q;
      amount = q != p && text_read_amount_here(s, n, &e, &v);
    }
    if (!amount) {
      ++p;
      continue;
    }
    size_t u = e;
    const TextUnit unit = text_read_unit(s, n, &u);
    if (unit != TextUnit::kNone) {
      const bool rate = u < n && s[u] == '/';
      if (!rate && !shank_next_to(s, n, p, u)) add_size(&z, Size{v, comment_unit(unit)});
      p = u;
      continue;
    }
    size_t d = e;
    if (text_read_degrees(s, n, &d)) {
      const int64_t mdeg = v / 1000000;
      bool seen = false;
      for (int k = 0; k < z.nangles && k < 2; ++k) seen = seen || z.angle_mdeg[k] == mdeg;
      if (!seen && z.nangles < 2) z.angle_mdeg[z.nangles] = mdeg;
      if (!seen && z.nangles < 3) ++z.nangles;
      p = d;
      continue;
    }
    p = e;
  }
  return z;
}

// "diameter" or "dia" and the amount after it (its unit optional).
bool labelled_diameter(const char* s, size_t n, Size* out) {
  static const char* const kLabels[] = {"diameter", "dia"};
  for (const char* w : kLabels) {
    for (size_t at = text_find(s, n, w, true); at < n; at = text_find(s, n, w, true, at + 1)) {
      size_t p = at;
      while (w[p - at]) ++p;
      p = text_skip_spaces(s, n, p);
      if (p < n && (s[p] == ':' || s[p] == '=')) p = text_skip_spaces(s, n, p + 1);
      int64_t v = 0;
      if (!text_read_amount(s, n, &p, &v) || v <= 0) continue;
      *out = Size{v, comment_unit(text_read_unit(s, n, &p))};
      return true;
    }
  }
  return false;
}

// The one amount of a text whose sizes have no unit (1/4 endmill), not a
// count (2 flute); false when there is none or more than one.
bool bare_amount(const char* s, size_t n, Size* out) {
  static const char* const kCounts[] = {"flute", "fl", "teeth", "tooth", "x", "pcs", "pack", "deg", "degree"};
  int found = 0;
  for (size_t p = 0; p < n;) {
    int64_t v = 0;
    size_t e = p;
    if (!text_read_amount(s, n, &e, &v)) {
      ++p;
      continue;
    }
    size_t u = e;
    if (text_read_unit(s, n, &u) != TextUnit::kNone || text_read_degrees(s, n, &u)) {  // a rate, an angle: no size
      p = u;
      continue;
    }
    size_t w = e < n && s[e] == '-' ? e + 1 : text_skip_spaces(s, n, e);
    bool count = false;
    for (const char* c : kCounts) count = count || (w < n && text_find(s, n, c, true, w) == w);
    if (!count) {
      if (++found > 1) return false;
      *out = Size{v, CommentUnit::kProgram};
    }
    p = e;
  }
  return found == 1;
}

// A number before the name: T1 ..., 1 = ..., Tool 3: ..., Tool #3 ...;
// *rest is where the name starts.
int32_t leading_number(const char* s, size_t n, size_t* rest) {
  size_t p = text_skip_spaces(s, n, 0);
  const size_t start = p;
  bool tool_word = false;
  if (p < n && (s[p] == 't' || s[p] == 'T') && p + 1 < n && text_is_digit(s[p + 1])) {
    ++p;
  } else if (text_has_at(s, n, p, "tool") && p + 4 < n && !text_is_letter(s[p + 4])) {
    p = text_skip_spaces(s, n, p + 4);
    if (p < n && s[p] == '#') ++p;
    tool_word = true;
  }
  int digits = 0;
  const int32_t num = text_read_digits(s, n, &p, &digits);
  if (digits == 0 || (p < n && (text_is_letter(s[p]) || text_is_digit(s[p]) || s[p] == '.' || s[p] == '/'))) {
    *rest = start;
    return -1;
  }
  size_t q = text_skip_spaces(s, n, p);
  const bool bare = p - digits == start;  // "1 = End Mill"
  if (q < n && (s[q] == '=' || s[q] == ':')) {
    *rest = q + 1;
    return num;
  }
  if (bare || tool_word) {
    *rest = start;
    return -1;
  }
  *rest = q;
  return num;
}

// After a "Tool:" (or "Tool =") label: where the name starts; n if none.
size_t after_tool_label(const char* s, size_t n) {
  for (size_t at = text_find(s, n, "tool", true); at < n; at = text_find(s, n, "tool", true, at + 1)) {
    const size_t p = text_skip_spaces(s, n, at + 4);
    if (p < n && (s[p] == ':' || s[p] == '=')) return p + 1;
  }
  return n;
}

}  // namespace

NamedKind named_kind(const char* s, size_t n) {
  if (names_tap(s, n) || any_of(s, n, kRejectKinds)) return NamedKind::kReject;
  if (any_of(s, n, kBallWords)) return NamedKind::kBall;
  if (any_of(s, n, kBullWords)) return NamedKind::kBull;
  if (any_of(s, n, kVBitWords)) return NamedKind::kVBit;
  if (text_has_prefix(s, n, "slot drill")) return NamedKind::kFlat;  // a two-flute end mill (UK)
  if (text_has_word(s, n, "drill") || text_has_word(s, n, "drills")) return NamedKind::kDrill;
  if (any_of(s, n, kFlatWords)) return NamedKind::kFlat;
  return NamedKind::kNone;
}

bool named_shape_of(NamedKind k, const char* s, size_t n, ToolComment* c) {
  const Sizes z = find_sizes(s, n, false);
  switch (k) {
    case NamedKind::kNone:
    case NamedKind::kFlat: c->kind = ToolKind::kFlat; return true;
    case NamedKind::kBall: c->kind = ToolKind::kBall; return true;
    case NamedKind::kVBit:
      if (z.nangles != 1) return false;
      c->kind = ToolKind::kVBit;
      c->tip_angle_mdeg = static_cast<int32_t>(z.angle_mdeg[0]);
      return true;
    case NamedKind::kDrill:
      if (z.nangles > 1) return false;
      c->kind = ToolKind::kVBit;
      c->tip_angle_mdeg = z.nangles == 1 ? static_cast<int32_t>(z.angle_mdeg[0]) : kDrillPointMdeg;
      return true;
    case NamedKind::kBull:
    case NamedKind::kReject: return false;
  }
  return false;
}

bool read_pcb2gcode(const char* s, size_t n, ToolComment* out) {
  size_t p = text_skip_spaces(s, n, 0);
  if (text_has_at(s, n, p, "msg")) {
    p += 3;
    if (p < n && s[p] == ',') ++p;
    p = text_skip_spaces(s, n, p);
  }
  if (!text_has_at(s, n, p, "change tool bit to")) return false;
  p = text_skip_spaces(s, n, p + 18);
  static const struct {
    const char* words;
    bool drill;
  } kWhat[] = {{"drill size", true}, {"drill diameter", true}, {"mill diameter", false},
               {"mill size", false}, {"cutter diameter", false}, {"cutter size", false}};
  for (const auto& w : kWhat) {
    if (!text_has_at(s, n, p, w.words)) continue;
    size_t q = p;
    while (w.words[q - p]) ++q;
    q = text_skip_spaces(s, n, q);
    int64_t v = 0;
    if (!text_read_amount(s, n, &q, &v) || v <= 0) return false;  // "mill diameter 0.00000in": no size given
    ToolComment c;
    c.form = ToolCommentForm::kPcb2gcode;
    c.unit = comment_unit(text_read_unit(s, n, &q));
    c.diameter_e9 = v;
    c.kind = w.drill ? ToolKind::kVBit : ToolKind::kFlat;
    c.tip_angle_mdeg = w.drill ? kDrillPointMdeg : 0;
    *out = c;
    return true;
  }
  return false;
}

bool read_named(const char* s, size_t n, ToolComment* out) {
  size_t rest = 0;
  const int32_t number = leading_number(s, n, &rest);
  s += rest;
  n -= rest;
  const size_t label = after_tool_label(s, n);
  const bool labelled = label < n;
  if (labelled) {
    s += label;
    n -= label;
  }
  if (text_word_count(s, n) > kNamedWordsMax || any_of(s, n, kNotDiameter)) return false;
  NamedKind kind = named_kind(s, n);
  if (kind == NamedKind::kReject) return false;
  bool weak = false;
  if (kind == NamedKind::kNone) {
    if (labelled) kind = NamedKind::kFlat;  // "Tool: 3.0mm"
    else if (text_has_word(s, n, "mill")) kind = NamedKind::kFlat, weak = true;  // "M6 T7 (0.0625 mill)"
    else return false;
  }
  ToolComment c;
  c.form = ToolCommentForm::kNamed;
  c.number = number;
  const Sizes z = find_sizes(s, n, kind == NamedKind::kBull);
  if (kind == NamedKind::kBull) {  // two sizes: the corner radius is the smaller
    if (z.nsizes != 2 || z.size[0].unit != z.size[1].unit) return false;
    const bool first_larger = z.size[0].e9 > z.size[1].e9;
    c.unit = z.size[0].unit;
    c.diameter_e9 = first_larger ? z.size[0].e9 : z.size[1].e9;
    c.corner_e9 = first_larger ? z.size[1].e9 : z.size[0].e9;
    c.kind = ToolKind::kBullNose;
    if (2 * c.corner_e9 > c.diameter_e9) return false;
    *out = c;
    return true;
  }
  if (kind != NamedKind::kVBit && kind != NamedKind::kDrill && text_has_word(s, n, "radius"))
    return false;  // its size may be a radius
  Size d{};
  if (z.nsizes == 1) {
    d = z.size[0];
  } else if (labelled_diameter(s, n, &d)) {
    if (z.nsizes > 1 && d.unit == CommentUnit::kProgram) return false;
  } else if (z.nsizes == 0 && text_word_count(s, n) <= kWeakWordsMax && bare_amount(s, n, &d)) {
    weak = true;  // "(1/4 endmill)": believed on its M6's line only
  } else {
    return false;
  }
  if (d.e9 <= 0 || d.e9 > 1000 * kE9) return false;
  if (!named_shape_of(kind, s, n, &c)) return false;
  c.unit = d.unit;
  c.diameter_e9 = d.e9;
  c.weak = weak;
  *out = c;
  return true;
}

}  // namespace dexmill
