// G-code input errors and warnings (core/README.md, habit 4): one enum class with
// stable numbers and one message table, returned and never thrown.
//
// A diagnostic carries the 1-based line and column of the offending word, the
// word's text (for messages such as "G41 ... is not supported") and up to two
// lengths in nanometres (for messages that quote radii). gcode_format_message()
// turns it into text without any I/O, so a controller can show it on its panel;
// the hosted reader (platform/input/gcode_file.h) prefixes `FILE:LINE:COL: error: `.
#ifndef DEXMILL_CORE_GCODE_ERROR_H
#define DEXMILL_CORE_GCODE_ERROR_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

// Numbers are stable: tests and users may quote them. Add at the end of a range.
// 16 bits: 0..255 are used, and numbers are never reused.
enum class GcodeError : uint16_t {
  kOk = 0,
  // -- reading the line (1..39)
  kLineTooLong = 1,
  kBadCharacter = 2,
  kUnknownWord = 3,
  kMissingNumber = 4,
  kBadNumber = 5,
  kNumberTooLarge = 6,
  kUnterminatedComment = 7,
  kNestedComment = 8,
  kNotInteger = 9,
  kNegativeValue = 10,
  kCodeNotInTenths = 11,
  kUnknownGcode = 12,
  kUnknownMcode = 13,
  kModalGroupConflict = 14,
  kDuplicateWord = 15,
  kLineNumberNotFirst = 16,
  kTooManyMcodes = 17,
  kStrayCloseParen = 18,
  kNotText = 19,
  kUtf16Text = 20,
  kMisplacedOword = 21,
  // parameters and expressions
  kExprDivideByZero = 22,
  kExprDomain = 23,
  kExprOutOfRange = 24,
  kExprSyntax = 25,
  kExprUnknownFunction = 26,
  kParamNumberRange = 27,
  kParamUnknownName = 28,
  kParamReadOnly = 29,
  kParamNameTooLong = 30,
  kTooManyNamedParams = 31,
  kTooManyAssignments = 32,
  kExprTooDeep = 33,
  // -- checking the block (40..99)
  kFeedZero = 40,
  kInverseTimeNoF = 41,
  kArcNoCentre = 42,
  kArcRadiusMismatch = 43,
  kArcZeroRadius = 44,
  kArcRSameEnds = 45,
  kArcRTooSmall = 46,
  kArcWordWrongPlane = 47,
  kArcRAndIjk = 48,
  kAxisWordsWithG80 = 49,
  kAxisWordsUnused = 50,
  kTwoAxisUsers = 51,
  kG53BadMotion = 52,
  kCycleNoR = 53,
  kCycleNoZ = 54,
  kCycleRBelowZ = 55,
  kCycleNoP = 56,
  kCycleNoQ = 57,
  kCycleQNotPositive = 58,
  kCycleZeroRepeats = 59,
  kCycleInverseTime = 60,
  kG10NoL = 61,
  kG10BadL = 62,
  kG10BadP = 63,
  kG92NoAxis = 64,
  kDwellNoP = 65,
  kWordUnused = 66,
  kPositionOutOfRange = 67,
  kTurnsNotPositive = 68,
  kG43NoTool = 69,
  kToolUnknown = 70,
  kG10PNeeded = 71,
  kLineNumberTooLarge = 72,
  kG53Incremental = 73,
  kCycleNoIjk = 74,
  kCycleSpindleStopped = 75,
  kCycleSpindleWrongWay = 76,
  kCyclePeckCount = 77,
  kProbeNoAxis = 78,
  kProbeTooClose = 79,
  // cutter radius compensation (G40, G41, G42, G41.1, G42.1; LinuxCNC's rules)
  kCompOnWhenOn = 80,
  kCompPlane = 81,
  kCompChangePlane = 82,
  kCompForbidden = 83,
  kCompNoD = 84,
  kCompEntryTooShort = 85,
  kCompEntryArcTooShort = 86,
  kCompArcTooSmall = 87,
  kCompConcaveStraight = 88,
  kCompConcaveArc = 89,
  kCompLineArcGouge = 90,
  kCompArcSameCentre = 91,
  kCompArcArcGouge = 92,
  kCompArcLineGouge = 93,
  kCompArcAfterExit = 94,
  kCompQueueFull = 95,
  kCompInternal = 96,
  // probes that touch the simulated stock (core/interp/interp.h ProbeSensor)
  kProbeAlreadyTripped = 97,
  kProbeNotTripped = 98,
  kProbeNoContact = 99,
  // -- recognised but not supported (100..139)
  kUnsupportedOword = 100,
  kUnsupportedParameter = 101,
  kUnsupportedExpression = 102,
  kUnsupportedAxis = 103,
  kUnsupportedGcode = 104,
  kUnsupportedMcode = 105,
  kUnsupportedCutterComp = 106,  // no longer raised (compensation is supported); number kept
  // 107 was polar coordinates, read since (kPolar*)
  kUnsupportedRotation = 108,  // no longer raised (G10 L2 R turns a system); number kept
  kUnsupportedCompOrientation = 109,
  kUnsupportedContextComp = 110,
  // -- warnings (140..): the line was skipped or a word ignored, safely
  kWarnMcodeIgnored = 140,
  kWarnGrblCommand = 141,
  kWarnG10ToolTable = 142,
  kWarnAfterEnd = 143,
  kWarnNoProgramEnd = 144,
  kWarnNoClosingPercent = 145,
  kWarnEmptyProgram = 146,
  kWarnNoMotion = 147,
  kWarnDefaultFeed = 148,
  kWarnFastFeed = 149,
  kWarnFastSpindle = 150,
  kWarnProbe = 151,
  kWarnTapPlane = 152,
  kWarnCycleLevelMoved = 153,
  kWarnMcodeMachine = 154,
  kWarnManualRetract = 155,
  kWarnDiameterMode = 156,
  kWarnCompNoTable = 157,
  kWarnM99Main = 158,
  kWarnG49H = 159,
  kWarnContextRest = 160,
  kWarnUnitsNotSet = 161,
  kWarnUnitsLookInch = 162,
  kWarnFeedBeforeUnits = 163,
  // -- o-word control flow (200..229; errors, though after the warnings:
  // the ranges above were full)
  kOwordBadLabel = 200,
  kOwordUnknownStatement = 201,
  kOwordTextAfter = 202,
  kOwordNoValue = 203,
  kOwordTooManyArgs = 204,
  kOwordUndefinedLabel = 205,
  kOwordLabelKind = 206,
  kOwordDuplicateLabel = 207,
  kOwordNotInSub = 208,
  kOwordNestedSub = 209,
  kOwordSubRedefined = 210,
  kOwordSubAgain = 211,
  kOwordCallDepth = 212,
  kOwordSubNotFound = 213,
  kOwordTooManyLabels = 214,
  kOwordUnclosed = 215,
  kOwordNoSource = 216,
  kOwordSeek = 217,
  kBlockLimit = 218,
  kOwordFanucMix = 220,
  kM98NoP = 221,
  // -- polar coordinates (@ ^) and splines (G5, G5.1), as LinuxCNC 2.9 checks
  // them (230..; block checks: 40..99 was full)
  kPolarWithXY = 230,
  kPolarPlane = 231,
  kPolarNotMotion = 232,
  kPolarG53 = 233,
  kPolarNoAngle = 234,
  kPolarIncrementalOrigin = 235,
  kSplinePlane = 236,
  kSplineZ = 237,
  kSplineIJ = 238,
  kSplinePQ = 239,
  kSplineNoAxis = 240,
  // spindle-synchronised motion G33 and rigid tapping G33.1
  kSyncNoPitch = 241,
  kSyncFeedWord = 242,
  kSyncNoAxis = 243,
  kSyncPitchNotPositive = 244,
  kFeedPerRevNoSpeed = 245,
  kTloAddHAndAxes = 246,
  kTloAddNothing = 247,
  kContextNone = 248,
  kG10L20Rotation = 249,
  kNurbsXY = 250,
  kNurbsPOnlyFirst = 251,
  kNurbsWeight = 252,
  kNurbsNoStart = 253,
  kNurbsTooFew = 254,
  kNurbsTooMany = 255,
};

