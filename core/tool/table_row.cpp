// One line of a LinuxCNC tool table; see table_row.h.
#include "core/tool/table_row.h"

#include "core/math/decimal.h"
#include "core/math/text_out.h"
#include "core/tool/tool_comment.h"

namespace dexmill {
namespace {

// The C locale's isspace (a comment's words) and toupper.
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
bool is_table_word(char c) {
  for (const char* w = "TPDXYZABCUVWIJQ"; *w; ++w)
    if (*w == c) return true;
  return false;
}
bool has_colon(const char* s, size_t n) {
  for (size_t k = 0; k < n; ++k)
    if (s[k] == ':') return true;
  return false;
}

// A shape in a comment: the first word that is a tool spec. A word that
// names a shape (ball: flat: bull: vbit:) but does not parse is not
// skipped: *bad gets its offset and *why the reason, and false comes back,
// so the tool is not silently simulated as another shape.
bool spec_in_comment(const char* s, size_t n, Tool* out, size_t* bad, ToolSpecError* why) {
  size_t k = 0;
  *why = ToolSpecError::kOk;
  while (k < n) {
    while (k < n && is_space(s[k])) ++k;
    const size_t b = k;
    while (k < n && !is_space(s[k])) ++k;
    if (k == b || !has_colon(s + b, k - b)) continue;
    const ToolSpecError e = tool_spec_parse(s + b, k - b, out);
    if (e == ToolSpecError::kOk) return true;
    if (e != ToolSpecError::kUnknownShape && *why == ToolSpecError::kOk) {
      *bad = b;
      *why = e;
    }
  }
  return false;
}

ToolRowError refuse(ToolRowFault* why, ToolRowError e, size_t col, int32_t number) {
  why->error = e;
  why->col = static_cast<uint32_t>(col);
  why->number = number;
  return e;
}

// The words before the comment (s[0, n)) into *r; *d_nm and whether T and D came.
ToolRowError read_words(const char* s, size_t n, bool inch, ToolRow* r, int64_t* d_nm, bool* have_t, bool* have_d,
                        ToolRowFault* why) {
  size_t k = 0;
  while (k < n) {
    const char c = upper(s[k]);
    if (c == ' ' || c == '\t' || c == '\r') {
      ++k;
      continue;
    }
    const size_t col = k + 1;
    if (c == 0 || !is_table_word(c)) {
      why->word = s[k];
      return refuse(why, ToolRowError::kUnknownWord, col, r->number);
    }
    ++k;
    Decimal d;
    size_t pos = k;
    if (decimal_parse(s, n, &pos, &d) != DecimalParse::kOk) {
      why->word = c;
      return refuse(why, ToolRowError::kNeedsNumber, col, r->number);
    }
    k = pos;
    int64_t iv = 0;
    if (c == 'T' || c == 'P') {
      if (!decimal_to_int(d, &iv) || iv < 0 || iv > 1000000000)
        return refuse(why, c == 'T' ? ToolRowError::kBadNumber : ToolRowError::kBadPocket, col, r->number);
      if (c == 'P') {
        r->pocket = static_cast<int32_t>(iv);
        continue;
      }
      r->number = static_cast<int32_t>(iv);
      *have_t = true;
      r->t_col = static_cast<uint32_t>(col);
    } else if (c == 'D') {
      *d_nm = decimal_to_nm(d, inch);
      *have_d = true;
      // D0 is common in LinuxCNC tables (a probe, a slot kept free): such
      // a tool reads, and cannot cut.
      if ((*d_nm < kNmPerUm && *d_nm != 0) || *d_nm > 1000 * kNmPerMm)
        return refuse(why, ToolRowError::kBadDiameter, col, r->number);
    } else if (c == 'Z') {
      r->length_offset_nm = decimal_to_nm(d, inch);
      if (r->length_offset_nm > kToolRowMaxOffsetNm || r->length_offset_nm < -kToolRowMaxOffsetNm)
        return refuse(why, ToolRowError::kBadOffset, col, r->number);
    }  // other offsets and lathe fields: a 3-axis mill has no use for them
  }
  return ToolRowError::kOk;
}

}  // namespace

ToolRowError tool_table_row(const char* s, size_t n, bool inch, ToolRowDefined defined, const void* ctx, ToolRow* out,
                            ToolRowFault* why) {
  *why = ToolRowFault();
  ToolRow r;
  size_t words_end = n;
  for (size_t k = 0; k < n; ++k)
    if (s[k] == ';') {
      words_end = k;
      break;
    }
  bool have_t = false, have_d = false;
  int64_t diameter_nm = 0;
  const ToolRowError words = read_words(s, words_end, inch, &r, &diameter_nm, &have_t, &have_d, why);
  if (words != ToolRowError::kOk) return words;
  const char* comment = words_end < n ? s + words_end + 1 : s + n;
  const size_t comment_n = words_end < n ? n - words_end - 1 : 0;
  if (!have_t && !have_d) {
    *out = r;  // a comment line or a blank one
    return ToolRowError::kOk;
  }
  if (!have_t) return refuse(why, ToolRowError::kNoNumber, 1, 0);
  if (!have_d) return refuse(why, ToolRowError::kNoDiameter, r.t_col, r.number);
  if (const uint32_t first = defined ? defined(ctx, r.number) : 0) {
    why->other_line = first;
    return refuse(why, ToolRowError::kDuplicate, r.t_col, r.number);
  }
  Tool t;
  size_t bad_at = 0;
  ToolSpecError spec = ToolSpecError::kOk;
  const bool have_spec = spec_in_comment(comment, comment_n, &t, &bad_at, &spec);
  if (!have_spec && spec != ToolSpecError::kOk) {
    size_t end = bad_at;
    while (end < comment_n && !is_space(comment[end])) ++end;
    why->shape = comment + bad_at;
    why->shape_n = end - bad_at;
    why->spec = spec;
    return refuse(why, ToolRowError::kBadShape, static_cast<size_t>(comment - s) + bad_at + 1, r.number);
  }
  if (have_spec) {
    t.diameter_nm = diameter_nm;
    if (t.kind == ToolKind::kBullNose && t.corner_radius_nm > diameter_nm / 2)
      return refuse(why, ToolRowError::kCornerRadius, r.t_col, r.number);
  } else {
    // No spec: the remark's kind words, read as a program's tool comments
    // are (core/tool/tool_comment.h); a row that names none is a flat end
    // mill, one whose shape cannot be completed is one with a warning.
    t = Tool();
    t.diameter_nm = diameter_nm;
    if (tool_remark_shape(comment, comment_n, &t.kind, &t.tip_angle_mdeg) == RemarkShape::kUnusable) {
      t.kind = ToolKind::kFlat;
      t.tip_angle_mdeg = 0;
      r.flat_guess = true;
    }
  }
  t.length_nm = tool_default_length_nm(t);
  if (diameter_nm != 0 && !ok(tool_check(t))) return refuse(why, ToolRowError::kOutOfRange, r.t_col, r.number);
  r.tool = t;
  r.empty = false;
  *out = r;
  return ToolRowError::kOk;
}

size_t tool_row_message(const ToolRowFault& f, char* buf, size_t n) {
  TextOut o{buf, n, 0};
  const auto tool = [&o, &f](const char* before, const char* after) {
    o.puts(before);
    o.put('T');
    o.put_int(f.number);
    o.puts(after);
  };
  switch (f.error) {
    case ToolRowError::kOk: break;
    case ToolRowError::kUnknownWord:
      o.puts("unknown word '");
      o.put(f.word);
      o.puts("' in the tool table (T P D X Y Z A B C U V W I J Q)");
      break;
    case ToolRowError::kNeedsNumber:
      o.put('\'');
      o.put(f.word);
      o.puts("' needs a number");
      break;
    case ToolRowError::kBadNumber: o.puts("the tool number must be a whole number from 0 to 1e9"); break;
    case ToolRowError::kBadPocket: o.puts("the pocket must be a whole number from 0 to 1e9"); break;
    case ToolRowError::kBadDiameter: o.puts("the diameter must be 0 or between 0.001 and 1000 mm"); break;
    case ToolRowError::kBadOffset: o.puts("the length offset is beyond +-10 m"); break;
    case ToolRowError::kNoNumber: o.puts("a tool needs a number (T)"); break;
    case ToolRowError::kNoDiameter: tool("tool ", " has no diameter (D)"); break;
    case ToolRowError::kDuplicate:
      tool("tool ", " is already defined on line ");
      o.put_uint(f.other_line);
      break;
    case ToolRowError::kBadShape:
      o.puts("the shape '");
      o.put(f.shape, f.shape_n);
      tool("' of ", " is not usable: ");
      o.puts(tool_spec_message(f.spec));
      break;
    case ToolRowError::kCornerRadius: tool("the corner radius of ", " is larger than D/2"); break;
    case ToolRowError::kOutOfRange: tool("tool ", " is out of range"); break;
  }
  return o.end();
}

size_t tool_row_warning(const ToolRow& row, char* buf, size_t n) {
  TextOut o{buf, n, 0};
  o.put('T');
  o.put_int(row.number);
  o.puts(" is simulated as a flat end mill; put its shape in the comment, e.g. vbit:D:ANGLE or bull:D:R");
  return o.end();
}

}  // namespace dexmill
