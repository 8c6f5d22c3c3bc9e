// LinuxCNC tool tables (the `--tools FILE` of `dexmill run`):
//
//   T1 P1 D6.0 Z+30.0 ;flat end mill 6 mm
//   T2 P2 D6.0 Z+35.0 ;ball end 6 mm
//   T3 P3 D5.0 Z+40.0 ;spot drill vbit:5:118
//
// One tool a line; words T (number, required), P (pocket), D (diameter,
// required), X Y Z A B C U V W (offsets; Z is the length that G43 applies),
// I J Q (lathe fields, ignored); ';' starts the comment; blank lines and
// lines holding only a comment are skipped. Lengths are in mm, or in inch
// when load/parse are told so (the units the caller chose by
// core/sim/tool_units.h's rule: the program's, not the machine's as in
// LinuxCNC).
//
// LinuxCNC's table has no shape field, so the shape comes from the comment:
//   1. a word of the comment that is a --tool spec (`ball:6`, `bull:10:1.5`,
//      `vbit:5:118`, with ,len=L) gives the shape, corner radius or angle and
//      flute length; the diameter is always the table's D;
//   2. otherwise a comment containing "ball" makes a ball end;
//   3. otherwise the tool is a flat end mill. A comment that names "bull",
//      "vbit", "v-bit" or "engrav" without a spec gets a warning, since the
//      flat shape is then a guess.
#ifndef DEXMILL_PLATFORM_FORMAT_TOOL_TABLE_H
#define DEXMILL_PLATFORM_FORMAT_TOOL_TABLE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/cut/mill.h"
#include "core/sim/job.h"  // SingleToolLibrary
#include "core/interp/interp.h"
#include "core/tool/tool.h"

namespace dexmill {

struct ToolTableEntry {
  int32_t number = 0;
  int32_t pocket = 0;
  Tool tool;
  int64_t length_offset_nm = 0;  // Z, for G43
  uint32_t line = 0;             // where it was defined
};

// The largest table file read (a real one is a few kilobytes).
constexpr std::size_t kToolTableMaxBytes = std::size_t{64} << 20;

class ToolTableFile final : public ToolLibrary, public ToolTable {
 public:
  enum class Load : uint8_t { kOk, kIoError, kInputError };

  // Reads a table file. On failure message() holds the whole error line:
  // "FILE:LINE:COL: error: ..." (kInputError) or "cannot open ..." (kIoError).
  Load load(const char* path, bool inch);
  // The same from text in memory; `name` is used in messages.
  Load parse(const char* name, const char* text, std::size_t n, bool inch);

  // False for a tool the table lacks, and for one of diameter 0 (D0: no cutter).
  bool tool(int32_t number, Tool* out) const override;
  // The table has the tool (of any diameter).
  bool has(int32_t number) const { return find(number) != nullptr; }
  bool tool_length_nm(int32_t number, int64_t* z_nm) const override;
  bool tool_radius_nm(int32_t number, int64_t* r_nm) const override;

  const std::vector<ToolTableEntry>& entries() const { return entries_; }
  const std::string& message() const { return message_; }
  // "FILE:LINE:COL: warning: ..." lines.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::string& name() const { return name_; }

 private:
  const ToolTableEntry* find(int32_t number) const;
  bool parse_line(const char* s, std::size_t n, uint32_t line, bool inch);
  void error_at(uint32_t line, std::size_t col, const std::string& what);

  std::string name_;
  std::vector<ToolTableEntry> entries_;
  std::string message_;
  std::vector<std::string> warnings_;
};

}  // namespace dexmill

#endif
