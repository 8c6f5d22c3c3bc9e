// The values options take, read exactly (never through floating point):
// decimal numbers scaled to integers, WxH pairs, comma-separated mm lists,
// boxes, file extensions; and the one input file a subcommand takes.
#ifndef DEXMILL_TOOLS_CLI_OPTION_VALUES_H
#define DEXMILL_TOOLS_CLI_OPTION_VALUES_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace dexmill {
namespace cli {

// A decimal number as written, times `scale` (1e6 for mm -> nm, 1000 for
// s -> ms), rounded to nearest; false when s[0, n) is anything else.
bool parse_scaled(const char* s, std::size_t n, int64_t scale, int64_t* out);
bool parse_scaled(const char* s, int64_t scale, int64_t* out);

// "AxB" (or "AXB") with both whole numbers in [lo, hi].
bool parse_pair(const char* s, int64_t lo, int64_t hi, int32_t* a, int32_t* b);

// A size in bytes: a whole number of them, or of K, M or G (powers of 1024:
// KiB, MiB, GiB; either case), from 1 to what 64 bits hold; false for
// anything else (no sign, fraction or space; 0; past 2^64 - 1).
bool parse_size_bytes(const char* s, uint64_t* bytes);

// "A,B,C..." with exactly n numbers in mm, into nm, each within the range
// of G-code coordinates.
bool parse_mm_list(const char* s, int n, int64_t* v);

// "X0,Y0,Z0,X1,Y1,Z1" in mm with X0 < X1, Y0 < Y1, Z0 < Z1.
bool parse_box(const char* s, int64_t* v);

// True when `name` ends in `ext` (".stl"), in any case, after at least
// one other character.
bool has_extension(const std::string& name, const char* ext);

// The operand of a subcommand that takes one input file (index: how many
// came before it): into *file, or the usage error for a second one.
int take_file(std::string* file, const char* arg, int index);

}  // namespace cli
}  // namespace dexmill

#endif
