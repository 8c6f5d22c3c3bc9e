// The words and numbers of a comment a CAM post wrote, as the tool comment
// recogniser (core/tool/tool_comment.h) reads them: ASCII letters in either
// case, amounts as decimals or inch fractions, their length units and
// degrees. Integer only; bytes above 0x7f are neither letters nor digits
// (UTF-8 text such as "Fräser" or "°" passes through as other bytes).
#ifndef DEXMILL_CORE_TOOL_COMMENT_TEXT_H
#define DEXMILL_CORE_TOOL_COMMENT_TEXT_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

inline bool text_is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool text_is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline bool text_is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }
inline char text_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// s[at, n) begins with w (lower case), ignoring case.
bool text_has_at(const char* s, size_t n, size_t at, const char* w);
// The first place at or after `from` where w begins a word (no letter just
// before it); with `whole`, also no letter just after it (a digit may follow:
// "Endmill001"). n when there is none.
size_t text_find(const char* s, size_t n, const char* w, bool whole, size_t from = 0);
inline bool text_has_word(const char* s, size_t n, const char* w) { return text_find(s, n, w, true) < n; }
inline bool text_has_prefix(const char* s, size_t n, const char* w) { return text_find(s, n, w, false) < n; }
size_t text_skip_spaces(const char* s, size_t n, size_t at);
// Runs of bytes that are not white space.
int text_word_count(const char* s, size_t n);
// Up to six digits at s[*pos] (a tool number) as their value, *pos moved
// past them; *digits how many there were (0: none, value 0).
int32_t text_read_digits(const char* s, size_t n, size_t* pos, int* digits);

// An unsigned amount at s[*pos]: a decimal (12, 12.5, .5, 12.) or an inch
// fraction (1/4, a whole part before it: 1 1/4, 1-1/4), as 1e-9 units,
// rounded to nearest. A digit or letter just before it makes it part of a
// word, not an amount (T1, 2D). False when there is none (*pos unchanged),
// or when its whole part exceeds 10^8; else *pos is just past it.
bool text_read_amount(const char* s, size_t n, size_t* pos, int64_t* e9);
// The same whatever comes before it (R1.5: a corner radius after its letter).
bool text_read_amount_here(const char* s, size_t n, size_t* pos, int64_t* e9);
// The same with an optional sign before it.
bool text_read_signed(const char* s, size_t n, size_t* pos, int64_t* e9);

enum class TextUnit : uint8_t { kNone = 0, kMm = 1, kInch = 2 };
// A length unit at s[*pos], after spaces: mm, millimeter(s), in, inch,
// inches, " (and '' for it). A letter just after it makes it another word
// ("2 inserts"). kNone (*pos unchanged) when there is none.
TextUnit text_read_unit(const char* s, size_t n, size_t* pos);
// Degrees at s[*pos], after spaces or one '-': deg, degree(s), or the
// UTF-8 degree sign. False (*pos unchanged) when there are none.
bool text_read_degrees(const char* s, size_t n, size_t* pos);

}  // namespace dexmill

#endif