// Stable number of an error, for messages and tests.
inline int gcode_error_number(GcodeError e) { return static_cast<int>(e); }
// True for the warning range (the line still ran, or was skipped safely).
inline bool gcode_is_warning(GcodeError e) { return static_cast<int>(e) >= 140 && static_cast<int>(e) < 200; }

struct GcodeDiag {
  GcodeError code;
  uint32_t line;   // 1-based
  uint16_t col;    // 1-based byte column of the offending word (1 if none)
  char word[16];   // text of the word as written (upper case), NUL-terminated
  int64_t a_nm;    // lengths quoted by the message ({a}, {b}), nm
  int64_t b_nm;
  // The error may be only a consequence of an earlier one (an earlier bad
  // block left the state it reads unknown; core/interp/interp_follow_on.cpp).
  bool follow_on;
};

// The template of a message: `{w}` stands for diag.word, `{a}`/`{b}` for
// a_nm/b_nm printed in mm with 4 decimals, `{n}` for a_nm as a whole
// number (a count). Never null.
const char* gcode_error_template(GcodeError e);

// Writes the message of `d` (without file, line or column) into buf, NUL
// terminated, truncating to n - 1 bytes. Returns the length written.
size_t gcode_format_message(const GcodeDiag& d, char* buf, size_t n);

// Receives warnings as they happen (errors are returned instead).
class GcodeDiagSink {
 public:
  virtual void warning(const GcodeDiag& d) = 0;

 protected:
  ~GcodeDiagSink() = default;
};

// Where a program's message comments go (DEBUG, PRINT, MSG):
// kind 1 DEBUG, 2 PRINT, 3 MSG (core/gcode/block.h GcodeMessage), the text
// as LinuxCNC would show it.
class GcodeMessageSink {
 public:
  virtual void message(uint32_t line, int kind, const char* text) = 0;

 protected:
  ~GcodeMessageSink() = default;
};

}  // namespace dexmill

#endif
