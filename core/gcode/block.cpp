// Reading a line into a GcodeBlock: the word tables of RS274/NGC as LinuxCNC
// implements them, modal-group conflicts, duplicate words, and the special
// line forms (%, O program numbers, grbl $ commands).
#include "core/gcode/block.h"

#include <string.h>

#include "core/gcode/expr.h"
#include "core/gcode/lex.h"

namespace dexmill {

namespace {

enum class Support : uint8_t { kYes, kUnsupported, kUnknown };

struct GInfo {
  int16_t tenths;
  uint8_t group;
  Support support;
};

// Every G code LinuxCNC knows; the ones dexmill does not run are listed so
// that they get "is not supported" rather than "unknown".
constexpr GInfo kGCodes[] = {
    {0, kGMotion, Support::kYes},          {10, kGMotion, Support::kYes},
    {20, kGMotion, Support::kYes},         {30, kGMotion, Support::kYes},
    {40, kGNonModal, Support::kYes},       {50, kGMotion, Support::kYes},
    {51, kGMotion, Support::kYes},         {52, kGMotion, Support::kYes},
    {53, kGMotion, Support::kYes}, {70, kGLathe, Support::kYes},
    {80, kGLathe, Support::kYes}, {100, kGNonModal, Support::kYes},
    {170, kGPlane, Support::kYes},         {171, kGPlane, Support::kUnsupported},
    {180, kGPlane, Support::kYes},         {181, kGPlane, Support::kUnsupported},
    {190, kGPlane, Support::kYes},         {191, kGPlane, Support::kUnsupported},
    {200, kGUnits, Support::kYes},         {210, kGUnits, Support::kYes},
    {280, kGNonModal, Support::kYes},      {281, kGNonModal, Support::kYes},
    {300, kGNonModal, Support::kYes},      {301, kGNonModal, Support::kYes},
    {330, kGMotion, Support::kYes},        {331, kGMotion, Support::kYes},
    {382, kGMotion, Support::kYes},        {383, kGMotion, Support::kYes},
    {384, kGMotion, Support::kYes},        {385, kGMotion, Support::kYes},
    {400, kGCutterComp, Support::kYes},    {410, kGCutterComp, Support::kYes},
    {411, kGCutterComp, Support::kYes}, {420, kGCutterComp, Support::kYes},
    {421, kGCutterComp, Support::kYes}, {430, kGToolLength, Support::kYes},
    {431, kGToolLength, Support::kYes},    {432, kGToolLength, Support::kYes},
    {490, kGToolLength, Support::kYes},    {520, kGNonModal, Support::kUnsupported},
    {530, kGNonModal, Support::kYes},      {540, kGCoordSystem, Support::kYes},
    {550, kGCoordSystem, Support::kYes},   {560, kGCoordSystem, Support::kYes},
    {570, kGCoordSystem, Support::kYes},   {580, kGCoordSystem, Support::kYes},
    {590, kGCoordSystem, Support::kYes},   {591, kGCoordSystem, Support::kYes},
    {592, kGCoordSystem, Support::kYes},   {593, kGCoordSystem, Support::kYes},
    {610, kGPathControl, Support::kYes},   {611, kGPathControl, Support::kYes},
    {640, kGPathControl, Support::kYes},   {730, kGMotion, Support::kYes},
    {740, kGMotion, Support::kYes}, {760, kGMotion, Support::kUnsupported},
    {800, kGMotion, Support::kYes},        {810, kGMotion, Support::kYes},
    {820, kGMotion, Support::kYes},        {830, kGMotion, Support::kYes},
    {840, kGMotion, Support::kYes}, {850, kGMotion, Support::kYes},
    {860, kGMotion, Support::kYes},        {870, kGMotion, Support::kYes},
    {880, kGMotion, Support::kYes}, {890, kGMotion, Support::kYes},
    {900, kGDistance, Support::kYes},      {901, kGArcDistance, Support::kYes},
    {910, kGDistance, Support::kYes},      {911, kGArcDistance, Support::kYes},
    {920, kGNonModal, Support::kYes},      {921, kGNonModal, Support::kYes},
    {922, kGNonModal, Support::kYes},      {923, kGNonModal, Support::kYes},
    {930, kGFeedMode, Support::kYes},      {940, kGFeedMode, Support::kYes},
    {950, kGFeedMode, Support::kYes}, {960, kGSpindleMode, Support::kUnsupported},
    {970, kGSpindleMode, Support::kYes},   {980, kGRetract, Support::kYes},
    {990, kGRetract, Support::kYes},
};

const GInfo* find_g(int64_t tenths) {
  for (const GInfo& g : kGCodes)
    if (g.tenths == tenths) return &g;
  return nullptr;
}

enum class MKind : uint8_t { kRun, kIgnore, kUnsupported, kUnknown };

MKind classify_m(int64_t tenths, uint8_t* group) {
  if (tenths % 10 != 0) return MKind::kUnknown;
  int64_t m = tenths / 10;
  switch (m) {
    case 0: case 1: case 2: case 30: case 60: *group = kMStop; return MKind::kRun;
    case 3: case 4: case 5: *group = kMSpindle; return MKind::kRun;
    case 19: *group = kMSpindle; return MKind::kIgnore;
    case 6: case 61: *group = kMToolChange; return MKind::kRun;
    case 7: case 8: case 9: *group = kMCoolant; return MKind::kRun;
    case 48: case 49: case 50: case 51: case 52: case 53: *group = kMOverride; return MKind::kIgnore;
    case 62: case 63: case 64: case 65: case 66: case 67: case 68: *group = kMIo; return MKind::kIgnore;
    case 70: case 71: case 72: case 73: *group = kMContext; return MKind::kRun;
    default: break;
  }
  // M100-M199 are LinuxCNC's user M codes (a file each); any other M code
  // below 200 that it does not define itself a machine may define by a
  // remap (an accessory's M code, Centroid's M25): both read, then skipped
  // with a warning. M98/M99 (subroutines) are not such codes.
  if (m <= 199 && m != 98 && m != 99) {
    *group = kMUser;
    return MKind::kIgnore;
  }
  return MKind::kUnknown;
}

// A parameter assignment read from the line, made after it.
struct Assignment {
  ParamRef ref;
  GValue value;
  uint16_t col;
};

// "#123" or "#<name>", for diagnostics (out: kParamNameMax + 4 bytes).
void param_ref_text(const ParamRef& r, char* out) {
  size_t k = 0;
  out[k++] = '#';
  if (r.named) {
    out[k++] = '<';
    for (size_t i = 0; r.name[i] && k < kParamNameMax + 1; ++i) out[k++] = r.name[i];
    out[k++] = '>';
  } else {
    char tmp[8];
    int t = 0;
    int64_t v = r.number;
    do { tmp[t++] = static_cast<char>('0' + v % 10); v /= 10; } while (v && t < 8);
    while (t) out[k++] = tmp[--t];
  }
  out[k] = 0;
}

// Appends to out[*k, cap - 1).
struct Appender {
  char* out;
  size_t cap, k;
  void put(char c) {
    if (k + 1 < cap) out[k++] = c;
  }
  // A value as LinuxCNC's %lf: 6 decimals, rounded.
  void value(int64_t e9) {
    int64_t v = e9 / 1000 + (e9 % 1000 >= 500 ? 1 : (e9 % 1000 <= -500 ? -1 : 0));
    if (v < 0) put('-');
    uint64_t u = static_cast<uint64_t>(v < 0 ? -v : v);
    char tmp[24];
    int t = 0;
    for (int i = 0; i < 6; ++i, u /= 10) tmp[t++] = static_cast<char>('0' + u % 10);
    tmp[t++] = '.';
    do { tmp[t++] = static_cast<char>('0' + u % 10); u /= 10; } while (u);
    while (t) put(tmp[--t]);
  }
};

// The message text with #n and #<name> replaced by their values (when
// `substitute`: DEBUG and PRINT), "######" for a name never set.
void format_message(const char* s, size_t n, const ParamStore& p, bool substitute, char* out) {
  Appender a{out, kGcodeMessageMax, 0};
  for (size_t i = 0; i < n;) {
    if (substitute && s[i] == '#' && i + 1 < n && (s[i + 1] == '<' || (s[i + 1] >= '0' && s[i + 1] <= '9'))) {
      GValue v{0};
      bool known = true;
      if (s[i + 1] == '<') {
        size_t e = i + 2;
        while (e < n && s[e] != '>') ++e;
        if (e >= n) {
          a.put(s[i++]);
          continue;
        }
        known = param_get_named(p, s + i + 2, e - i - 2, &v, &known) == GcodeError::kOk && known;
        i = e + 1;
      } else {
        int64_t num = 0;
        size_t e = i + 1;
        while (e < n && s[e] >= '0' && s[e] <= '9' && num < 100000) num = num * 10 + (s[e++] - '0');
        known = param_get(p, num, &v) == GcodeError::kOk;
        i = e;
      }
      if (known) a.value(v.e9);
      else for (int k = 0; k < 6; ++k) a.put('#');
      continue;
    }
    a.put(s[i++]);
  }
  out[a.k] = 0;
}

GcodeError fail(GcodeDiag* d, GcodeError e, uint16_t col, const char* word) {
  d->code = e;
  d->col = col;
  size_t n = strlen(word);
  if (n > sizeof d->word - 1) n = sizeof d->word - 1;
  memcpy(d->word, word, n);
  d->word[n] = 0;
  return e;
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

int gcode_g_group(int64_t tenths) {
  const GInfo* g = find_g(tenths);
  return g ? g->group : -1;
}

void gcode_code_text(char letter, int32_t tenths, char* buf) {
  char tmp[16];
  int k = 0;
  int32_t v = tenths < 0 ? -tenths : tenths;
  int32_t whole = v / 10, frac = v % 10;
  do { tmp[k++] = static_cast<char>('0' + whole % 10); whole /= 10; } while (whole);
  int i = 0;
  buf[i++] = letter;
  if (tenths < 0) buf[i++] = '-';
  while (k) buf[i++] = tmp[--k];
  if (frac) {
    buf[i++] = '.';
    buf[i++] = static_cast<char>('0' + frac);
  }
  buf[i] = 0;
}

GcodeError gcode_read_block(const char* s, size_t n, uint32_t line, GcodeBlock* b, GcodeLineKind* kind,
                            GcodeDiag* d) {
  return gcode_read_block(s, n, line, b, kind, d, nullptr);
}

GcodeError gcode_read_block(const char* s, size_t n, uint32_t line, GcodeBlock* b, GcodeLineKind* kind,
                            GcodeDiag* d, ParamStore* params) {
  d->line = line;
  d->col = 1;
  d->word[0] = 0;
  d->a_nm = d->b_nm = 0;
  *kind = GcodeLineKind::kBlock;
  b->line = line;
  b->block_delete = false;
  b->has = 0;
  b->coolant_bits = 0;
  b->m_count = 0;
  b->first_col = 1;
  b->message_kind = GcodeMessage::kNone;
  b->message[0] = 0;
  for (int i = 0; i < kGGroupCount; ++i) b->g[i] = -1;
  for (int i = 0; i < kMGroupCount; ++i) b->m[i] = -1;

  if (n > kGcodeMaxLine) {
    d->a_nm = static_cast<int64_t>(kGcodeMaxLine);
    return fail(d, GcodeError::kLineTooLong, static_cast<uint16_t>(kGcodeMaxLine + 1), "");
  }
  size_t i = 0;
  while (i < n && is_blank(s[i])) ++i;
  // '%' alone on a line delimits the program (RS274/NGC 3.3.1).
  if (i < n && s[i] == '%') {
    GcodeScanner rest(s, n);
    rest.set_pos(i + 1);
    if (rest.at_end()) {
      *kind = GcodeLineKind::kPercent;
      return GcodeError::kOk;
    }
  }
  // A grbl system command ($H, $X, $J=...) is no G-code.
  if (i < n && s[i] == '$') {
    *kind = GcodeLineKind::kGrblCommand;
    size_t e = n;
    while (e > i && is_blank(s[e - 1])) --e;
    gcode_set_word(d, s + i, e - i);
    d->col = static_cast<uint16_t>(i + 1);
    return GcodeError::kOk;
  }
  if (i < n && s[i] == '/') {
    b->block_delete = true;
    ++i;
  }
  // `O1234` alone (with comments) is a program number; any other O word is
  // an o-word of LinuxCNC's control flow, which we do not run.
  {
    size_t j = i;
    while (j < n && is_blank(s[j])) ++j;
    if (j < n && (s[j] == 'O' || s[j] == 'o')) {
      size_t k = j + 1;
      while (k < n && is_blank(s[k])) ++k;
      size_t digits = k;
      while (k < n && s[k] >= '0' && s[k] <= '9') ++k;
      GcodeScanner rest(s, n);
      rest.set_pos(k);
      if (k > digits && rest.at_end()) {
        *kind = GcodeLineKind::kProgramNumber;
        return GcodeError::kOk;
      }
      size_t e = j;
      while (e < n && s[e] != ' ' && s[e] != '\t' && s[e] != '\r' && s[e] != '(' && s[e] != ';') ++e;
      gcode_set_word(d, s + j, e - j);
      d->code = GcodeError::kUnsupportedOword;
      d->col = static_cast<uint16_t>(j + 1);
      return GcodeError::kUnsupportedOword;
    }
  }

  GcodeScanner sc(s, n);
  sc.set_pos(i);
  sc.set_params(params);
  bool first = true;
  bool after_word = false;  // a word other than N was read
  Assignment assign[kGcodeAssignMax];
  int nassign = 0;
  for (;;) {
    GcodeWord w;
    GcodeError e = sc.next(&w, d);
    if (e != GcodeError::kOk) {
      // LinuxCNC reads an o-word only at the start of a line (after N); an O
      // after other words is a stray letter (Y1O: a zero typed as O).
      if (e == GcodeError::kUnsupportedOword && after_word) return fail(d, GcodeError::kMisplacedOword, d->col, "O");
      if (e == GcodeError::kUnsupportedOword || e == GcodeError::kBadCharacter) {
        // Quote the rest of an o-word ("O100"), or the byte itself.
        size_t at = d->col - 1, end = at + 1;
        if (e == GcodeError::kUnsupportedOword)
          while (end < n && s[end] != ' ' && s[end] != '\t' && s[end] != '\r' && s[end] != '(') ++end;
        gcode_set_word(d, s + at, end - at);
      }
      return e;
    }
    if (!w.letter) break;
    if (w.letter == '#') {  // #n = value: made after the line
      if (nassign >= kGcodeAssignMax) return fail(d, GcodeError::kTooManyAssignments, w.col, "#");
      size_t at = sc.pos();
      Assignment& a = assign[nassign++];
      a.col = w.col;
      e = expr_read_param_ref(s, n, &at, *params, &a.ref, d);
      if (e != GcodeError::kOk) return e;
      while (at < n && is_blank(s[at])) ++at;
      if (at >= n || s[at] != '=') return fail(d, GcodeError::kExprSyntax, static_cast<uint16_t>(at + 1), "#");
      ++at;
      e = expr_read_value(s, n, &at, *params, &a.value, d);
      if (e != GcodeError::kOk) return e;
      sc.set_pos(at);
      first = false;
      after_word = true;
      continue;
    }
    if (first) b->first_col = w.col;
    char code_text[16];
    if (w.letter == 'N') {
      if (!first) {
        gcode_code_text('N', 0, code_text);
        return fail(d, GcodeError::kLineNumberNotFirst, w.col, "N");
      }
      first = false;
      int64_t nv;
      if (!decimal_to_int(w.value, &nv)) return fail(d, GcodeError::kNotInteger, w.col, "N");
      if (nv < 0) return fail(d, GcodeError::kNegativeValue, w.col, "N");
      continue;  // line numbers carry no meaning for the machine
    }
    first = false;
    after_word = true;
    if (w.letter == 'G' || w.letter == 'M') {
      int64_t tenths;
      const char letter_str[2] = {w.letter, 0};
      if (decimal_is_negative(w.value)) return fail(d, GcodeError::kNegativeValue, w.col, letter_str);
      if (!decimal_to_tenths(w.value, &tenths)) return fail(d, GcodeError::kCodeNotInTenths, w.col, letter_str);
      if (tenths > 99999) return fail(d, GcodeError::kNumberTooLarge, w.col, letter_str);
      gcode_code_text(w.letter, static_cast<int32_t>(tenths), code_text);
      if (w.letter == 'G') {
        const GInfo* g = find_g(tenths);
        if (!g) return fail(d, GcodeError::kUnknownGcode, w.col, code_text);
        if (g->support == Support::kUnsupported) return fail(d, GcodeError::kUnsupportedGcode, w.col, code_text);
        // LinuxCNC drops G80 when another motion code shares its block.
        if (g->group == kGMotion && b->g[kGMotion] >= 0 && (tenths == 800 || b->g[kGMotion] == 800)) {
          if (tenths == 800) continue;
        } else if (b->g[g->group] >= 0) {
          return fail(d, GcodeError::kModalGroupConflict, w.col, code_text);
        }
        b->g[g->group] = static_cast<int16_t>(tenths);
        b->g_col[g->group] = w.col;
      } else {
        uint8_t group = 0;
        MKind k = classify_m(tenths, &group);
        if (k == MKind::kUnknown) return fail(d, GcodeError::kUnknownMcode, w.col, code_text);
        if (k == MKind::kUnsupported) return fail(d, GcodeError::kUnsupportedMcode, w.col, code_text);
        if (++b->m_count > 4) return fail(d, GcodeError::kTooManyMcodes, w.col, code_text);
        if (group == kMCoolant) {
          // LinuxCNC allows M7 and M8 together; M9 goes alone.
          uint8_t bit = static_cast<uint8_t>(tenths == 70 ? 1 : tenths == 80 ? 2 : 4);
          if ((b->coolant_bits & bit) || (b->coolant_bits && (bit == 4 || (b->coolant_bits & 4))))
            return fail(d, GcodeError::kModalGroupConflict, w.col, code_text);
          b->coolant_bits = static_cast<uint8_t>(b->coolant_bits | bit);
          b->m[group] = static_cast<int16_t>(tenths);
          b->m_col[group] = w.col;
          continue;
        }
        if (b->m[group] >= 0) return fail(d, GcodeError::kModalGroupConflict, w.col, code_text);
        b->m[group] = static_cast<int16_t>(tenths);
        b->m_col[group] = w.col;
      }
      continue;
    }
    const int li = gcode_word_index(w.letter);
    if (w.letter == 'A' || w.letter == 'B' || w.letter == 'C' || w.letter == 'U' || w.letter == 'V' ||
        w.letter == 'W') {
      const char letter_str[2] = {w.letter, 0};
      return fail(d, GcodeError::kUnsupportedAxis, w.col, letter_str);
    }
    // LinuxCNC reads a second '@' or '^' over the first (read_atsign, read_carat).
    if (((b->has >> li) & 1u) && w.letter != '@' && w.letter != '^') {
      const char letter_str[2] = {w.letter, 0};
      return fail(d, GcodeError::kDuplicateWord, w.col, letter_str);
    }
    b->has |= 1u << li;
    b->value[li] = w.value;
    b->col[li] = w.col;
  }
  for (int k = 0; k < nassign; ++k) {
    const Assignment& a = assign[k];
    const GcodeError e = a.ref.named ? param_set_named(params, a.ref.name, strlen(a.ref.name), a.value)
                                     : param_set(params, a.ref.number, a.value);
    if (e != GcodeError::kOk) {
      char word[kParamNameMax + 4];
      param_ref_text(a.ref, word);
      return fail(d, e, a.col, word);
    }
  }
  if (params && sc.message_kind()) {
    b->message_kind = static_cast<GcodeMessage>(sc.message_kind());
    format_message(s + sc.message_at(), sc.message_len(), *params, b->message_kind != GcodeMessage::kMsg, b->message);
  }
  return GcodeError::kOk;
}

}  // namespace dexmill
