// Machine descriptions: told apart by content and read (LinuxCNC INI and
// parameter files, grbl settings dumps); see machine_file.h.
#include "platform/format/machine_file.h"

#include <cerrno>
#include <cstdio>
#include <utility>

#include "platform/format/machine_text.h"
#include "platform/os/path_name.h"
#include "platform/os/read_file.h"

namespace dexmill {
namespace {

using namespace machine_text;


// ---------------------------------------------------------------- detection

enum class Kind : uint8_t { kUnknown, kIni, kGrbl };

// The heads of grbl's bracketed reports and messages.
bool grbl_head(const Span& h) {
  static const char* const kHeads[] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3", "G28",
                                       "G30", "G92", "TLO", "PRB", "GC",  "MSG", "VER",   "OPT",   "HLP",   "echo"};
  for (const char* k : kHeads)
    if (h.is(k)) return true;
  return false;
}

Kind kind_of_line(const Span& t) {
  if (t.s[0] == '$' || t.s[0] == '<' || t.starts("Grbl")) return Kind::kGrbl;
  if (t.s[0] != '[') return Kind::kUnknown;
  const std::size_t colon = t.find(':'), close = t.find(']');
  if (colon < close) return grbl_head(Span{t.s + 1, colon - 1, t.col + 1}) ? Kind::kGrbl : Kind::kUnknown;
  return close < t.n ? Kind::kIni : Kind::kUnknown;
}

bool detect(const char* name, const char* text, std::size_t n, Kind* kind, std::string* err) {
  Lines lines(name, text, n);
  Span l;
  uint32_t no = 0;
  for (;;) {
    const Next r = lines.next(&l, &no, err);
    if (r == Next::kBad) return false;
    if (r == Next::kEnd) break;
    const Span t = trim(l);
    if (!t.n || t.s[0] == '#' || t.s[0] == ';' || t.is("ok")) continue;
    *kind = kind_of_line(t);
    if (*kind != Kind::kUnknown) return true;
    break;
  }
  *err = error_at(name, 1, 1, kNotMachine);
  return false;
}

}  // namespace

bool machine_file_parse(const char* name, const char* text, std::size_t n, const std::string& dir, MachineFile* out,
                        std::string* err) {
  Kind kind = Kind::kUnknown;
  if (!detect(name, text, n, &kind, err)) return false;
  MachineFile f;
  const bool ok = kind == Kind::kGrbl ? parse_grbl(name, text, n, &f, err) : parse_ini(name, text, n, dir, &f, err);
  if (!ok) return false;
  *out = std::move(f);
  return true;
}

MachineLoad machine_file_load(const std::string& path, MachineFile* out, std::string* err) {
  std::vector<unsigned char> bytes;
  ReadFile r = read_whole_file(path, kMachineFileMaxBytes, &bytes, err);
  if (r == ReadFile::kIoError) return MachineLoad::kIoError;
  if (r != ReadFile::kOk) return MachineLoad::kInputError;
  MachineFile f;
  if (!machine_file_parse(path.c_str(), reinterpret_cast<const char*>(bytes.data()), bytes.size(), folder_of(path), &f,
                          err))
    return MachineLoad::kInputError;
  if (f.spec.kind == MachineKind::kLinuxcnc && !f.parameter_file.empty()) {
    // LinuxCNC makes the file on its first run: one not there yet is no
    // error (its restore_parameters says the same), and holds no offsets.
    errno = 0;
    std::FILE* probe = std::fopen(f.parameter_file.c_str(), "rb");
    if (!probe && errno == ENOENT) {
      f.parameter_file_missing = true;
    } else {
      if (probe) std::fclose(probe);
      r = read_whole_file(f.parameter_file, kMachineFileMaxBytes, &bytes, err);
      if (r == ReadFile::kIoError) return MachineLoad::kIoError;
      if (r != ReadFile::kOk) return MachineLoad::kInputError;
      if (!machine_var_parse(f.parameter_file.c_str(), reinterpret_cast<const char*>(bytes.data()), bytes.size(),
                             f.spec.inch, &f.spec, err))
        return MachineLoad::kInputError;
      if (f.disable_g92_persistence) f.spec.g92 = PointNm{0, 0, 0};
    }
  }
  *out = std::move(f);
  return MachineLoad::kOk;
}

}  // namespace dexmill
