// core/gcode/lex.h and core/gcode/block.h: the forms of words and lines that
// real programs use, and the errors of malformed ones.
#include <cstring>

#include "core/gcode/block.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

GcodeError read(const char* s, GcodeBlock* b, GcodeLineKind* k, GcodeDiag* d) {
  return gcode_read_block(s, std::strlen(s), 7, b, k, d);
}

}  // namespace

TEST(lex_case_spaces_leading_zeros) {
  GcodeBlock b;
  GcodeLineKind k;
  GcodeDiag d;
  CHECK_EQ(read("g01 x 1 0 Y-.5 f0200.", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.g[kGMotion], 10);
  CHECK(b.has_word('X'));
  CHECK_EQ(b.val('X').mant, 10);
  CHECK_EQ(b.val('Y').mant, -5);
  CHECK_EQ(b.val('Y').frac, 1);
  CHECK_EQ(b.col_of('Y'), 11);
  CHECK_EQ(b.val('F').mant, 200);
  CHECK_EQ(read("G 1 X 1 0", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.g[kGMotion], 10);
  CHECK_EQ(b.val('X').mant, 10);
  CHECK_EQ(read("G38.2 Z-1 F10", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.g[kGMotion], 382);
  CHECK_EQ(read("G33.1 Z-1 K1", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.g[kGMotion], 331);
  CHECK_EQ(read("G76 P1 Z-1 I-0.1 J0.1 K0.2", &b, &k, &d), GcodeError::kUnsupportedGcode);
  CHECK_EQ(std::strcmp(d.word, "G76"), 0);
}

TEST(lex_comments_anywhere) {
  GcodeBlock b;
  GcodeLineKind k;
  GcodeDiag d;
  CHECK_EQ(read("G1 (comment) X2 (another)Y3 ; tail (not closed", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.val('X').mant, 2);
  CHECK_EQ(b.val('Y').mant, 3);
  CHECK_EQ(read("(only a comment)", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.has, 0u);
  CHECK_EQ(read("(non-ASCII \xc3\xa9 \xff inside)G0 X1", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.val('X').mant, 1);
  CHECK_EQ(read("G0 X1 (open", &b, &k, &d), GcodeError::kUnterminatedComment);
  CHECK_EQ(d.col, 7);
  CHECK_EQ(read("(a (b))", &b, &k, &d), GcodeError::kNestedComment);
  CHECK_EQ(d.col, 4);
  CHECK_EQ(read("G0 X1 )", &b, &k, &d), GcodeError::kStrayCloseParen);
  CHECK_EQ(d.col, 7);
}

TEST(lex_line_forms) {
  GcodeBlock b;
  GcodeLineKind k;
  GcodeDiag d;
  CHECK_EQ(read("%", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(k, GcodeLineKind::kPercent);
  CHECK_EQ(read("  % (start)\r", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(k, GcodeLineKind::kPercent);
  CHECK_EQ(read("O1234 (name)", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(k, GcodeLineKind::kProgramNumber);
  CHECK_EQ(read("o100 sub", &b, &k, &d), GcodeError::kUnsupportedOword);
  CHECK_EQ(std::strcmp(d.word, "O100"), 0);
  CHECK_EQ(read("$H", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(k, GcodeLineKind::kGrblCommand);
  CHECK_EQ(std::strcmp(d.word, "$H"), 0);
  CHECK_EQ(read("/G0 X1", &b, &k, &d), GcodeError::kOk);
  CHECK(b.block_delete);
  CHECK_EQ(read("N10 G0 X1\r", &b, &k, &d), GcodeError::kOk);  // CR of CRLF
  CHECK_EQ(b.val('X').mant, 1);
  CHECK_EQ(read("G0\tX1\tY2", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.val('Y').mant, 2);
  CHECK_EQ(read("", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(k, GcodeLineKind::kBlock);
}

TEST(lex_errors) {
  GcodeBlock b;
  GcodeLineKind k;
  GcodeDiag d;
  CHECK_EQ(read("G0 X", &b, &k, &d), GcodeError::kMissingNumber);
  CHECK_EQ(d.col, 4);
  CHECK_EQ(read("G0 X-", &b, &k, &d), GcodeError::kBadNumber);
  CHECK_EQ(read("G0 X1 X2", &b, &k, &d), GcodeError::kDuplicateWord);
  CHECK_EQ(d.col, 7);
  CHECK_EQ(read("G0 G1", &b, &k, &d), GcodeError::kModalGroupConflict);
  CHECK_EQ(read("G0 G80 X1", &b, &k, &d), GcodeError::kOk);  // LinuxCNC drops the G80
  CHECK_EQ(b.g[kGMotion], 0);
  CHECK_EQ(read("G1.55", &b, &k, &d), GcodeError::kCodeNotInTenths);
  CHECK_EQ(read("G-1", &b, &k, &d), GcodeError::kNegativeValue);
  CHECK_EQ(read("M3 M4", &b, &k, &d), GcodeError::kModalGroupConflict);
  CHECK_EQ(read("M7 M8", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(b.coolant_bits, 3);
  CHECK_EQ(read("M8 M9", &b, &k, &d), GcodeError::kModalGroupConflict);
  CHECK_EQ(read("X1 #2", &b, &k, &d), GcodeError::kUnsupportedParameter);
  CHECK_EQ(read("X[1]", &b, &k, &d), GcodeError::kUnsupportedExpression);
  CHECK_EQ(read("G0 A1", &b, &k, &d), GcodeError::kUnsupportedAxis);
  CHECK_EQ(read("G0 X1 \x80", &b, &k, &d), GcodeError::kBadCharacter);
  CHECK_EQ(std::strcmp(d.word, "\\x80"), 0);
  CHECK_EQ(read("G0 N5", &b, &k, &d), GcodeError::kLineNumberNotFirst);
  char long_line[kGcodeMaxLine + 2];
  std::memset(long_line, ' ', sizeof long_line);
  long_line[kGcodeMaxLine + 1] = 0;
  CHECK_EQ(read(long_line, &b, &k, &d), GcodeError::kLineTooLong);
  long_line[kGcodeMaxLine] = 0;
  CHECK_EQ(read(long_line, &b, &k, &d), GcodeError::kOk);  // exactly the limit is fine
}

// A stray letter is a typo, not a feature dexmill lacks: LinuxCNC reads an
// o-word only at the start of a line, and '@'/'^' only with a number.
TEST(lex_stray_letters_are_typos) {
  GcodeBlock b;
  GcodeLineKind k;
  GcodeDiag d;
  CHECK_EQ(read("G1 Y1O F100", &b, &k, &d), GcodeError::kMisplacedOword);
  CHECK_EQ(d.col, 6);
  CHECK_EQ(std::strcmp(d.word, "O"), 0);
  CHECK_EQ(read("N10 O100 sub", &b, &k, &d), GcodeError::kUnsupportedOword);  // after N it starts the line
  CHECK_EQ(std::strcmp(d.word, "O100"), 0);
  CHECK_EQ(read("/o100 sub", &b, &k, &d), GcodeError::kUnsupportedOword);
  CHECK_EQ(read("G1 @ F100", &b, &k, &d), GcodeError::kMissingNumber);
  CHECK_EQ(d.col, 4);
  CHECK_EQ(std::strcmp(d.word, "@"), 0);
  CHECK_EQ(read("G1 X1 ^", &b, &k, &d), GcodeError::kMissingNumber);
  CHECK_EQ(read("G1 @-", &b, &k, &d), GcodeError::kBadNumber);
  // With a number, LinuxCNC's polar words: read like any word (slots 31 and
  // 29 of GcodeBlock), a second one over the first as LinuxCNC reads them.
  CHECK_EQ(read("G1 @ 5 ^90", &b, &k, &d), GcodeError::kOk);
  CHECK(b.has_polar());
  CHECK(b.has_axis());
  CHECK(b.has_word('@') && b.has_word('^'));
  CHECK_EQ(b.col_of('@'), 4);
  CHECK_EQ(b.col_of('^'), 8);
  CHECK_EQ(decimal_to_nm(b.val('@'), false), 5000000);
  CHECK_EQ(decimal_to_nm(b.val('^'), false), 90000000);
  CHECK_EQ(read("G1 @1 @2 ^3 ^4", &b, &k, &d), GcodeError::kOk);
  CHECK_EQ(decimal_to_nm(b.val('@'), false), 2000000);
  CHECK_EQ(decimal_to_nm(b.val('^'), false), 4000000);
  CHECK_EQ(read("G1 X1 Z2", &b, &k, &d), GcodeError::kOk);
  CHECK(!b.has_polar());
  // A computed polar value needs parameters, like any word's.
  CHECK_EQ(read("G1 ^#1", &b, &k, &d), GcodeError::kUnsupportedParameter);
  CHECK_EQ(read("G1 @[1]", &b, &k, &d), GcodeError::kUnsupportedExpression);
}
