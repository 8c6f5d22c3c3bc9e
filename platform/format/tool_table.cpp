// LinuxCNC tool table reader; see tool_table.h.
#include "platform/format/tool_table.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/math/decimal.h"
#include "core/tool/spec.h"
#include "core/tool/tool_comment.h"
#include "platform/os/read_file.h"

namespace dexmill {
namespace {

// A --tool spec among the comment's words, if any.
// A shape in a comment: the first word that is a tool spec. A word that
// names a shape (ball: flat: bull: vbit:) but does not parse is not
// skipped: *bad gets its offset and *why the reason, and false comes back,
// so the tool is not silently simulated as another shape.
bool spec_in_comment(const char* s, std::size_t n, Tool* out, std::size_t* bad, ToolSpecError* why) {
  std::size_t k = 0;
  *why = ToolSpecError::kOk;
  while (k < n) {
    while (k < n && std::isspace(static_cast<unsigned char>(s[k]))) ++k;
    std::size_t b = k;
    while (k < n && !std::isspace(static_cast<unsigned char>(s[k]))) ++k;
    if (k == b || !std::memchr(s + b, ':', k - b)) continue;
    const ToolSpecError e = tool_spec_parse(s + b, k - b, out);
    if (e == ToolSpecError::kOk) return true;
    if (e != ToolSpecError::kUnknownShape && *why == ToolSpecError::kOk) {
      *bad = b;
      *why = e;
    }
  }
  return false;
}

}  // namespace

void ToolTableFile::error_at(uint32_t line, std::size_t col, const std::string& what) {
  char head[600];
  std::snprintf(head, sizeof head, "%s:%u:%zu: error: ", name_.c_str(), static_cast<unsigned>(line), col);
  message_ = head + what;
}

const ToolTableEntry* ToolTableFile::find(int32_t number) const {
  for (const ToolTableEntry& e : entries_)
    if (e.number == number) return &e;
  return nullptr;
}

bool ToolTableFile::tool(int32_t number, Tool* out) const {
  const ToolTableEntry* e = find(number);
  if (!e || e->tool.diameter_nm == 0) return false;  // D0: no cutter
  *out = e->tool;
  return true;
}

bool ToolTableFile::tool_length_nm(int32_t number, int64_t* z_nm) const {
  const ToolTableEntry* e = find(number);
  if (!e) return false;
  *z_nm = e->length_offset_nm;
  return true;
}

bool ToolTableFile::tool_radius_nm(int32_t number, int64_t* r_nm) const {
  const ToolTableEntry* e = find(number);
  if (!e) return false;
  *r_nm = e->tool.diameter_nm / 2;  // LinuxCNC: D / 2 (an odd nm rounds down by half a nm)
  return true;
}

bool ToolTableFile::parse_line(const char* s, std::size_t n, uint32_t line, bool inch) {
  const char* semi = static_cast<const char*>(std::memchr(s, ';', n));
  const std::size_t words_end = semi ? static_cast<std::size_t>(semi - s) : n;
  ToolTableEntry e;
  e.line = line;
  bool have_t = false, have_d = false;
  std::size_t t_col = 1;
  int64_t diameter_nm = 0;
  std::size_t k = 0;
  while (k < words_end) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(s[k])));
    if (c == ' ' || c == '\t' || c == '\r') { ++k; continue; }
    const std::size_t col = k + 1;
    if (!std::strchr("TPDXYZABCUVWIJQ", c) || c == 0) {
      error_at(line, col, std::string("unknown word '") + s[k] + "' in the tool table (T P D X Y Z A B C U V W I J Q)");
      return false;
    }
    ++k;
    Decimal d;
    std::size_t pos = k;
    if (decimal_parse(s, words_end, &pos, &d) != DecimalParse::kOk) {
      error_at(line, col, std::string("'") + c + "' needs a number");
      return false;
    }
    k = pos;
    int64_t iv = 0;
    switch (c) {
      case 'T':
        if (!decimal_to_int(d, &iv) || iv < 0 || iv > 1000000000) {
          error_at(line, col, "the tool number must be a whole number from 0 to 1e9");
          return false;
        }
        e.number = static_cast<int32_t>(iv);
        have_t = true;
        t_col = col;
        break;
      case 'P':
        if (!decimal_to_int(d, &iv) || iv < 0 || iv > 1000000000) {
          error_at(line, col, "the pocket must be a whole number from 0 to 1e9");
          return false;
        }
        e.pocket = static_cast<int32_t>(iv);
        break;
      case 'D':
        diameter_nm = decimal_to_nm(d, inch);
        have_d = true;
        // D0 is common in LinuxCNC tables (a probe, a slot kept free): such
        // a tool reads, and cannot cut (tool() has none).
        if ((diameter_nm < kNmPerUm && diameter_nm != 0) || diameter_nm > 1000 * kNmPerMm) {
          error_at(line, col, "the diameter must be 0 or between 0.001 and 1000 mm");
          return false;
        }
        break;
      case 'Z':
        e.length_offset_nm = decimal_to_nm(d, inch);
        if (e.length_offset_nm > kGcodeMaxCoordNm || e.length_offset_nm < -kGcodeMaxCoordNm) {
          error_at(line, col, "the length offset is beyond +-10 m");
          return false;
        }
        break;
      default:  // other offsets and lathe fields: a 3-axis mill has no use for them
        break;
    }
  }
  const char* comment = semi ? semi + 1 : s + n;
  const std::size_t comment_n = semi ? n - words_end - 1 : 0;
  if (!have_t && !have_d) {
    return true;  // a comment line or a blank one
  }
  if (!have_t) {
    error_at(line, 1, "a tool needs a number (T)");
    return false;
  }
  if (!have_d) {
    error_at(line, t_col, "tool T" + std::to_string(e.number) + " has no diameter (D)");
    return false;
  }
  if (const ToolTableEntry* prev = find(e.number)) {
    error_at(line, t_col, "tool T" + std::to_string(e.number) + " is already defined on line " + std::to_string(prev->line));
    return false;
  }
  Tool t;
  std::size_t bad_at = 0;
  ToolSpecError why = ToolSpecError::kOk;
  const bool have_spec = spec_in_comment(comment, comment_n, &t, &bad_at, &why);
  if (!have_spec && why != ToolSpecError::kOk) {
    std::size_t end = bad_at;
    while (end < comment_n && !std::isspace(static_cast<unsigned char>(comment[end]))) ++end;
    error_at(line, static_cast<std::size_t>(comment - s) + bad_at + 1,
             "the shape '" + std::string(comment + bad_at, end - bad_at) + "' of T" + std::to_string(e.number) +
                 " is not usable: " + tool_spec_message(why));
    return false;
  }
  if (have_spec) {
    t.diameter_nm = diameter_nm;
    if (t.kind == ToolKind::kBullNose && t.corner_radius_nm > diameter_nm / 2) {
      error_at(line, t_col, "the corner radius of T" + std::to_string(e.number) + " is larger than D/2");
      return false;
    }
  } else {
    // No spec: the remark's kind words, read as a program's tool comments
    // are (core/tool/tool_comment.h); a row that names none is a flat end
    // mill, one whose shape cannot be completed is one with a warning.
    t = Tool();
    t.diameter_nm = diameter_nm;
    if (tool_remark_shape(comment, comment_n, &t.kind, &t.tip_angle_mdeg) == RemarkShape::kUnusable) {
      t.kind = ToolKind::kFlat;
      t.tip_angle_mdeg = 0;
      char w[700];
      std::snprintf(w, sizeof w,
                    "%s:%u:%zu: warning: T%d is simulated as a flat end mill; put its shape in the comment, e.g. "
                    "vbit:D:ANGLE or bull:D:R",
                    name_.c_str(), static_cast<unsigned>(line), t_col, static_cast<int>(e.number));
      warnings_.push_back(w);
    }
  }
  t.length_nm = tool_default_length_nm(t);
  if (diameter_nm != 0 && !ok(tool_check(t))) {
    error_at(line, t_col, "tool T" + std::to_string(e.number) + " is out of range");
    return false;
  }
  e.tool = t;
  entries_.push_back(e);
  return true;
}

