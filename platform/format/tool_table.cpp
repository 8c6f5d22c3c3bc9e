// LinuxCNC tool table reader; see tool_table.h.
#include "platform/format/tool_table.h"

#include <cstdio>
#include <cstring>

#include "core/tool/table_row.h"
#include "platform/os/read_file.h"

namespace dexmill {
namespace {

static_assert(kToolRowMaxOffsetNm == kGcodeMaxCoordNm, "a table's offsets are the interpreter's coordinates");

// ToolRowDefined over the table's entries.
uint32_t defined_on(const void* ctx, int32_t number) {
  for (const ToolTableEntry& e : *static_cast<const std::vector<ToolTableEntry>*>(ctx))
    if (e.number == number) return e.line;
  return 0;
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

// The row is core's (core/tool/table_row.h); here its place and the list.
bool ToolTableFile::parse_line(const char* s, std::size_t n, uint32_t line, bool inch) {
  ToolRow r;
  ToolRowFault f;
  char msg[600];
  if (tool_table_row(s, n, inch, defined_on, &entries_, &r, &f) != ToolRowError::kOk) {
    tool_row_message(f, msg, sizeof msg);
    error_at(line, f.col, msg);
    return false;
  }
  if (r.empty) return true;
  if (r.flat_guess) {
    char w[800];
    tool_row_warning(r, msg, sizeof msg);
    std::snprintf(w, sizeof w, "%s:%u:%u: warning: %s", name_.c_str(), static_cast<unsigned>(line),
                  static_cast<unsigned>(r.t_col), msg);
    warnings_.push_back(w);
  }
  ToolTableEntry e;
  e.number = r.number;
  e.pocket = r.pocket;
  e.tool = r.tool;
  e.length_offset_nm = r.length_offset_nm;
  e.line = line;
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
