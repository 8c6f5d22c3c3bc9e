// One block (line) of G-code, read and sorted but not yet interpreted
// (grbl's and LinuxCNC's first step: read words, then check, then commit).
//
// G and M codes are integers in tenths (G38.2 = 382, M6 = 60), like
// LinuxCNC. Each G code belongs to one modal group, and a block holds at
// most one code per group; value words (X, F, P, ...) appear at most once.
#ifndef DEXMILL_CORE_GCODE_BLOCK_H
#define DEXMILL_CORE_GCODE_BLOCK_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/error.h"
#include "core/gcode/params.h"
#include "core/math/decimal.h"

namespace dexmill {

// Longest line accepted, in bytes without the line end (LinuxCNC: 256).
constexpr size_t kGcodeMaxLine = 256;
// A message comment's text, with its parameters substituted (bytes, NUL
// included; longer text is cut).
constexpr size_t kGcodeMessageMax = 160;
// Parameter assignments on one line (LinuxCNC has no fixed limit).
constexpr int kGcodeAssignMax = 32;

enum class GcodeMessage : uint8_t { kNone = 0, kDebug = 1, kPrint = 2, kMsg = 3 };

// Modal groups of G codes (numbers as in RS274/NGC and LinuxCNC).
enum GGroup : uint8_t {
  kGNonModal = 0,     // G4 G10 G28 G28.1 G30 G30.1 G53 G92 G92.1 G92.2 G92.3
  kGMotion = 1,       // G0 G1 G2 G3 G5 G5.1 G38.x G73 G74 G80-G89 (and the unsupported ones)
  kGPlane = 2,        // G17 G18 G19
  kGDistance = 3,     // G90 G91
  kGArcDistance = 4,  // G90.1 G91.1
  kGFeedMode = 5,     // G93 G94 G95
  kGUnits = 6,        // G20 G21
  kGCutterComp = 7,   // G40
  kGToolLength = 8,   // G43 G43.1 G49
  kGRetract = 9,      // G98 G99 (RS274/NGC group 10)
  kGCoordSystem = 10, // G54..G59.3 (group 12)
  kGPathControl = 11, // G61 G61.1 G64 (group 13)
  kGSpindleMode = 12, // G97 (group 14)
  kGLathe = 13,       // G7 G8 (group 15: lathe diameter/radius mode; G7 halves X words, as LinuxCNC)
  kGGroupCount = 14,
};

// Groups of M codes we keep apart (LinuxCNC numbering in comments).
enum MGroup : uint8_t {
  kMStop = 0,      // group 4: M0 M1 M2 M30 M60
  kMToolChange,    // group 6: M6 M61
  kMSpindle,       // group 7: M3 M4 M5 M19
  kMCoolant,       // group 8: M7 M8 M9 (M7 and M8 may share a block)
  kMOverride,      // group 9: M48..M53
  kMIo,            // group 5: M62..M68
  kMUser,          // group 10: M100..M199, and other M codes a machine may remap (M25)
  kMContext,       // M70 M71 M72 M73: modal state saved and restored
  kMGroupCount,
};

// Value words: the letters 'A'..'Z' at 0..25, and LinuxCNC's polar words
// '^' (angle, degrees) at 29 and '@' (distance from the origin) at 31:
// (letter - 'A') mod 32 for all of them, without a branch.
constexpr int kGcodeWordSlots = 32;
constexpr int gcode_word_index(char letter) { return (letter - 'A') & 31; }

struct GcodeBlock {
  uint32_t line;
  bool block_delete;           // leading '/' (the switch is off: the block runs)
  // Value words, indexed by gcode_word_index().
  uint32_t has;                // bit i set: word i present
  Decimal value[kGcodeWordSlots];
  uint16_t col[kGcodeWordSlots];
  // G codes in tenths, one per group; -1 when absent.
  int16_t g[kGGroupCount];
  uint16_t g_col[kGGroupCount];
  // M codes in tenths, one per group; -1 when absent. Coolant may hold both
  // M7 and M8: coolant_bits has bit 0 for M7, bit 1 for M8, bit 2 for M9.
  int16_t m[kMGroupCount];
  uint16_t m_col[kMGroupCount];
  uint8_t coolant_bits;
  uint8_t m_count;
  uint16_t first_col;          // column of the first word (1 if none)
  // A (DEBUG,...), (PRINT,...) or (MSG,...) comment (read with parameters):
  // DEBUG and PRINT with #n and #<name> replaced by their values after the
  // line's assignments, as LinuxCNC prints them (6 decimals).
  GcodeMessage message_kind;
  char message[kGcodeMessageMax];

  bool has_word(char letter) const { return (has >> gcode_word_index(letter)) & 1u; }
  uint16_t col_of(char letter) const { return col[gcode_word_index(letter)]; }
  const Decimal& val(char letter) const { return value[gcode_word_index(letter)]; }
  // No word at all (a blank or comment-only line; N alone counts as none).
  bool empty() const {
    for (int i = 0; i < kGGroupCount; ++i)
      if (g[i] >= 0) return false;
    return has == 0 && m_count == 0;
  }
  // A polar word ('@' or '^'): LinuxCNC's polar_flag.
  static constexpr uint32_t kPolarBits = (1u << gcode_word_index('@')) | (1u << gcode_word_index('^'));
  bool has_polar() const { return (has & kPolarBits) != 0; }
  // X, Y, Z or a polar word: what LinuxCNC's axis_flag || polar_flag asks.
  bool has_axis() const {
    return (has & ((1u << ('X' - 'A')) | (1u << ('Y' - 'A')) | (1u << ('Z' - 'A')) | kPolarBits)) != 0;
  }
};

// What a line is, besides a block of words.
enum class GcodeLineKind : uint8_t {
  kBlock = 0,          // words (possibly none: blank or comment-only line)
  kPercent = 1,        // a '%' delimiter line
  kProgramNumber = 2,  // `O1234` alone (Fanuc program number): nothing to do
  kGrblCommand = 3,    // a grbl `$...` system command (diag.word holds it)
};

// Reads one line (without its line end; a trailing '\r' is fine) into *b.
// On an error, fills *d (code, col, word) and returns the code; *b is then
// unspecified. `line` is stored in b->line and d->line.
[[nodiscard]] GcodeError gcode_read_block(const char* text, size_t len, uint32_t line, GcodeBlock* b,
                                          GcodeLineKind* kind, GcodeDiag* d);
// The same with parameters: values may be computed from them,
// and the line's assignments (#n = value, #<name> = value) are made after
// the whole line was read (values on the line see the old ones), only when
// the line has no error.
[[nodiscard]] GcodeError gcode_read_block(const char* text, size_t len, uint32_t line, GcodeBlock* b,
                                          GcodeLineKind* kind, GcodeDiag* d, ParamStore* params);

// The modal group (GGroup) of a G code LinuxCNC knows, in tenths; -1 if none.
int gcode_g_group(int64_t tenths);

// Text of a code for diagnostics: "G38.2", "M6".
void gcode_code_text(char letter, int32_t tenths, char* buf16);

}  // namespace dexmill

#endif
