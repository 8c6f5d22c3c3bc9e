// The message table of G-code input errors, and the formatter that fills in
// a diagnostic's word and lengths (no stdio: this runs on a controller too).
#include "core/gcode/error.h"

#include "core/math/fixed.h"
#include "core/math/text_out.h"

namespace dexmill {

const char* gcode_error_template(GcodeError e) {
  switch (e) {
    case GcodeError::kOk: return "no error";
    case GcodeError::kLineTooLong: return "line is longer than {n} characters";
    case GcodeError::kBadCharacter: return "unexpected character '{w}' (not part of any G-code word)";
    case GcodeError::kUnknownWord: return "unknown word starting with '{w}'";
    case GcodeError::kMissingNumber: return "'{w}' is not followed by a number";
    case GcodeError::kBadNumber: return "bad number format after '{w}'";
    case GcodeError::kNumberTooLarge: return "number too large for '{w}'";
    case GcodeError::kUnterminatedComment: return "comment is not closed: '(' without ')' on the same line";
    case GcodeError::kNestedComment: return "nested comment: '(' inside a comment";
    case GcodeError::kNotInteger: return "{w}: the value must be an integer";
    case GcodeError::kNegativeValue: return "{w}: the value must not be negative";
    case GcodeError::kCodeNotInTenths: return "{w}: G and M codes have at most one decimal (like G38.2)";
    case GcodeError::kUnknownGcode: return "unknown G code {w}";
    case GcodeError::kUnknownMcode: return "unknown M code {w}";
    case GcodeError::kModalGroupConflict: return "{w}: two codes of the same modal group in one block";
    case GcodeError::kDuplicateWord: return "word '{w}' appears twice in one block";
    case GcodeError::kLineNumberNotFirst: return "line number {w} must be the first word of the line";
    case GcodeError::kTooManyMcodes: return "{w}: more than 4 M codes in one block";
    case GcodeError::kStrayCloseParen: return "')' without '(' (malformed comment)";
    case GcodeError::kNotText: return "not a text file (binary data, such as the byte {w}; G-code is plain text)";
    case GcodeError::kUtf16Text: return "the file is UTF-16 text; save it as UTF-8 or ASCII";
    case GcodeError::kMisplacedOword: return "'{w}' in the middle of a block: o-words start their line (a 0 typed as O?)";
    case GcodeError::kExprDivideByZero: return "{w}: division by zero";
    case GcodeError::kExprDomain: return "{w}: argument outside the function's domain (a root or power of a negative, LN of 0 or less, ACOS/ASIN beyond 1)";
    case GcodeError::kExprOutOfRange: return "{w}: result out of range (beyond 1e9)";
    case GcodeError::kExprSyntax: return "bad expression at '{w}' (an unknown operator, or a missing ']')";
    case GcodeError::kExprUnknownFunction: return "unknown function '{w}'";
    case GcodeError::kParamNumberRange: return "parameter {w} out of range (#1 to #5602)";
    case GcodeError::kParamUnknownName: return "named parameter {w} used before it was set";
    case GcodeError::kParamReadOnly: return "parameter {w} is read-only (the interpreter's own value)";
    case GcodeError::kParamNameTooLong: return "parameter name {w} is empty or longer than 31 characters";
    case GcodeError::kTooManyNamedParams: return "{w}: more than 200 named parameters (dexmill's fixed limit)";
    case GcodeError::kTooManyAssignments: return "{w}: more than 32 parameter assignments on one line";
    case GcodeError::kExprTooDeep: return "{w}: expression nested deeper than 256 levels (brackets, '#' and signs; more than a line holds)";
    case GcodeError::kFeedZero: return "{w}: feed move with zero feed rate (set F first; G93 and G94 set F to 0)";
    case GcodeError::kInverseTimeNoF: return "{w}: F word missing in inverse time mode (G93 needs F on every feed move)";
    case GcodeError::kArcNoCentre: return "{w}: R, I, J and K words all missing for arc";
    case GcodeError::kArcRadiusMismatch:
      return "{w}: radius to end of arc ({b} mm) differs from radius to start ({a} mm) by more than "
             "LinuxCNC's tolerance";
    case GcodeError::kArcZeroRadius: return "{w}: zero-radius arc (radius {a} mm)";
    case GcodeError::kArcRSameEnds: return "{w}: R-format arc whose end is its start (a full circle needs I/J/K)";
    case GcodeError::kArcRTooSmall:
      return "{w}: arc radius {a} mm is too small to reach the end point (half the distance is {b} mm)";
    case GcodeError::kArcWordWrongPlane: return "{w} word given for an arc in a plane that does not use it";
    case GcodeError::kArcRAndIjk: return "{w}: arc with both R and I/J/K words";
    case GcodeError::kAxisWordsWithG80: return "{w}: cannot use axis values with G80";
    case GcodeError::kAxisWordsUnused: return "{w}: axis value with no motion mode to use it (G80 in effect)";
    case GcodeError::kTwoAxisUsers: return "{w}: two G codes in one block both use the axis values";
    case GcodeError::kG53BadMotion: return "{w}: G53 needs G0 or G1";
    case GcodeError::kCycleNoR: return "{w}: R clearance plane missing in canned cycle";
    case GcodeError::kCycleNoZ: return "{w}: Z (bottom) missing in canned cycle";
    case GcodeError::kCycleRBelowZ: return "{w}: R clearance plane ({a} mm) below the bottom ({b} mm) of the canned cycle";
    case GcodeError::kCycleNoP: return "{w}: dwell time P missing in canned cycle";
    case GcodeError::kCycleNoQ: return "{w}: peck increment Q missing in canned cycle";
    case GcodeError::kCycleQNotPositive: return "{w}: peck increment Q must be positive";
    case GcodeError::kCycleZeroRepeats: return "{w}: cannot do zero repeats of a canned cycle";
    case GcodeError::kCycleInverseTime: return "{w}: cannot use inverse time feed (G93) with canned cycles";
    case GcodeError::kG10NoL: return "{w}: G10 needs an L word";
    case GcodeError::kG10BadL: return "{w}: G10 supports L2 and L20 here (L1, L10, L11 change the tool table)";
    case GcodeError::kG10BadP: return "{w}: G10 L2/L20 needs P0 to P9 (coordinate system)";
    case GcodeError::kG92NoAxis: return "{w}: G92 needs at least one axis word";
    case GcodeError::kDwellNoP: return "{w}: G4 needs a P word (seconds)";
    case GcodeError::kWordUnused: return "{w} word with no G or M code that uses it";
    case GcodeError::kPositionOutOfRange: return "{w}: position beyond the +-10 m range (would be {a} mm)";
    case GcodeError::kTurnsNotPositive: return "{w}: P (number of turns) must be a positive integer";
    case GcodeError::kG43NoTool: return "{w}: G43 without H uses the tool in the spindle, and there is none";
    case GcodeError::kToolUnknown: return "{w}: tool is not in the tool table";
    case GcodeError::kG10PNeeded: return "{w}: G10 L2/L20 needs a P word";
    case GcodeError::kLineNumberTooLarge: return "line number {w} is too large";
    case GcodeError::kG53Incremental: return "{w}: G53 cannot be used in incremental distance mode (G91)";
    case GcodeError::kCycleNoIjk:
      return "{w}: I, J and K words needed (the offset out of the hole's axis, and the top of the back bore)";
    case GcodeError::kCycleSpindleStopped: return "{w}: the spindle is not turning (M3 or M4 first)";
    case GcodeError::kCycleSpindleWrongWay:
      return "{w}: the spindle turns the wrong way (G84 taps with M3 clockwise, G74 with M4)";
    case GcodeError::kCyclePeckCount:
      return "{w}: Q makes {n} pecks down {b} mm, more than the 1000000 a block may make (is Q in the right units?)";
    case GcodeError::kProbeNoAxis: return "{w}: probe move without X, Y or Z";
    case GcodeError::kProbeTooClose: return "{w}: the probe move ends where it starts";
    case GcodeError::kProbeAlreadyTripped: return "{w}: the probe already touches the stock where the move starts";
    case GcodeError::kProbeNotTripped: return "{w}: the probe does not touch the stock where the move starts";
    case GcodeError::kProbeNoContact: return "{w}: the probe move reached its end without tripping (G38.2: touching the stock, G38.4: leaving it)";
    case GcodeError::kPolarWithXY: return "{w} word with polar coordinates (@ and ^ give X and Y)";
    case GcodeError::kPolarPlane: return "{w}: polar coordinates only in the XY plane (G17)";
    case GcodeError::kPolarNotMotion:
      return "{w}: polar coordinates can only be used for motion (not with G10, G28, G30, G43.1 or G92)";
    case GcodeError::kPolarG53: return "{w}: polar coordinates cannot be used with G53";
    case GcodeError::kPolarNoAngle: return "{w}: at the origin a polar position needs an angle (^)";
    case GcodeError::kPolarIncrementalOrigin:
      return "{w}: incremental (G91) polar motion is indeterminate at the origin (it has no angle)";
    case GcodeError::kSplinePlane: return "{w}: splines must be in the XY plane (G17)";
    case GcodeError::kSplineZ: return "{w}: splines may not move Z";
    case GcodeError::kSplineIJ: return "{w}: I and J must come together (G5.1 needs both, G5 both or neither)";
    case GcodeError::kSplinePQ: return "{w}: G5 needs both P and Q";
    case GcodeError::kSplineNoAxis: return "{w}: spline without an end point (X, Y, @ or ^)";
    case GcodeError::kSyncNoPitch: return "{w}: K word missing (the pitch: distance per spindle revolution)";
    case GcodeError::kSyncFeedWord: return "F word used with {w} (its feed is K times the spindle speed)";
    case GcodeError::kSyncNoAxis: return "{w}: no X, Y or Z to move to";
    case GcodeError::kNurbsXY: return "{w}: a NURBS control point needs both X and Y";
    case GcodeError::kNurbsPOnlyFirst: return "{w}: P without X and Y gives only the first control point's weight";
    case GcodeError::kNurbsWeight: return "{w}: every NURBS control point needs a positive weight P";
    case GcodeError::kNurbsNoStart: return "{w} without G5.2 first";
    case GcodeError::kNurbsTooFew: return "{w}: fewer control points than the order L = {n}";
    case GcodeError::kNurbsTooMany:
      return "{w}: NURBS beyond dexmill's limits: 64 control points, order 10, weights within a ratio of 4096, and "
             "no inverse time (G93)";
    case GcodeError::kG10L20Rotation: return "{w} not allowed in G10 L20 (G10 L2 R turns a system)";
    case GcodeError::kContextNone: return "{w}: no modal state saved at this call level (M70 or M73 first)";
    case GcodeError::kTloAddHAndAxes: return "{w}: H and axis words cannot both be given (one offset to add)";
    case GcodeError::kTloAddNothing: return "{w}: neither H nor Z: no offset to add";
    case GcodeError::kFeedPerRevNoSpeed: return "{w}: feed per revolution (G95) with spindle speed 0 (S first)";
    case GcodeError::kSyncPitchNotPositive:
      return "{w}: K (the pitch) must be positive: the move would never reach its end";
    case GcodeError::kUnsupportedOword: return "o-word subroutines and control flow ('{w}') are not supported";
    case GcodeError::kUnsupportedParameter: return "# parameters are not supported";
    case GcodeError::kUnsupportedExpression: return "[ ] expressions are not supported";
    case GcodeError::kUnsupportedAxis: return "{w} axis is not supported (dexmill simulates X, Y and Z)";
    case GcodeError::kCompOnWhenOn: return "{w}: cutter radius compensation is already on (G40 turns it off first)";
    case GcodeError::kCompPlane: return "{w}: cutter radius compensation works only in the XY (G17) and XZ (G18) planes";
    case GcodeError::kCompChangePlane: return "{w}: cannot change planes with cutter radius compensation on";
    case GcodeError::kCompForbidden: return "{w} cannot be used with cutter radius compensation on (G40 turns it off)";
    case GcodeError::kCompNoD: return "{w} needs a D word (the tool diameter)";
    case GcodeError::kCompEntryTooShort:
      return "{w}: the cutter compensation entry move ({a} mm) is not longer than the tool radius ({b} mm)";
    case GcodeError::kCompEntryArcTooShort:
      return "{w}: the cutter compensation entry arc ({a} mm from start to end) is not longer than the tool radius "
             "({b} mm)";
    case GcodeError::kCompArcTooSmall:
      return "{w}: tool radius ({b} mm) not less than the arc radius ({a} mm) with cutter compensation: the tool "
             "does not fit inside the arc";
    case GcodeError::kCompConcaveStraight:
      return "{w}: concave corner too tight for the tool: the straight move before it would have to run backwards "
             "(cutter compensation cannot reach it without gouging)";
    case GcodeError::kCompConcaveArc:
      return "{w}: concave corner too tight for the tool: the arc before it would have to sweep further than "
             "programmed (cutter compensation cannot reach it without gouging)";
    case GcodeError::kCompLineArcGouge:
      return "{w}: concave corner too tight for the tool: this arc cannot be reached from the line before it "
             "without gouging (cutter compensation)";
    case GcodeError::kCompArcSameCentre:
      return "{w}: arc after an arc with the same centre: cutter compensation cannot make the corner";
    case GcodeError::kCompArcArcGouge:
      return "{w}: concave corner too tight for the tool: the compensated tool cannot fit between the two arcs "
             "without gouging";
    case GcodeError::kCompArcLineGouge:
      return "{w}: concave corner too tight for the tool: the compensated tool cannot fit between the arc and this "
             "line without gouging";
    case GcodeError::kCompArcAfterExit:
      return "{w}: the move just after turning cutter compensation off (G40) must be straight, not an arc";
    case GcodeError::kCompQueueFull:
      return "{w}: more than 16 moves and commands held by cutter radius compensation (dexmill's fixed limit; "
             "they wait for the next move in the plane to fix the corner)";
    case GcodeError::kCompInternal: return "{w}: cutter compensation made an arc whose radius changed (a bug)";
    case GcodeError::kUnsupportedGcode: return "{w} is not supported";
    case GcodeError::kUnsupportedMcode: return "{w} is not supported";
    case GcodeError::kUnsupportedCutterComp: return "{w} (cutter radius compensation) is not supported";
    case GcodeError::kUnsupportedRotation: return "{w}: rotated coordinate systems are not supported";
    case GcodeError::kUnsupportedContextComp:
      return "{w}: restoring a saved state with cutter compensation turned the other way (on or off) is not "
             "supported: G40, G41 or G42 first";
    case GcodeError::kUnsupportedCompOrientation:
      return "{w} with L (a lathe tool orientation) is not supported (LinuxCNC takes it only in G18, on a lathe)";
    case GcodeError::kWarnMcodeIgnored: return "{w} ignored (it does not move the tool)";
    case GcodeError::kWarnGrblCommand: return "grbl command '{w}' skipped (the position is assumed unchanged)";
    case GcodeError::kWarnG10ToolTable: return "{w}: tool table change ignored (tool lengths are not applied to the path)";
    case GcodeError::kWarnAfterEnd: return "text after the end of the program (M2/M30 or %) ignored";
    case GcodeError::kWarnNoProgramEnd: return "the program ends without M2 or M30 (or a closing %): was the file cut short?";
    case GcodeError::kWarnNoClosingPercent: return "the file ends without the % that closes its opening %: was it cut short?";
    case GcodeError::kWarnEmptyProgram: return "the program is empty (no G-code in it)";
    case GcodeError::kWarnNoMotion: return "the program makes no move";
    case GcodeError::kWarnDefaultFeed:
      return "{w}: feed move with no F in force: it and any later one take --default-feed ({a} mm/min)";
    case GcodeError::kWarnFastFeed:
      return "{w}: feed above 1000000 mm/min, taken as written (the machine clamps it to its maximum velocity); "
             "the time estimate counts it as 1000000 mm/min";
    case GcodeError::kWarnFastSpindle: return "{w}: spindle speed above 1000000 rpm, taken as written";
    case GcodeError::kWarnProbe:
      return "{w}: without a stock a probe move runs to its end point (dexmill run stops each where it touches the "
             "stock)";
    case GcodeError::kWarnTapPlane:
      return "{w} in G18/G19: LinuxCNC 2.9 taps to a point with the plane's axes swapped (its "
             "convert_cycle_g74_g84); simulated as it moves";
    case GcodeError::kWarnCycleLevelMoved:
      return "{w}: the offsets changed during this canned-cycle series: G98 returns to the initial level "
             "in program coordinates, as LinuxCNC does, now {a} mm in the machine (was {b} mm)";
    case GcodeError::kWarnMcodeMachine:
      return "{w} is no LinuxCNC M code (a machine may define it, by a remap): skipped, what it does is not simulated";
    case GcodeError::kWarnDiameterMode:
      return "{w}: lathe diameter mode: X words are diameters until G8 (LinuxCNC halves them, on a mill too)";
    case GcodeError::kWarnContextRest:
      return "{w}: LinuxCNC 2.9 restores the saved modes as a block of its own in place of this line: the rest of "
             "the line (its motion, modes, coolant, stop) is not run, here either";
    case GcodeError::kWarnG49H:
      return "{w}: H word with G49 ignored (G49 cancels the tool length offset whatever H says; LinuxCNC refuses "
             "the H, a Centroid control takes it)";
    case GcodeError::kWarnM99Main:
      return "M99 in the main program: the machine starts the program again, endlessly; the preview runs it once";
    case GcodeError::kWarnUnitsNotSet:
      return "no G20/G21 before the first move: the program is read in {w}, the default (--units mm or --units "
             "inch says which)";
    case GcodeError::kWarnUnitsLookInch:
      return "the program never sets its units and its numbers look like inches, not mm: its moves span at most "
             "{a} across and its feeds reach {b} a minute; if it is in inches, give --units inch";
    case GcodeError::kWarnFeedBeforeUnits:
      return "{w} on the line that changes the units is read in the units before it, as RS274/NGC orders a line "
             "(F, then G20/G21) and LinuxCNC moves: {a} mm/min (grbl reads the line's units); put G20/G21 on a line "
             "before it";
    case GcodeError::kWarnCompNoTable:
      return "{w}: no tool table (--tools), so the tool radius is 0: the path is not compensated";
    case GcodeError::kWarnManualRetract:
      return "{w}: the operator retracts the tool by hand at the program stop; the next move starts from the "
             "bottom, as in LinuxCNC";
    case GcodeError::kOwordBadLabel:
      return "'{w}': an o-word label is a number (o100, o[#1]) or a <name> of at most 31 characters";
    case GcodeError::kOwordUnknownStatement:
      return "unknown o-word statement '{w}' (sub endsub call return do while endwhile repeat endrepeat if "
             "elseif else endif break continue)";
    case GcodeError::kOwordTextAfter: return "unexpected '{w}' after the o-word statement (only comments may follow)";
    case GcodeError::kOwordNoValue: return "'{w}' needs its value in brackets (as 'while [#1 LT 3]')";
    case GcodeError::kOwordTooManyArgs: return "more than 30 arguments in a call (LinuxCNC's #1..#30)";
    case GcodeError::kOwordUndefinedLabel: return "o{w}: no if, while, do or repeat with this label came before";
    case GcodeError::kOwordLabelKind: return "o{w}: the label belongs to another kind of statement (line {n})";
    case GcodeError::kOwordDuplicateLabel: return "o{w}: the label was already used at line {n}";
    case GcodeError::kOwordNotInSub: return "o{w}: return or endsub outside a subroutine";
    case GcodeError::kOwordNestedSub: return "o{w}: a subroutine defined inside another one's definition";
    case GcodeError::kOwordSubRedefined: return "o{w}: subroutine defined twice (first at line {n})";
    case GcodeError::kOwordSubAgain:
      return "o{w}: the definition of a subroutine is met again (it was called before it was defined, or it "
             "is inside a loop); LinuxCNC stops here too";
    case GcodeError::kOwordCallDepth: return "o{w}: subroutine calls nested more than 9 deep (LinuxCNC's limit)";
    case GcodeError::kOwordSubNotFound:
      return "o{w}: no such subroutine (not defined in the program, nor a file of that name on the subroutine "
             "path)";
    case GcodeError::kOwordTooManyLabels: return "o{w}: more than {n} o-word labels in a program (dexmill's fixed limit)";
    case GcodeError::kOwordUnclosed:
      return "o{w} of line {n} is never closed: the program ends while looking for its end (endif, endwhile, "
             "endrepeat, the closing while of a do, or endsub)";
    case GcodeError::kOwordNoSource:
      return "o{w}: loops and calls re-read the program, and this input cannot be re-read";
    case GcodeError::kOwordSeek: return "o{w}: cannot go back in the program to line {n} (the input cannot be re-read)";
    case GcodeError::kBlockLimit:
      return "the program ran {n} blocks (the --max-blocks limit): does the loop of line {m} never end?";
    case GcodeError::kOwordFanucMix:
      return "o{w}: a Fanuc-style program (a bare O{w} line) is called with M98 and ends with M99; a sub "
             "is called with 'call' and ends with endsub or return";
    case GcodeError::kM98NoP: return "M98 needs a P word: the number of the O program it calls";
  }
  return "unknown error";
}

namespace {

using Out = TextOut;

void put_uint(Out* o, uint64_t v) { o->put_uint(v); }

// nm as mm with 4 decimals, rounded to nearest (ties away from zero).
void put_mm4(Out* o, int64_t nm) {
  int64_t tenth_um = div_round(nm, 100);
  uint64_t a = abs_u64(tenth_um);
  if (tenth_um < 0) o->put('-');
  char digits[24];
  int k = 0;
  uint64_t ip = a / 10000, fp = a % 10000;
  do { digits[k++] = static_cast<char>('0' + ip % 10); ip /= 10; } while (ip);
  while (k) o->put(digits[--k]);
  o->put('.');
  for (uint64_t d = 1000; d; d /= 10) o->put(static_cast<char>('0' + (fp / d) % 10));
}

}  // namespace

size_t gcode_format_message(const GcodeDiag& d, char* buf, size_t n) {
  Out o{buf, n, 0};
  const char* t = gcode_error_template(d.code);
  for (; *t; ++t) {
    if (t[0] == '{' && t[1] && t[2] == '}') {
      if (t[1] == 'w') o.puts(d.word);
      else if (t[1] == 'n') {
        put_uint(&o, abs_u64(d.a_nm));
      } else if (t[1] == 'm') {
        put_uint(&o, abs_u64(d.b_nm));
      } else if (t[1] == 'a') put_mm4(&o, d.a_nm);
      else if (t[1] == 'b') put_mm4(&o, d.b_nm);
      t += 2;
      continue;
    }
    o.put(*t);
  }
  return o.end();
}

}  // namespace dexmill