ToolTableFile::Load ToolTableFile::parse(const char* name, const char* text, std::size_t n, bool inch) {
  name_ = name;
  entries_.clear();
  warnings_.clear();
  message_.clear();
  uint32_t line = 0;
  std::size_t b = 0;
  while (b < n) {
    const char* nl = static_cast<const char*>(std::memchr(text + b, '\n', n - b));
    const std::size_t e = nl ? static_cast<std::size_t>(nl - text) : n;
    ++line;
    if (!parse_line(text + b, e - b, line, inch)) return Load::kInputError;
    b = e + 1;
  }
  return Load::kOk;
}

ToolTableFile::Load ToolTableFile::load(const char* path, bool inch) {
  name_ = path;
  // A real table is a few kilobytes; a limit that is an error, never a cut.
  std::vector<unsigned char> text;
  std::string err;
  const ReadFile r = read_whole_file(path, kToolTableMaxBytes, &text, &err);
  if (r != ReadFile::kOk) {
    const std::string prefix = "dexmill: error: ";
    message_ = err.compare(0, prefix.size(), prefix) == 0 ? err.substr(prefix.size()) : err;
    return r == ReadFile::kTooLarge ? Load::kInputError : Load::kIoError;
  }
  return parse(path, reinterpret_cast<const char*>(text.data()), text.size(), inch);
}

}  // namespace dexmill
