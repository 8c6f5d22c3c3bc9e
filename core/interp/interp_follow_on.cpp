// Telling a root error from its follow-ons (`dexmill check` once
// gave 942 errors for one cause in a real file).
//
// LinuxCNC stops at the first error, so it has no rule for what comes after;
// `dexmill check` goes on, skipping each bad block. A skipped block leaves
// the modal state as it was, which is not what the program meant from there
// on: the next G1 fails for want of the F the bad line set, the next lines'
// X and Y "have no motion mode", the next arc starts from the wrong point.
// And a state the program never set right (no F at all) fails every block
// that uses it. Those errors are consequences, not news.
//
// The rule. The state is cut into facets (the position on each axis, the
// motion mode with the canned cycles' sticky values, the feed, the plane,
// units, distance modes, offsets, the tool, and whether the program ended).
// A facet becomes suspect when
//   - a block that would have set it fails (read leniently, so a line that
//     does not even read still marks what it names: `G1 Z#1 F#2` marks the
//     motion mode, Z and the feed; an o-word line, or an over-long line,
//     marks everything), or
//   - an error blames it: after "zero feed rate" the feed is known to be
//     wrong, after "axis value with no motion mode" the motion mode is;
// and trusted again when a block that sets it runs (an axis: when a block
// moves it to an absolute position while units, distance mode and offsets
// are trusted). An error is a follow-on when the check that raised it read
// a suspect facet: one the block did not set itself, or one it read before
// its own words applied (an arc's start point, a cycle's sticky values).
// The interpreter marks it (GcodeDiag::follow_on) and `dexmill check` counts
// it instead of printing it. Errors of a line's own words (reading errors,
// unsupported codes, a G10 without L) read no facet and are always reported,
// and the first error of a program never is a follow-on.
//
// Facets are coarse on purpose: one flag for all offsets, set again by any
// block that sets one of them. A wrong guess shows a consequence as an
// error (as before this rule), or hides an error behind an earlier one on
// the state it read; fixing the first error brings the second back.
#include "core/gcode/lex.h"
#include "core/interp/block_runner.h"

namespace dexmill {
namespace interp_detail {

namespace {

constexpr uint16_t kFacetGcode = kFacetPosition | kFacetMotion | kFacetFeed | kFacetPlane | kFacetUnits |
                                 kFacetDistance | kFacetArcDistance | kFacetOffsets;

uint16_t axis_facet(int axis) { return static_cast<uint16_t>(kFacetX << axis); }

// What a G code sets, by its group (and for group 0, by itself).
uint16_t g_facets(int64_t tenths) {
  switch (gcode_g_group(tenths)) {
    case kGMotion: return kFacetMotion;
    case kGPlane: return kFacetPlane;
    case kGDistance: return kFacetDistance;
    case kGArcDistance: return kFacetArcDistance;
    case kGFeedMode: return kFacetFeed;
    case kGUnits: return kFacetUnits;
    case kGToolLength: return kFacetOffsets | kFacetZ;  // the tip moves with the offset
    case kGRetract: return kFacetMotion;                // the cycles' clearance level
    case kGCoordSystem: return kFacetOffsets;
    case kGNonModal:
      if (tenths == 280 || tenths == 300) return kFacetPosition;
      if (tenths == 40 || tenths == 530) return 0;
      return kFacetOffsets;  // G10, G28.1, G30.1, G92 and its kin
    case -1: return kFacetGcode;  // not a G code at all: who knows
    case kGCutterComp: return kFacetComp;
    default: return 0;           // path control, spindle mode
  }
}

Plane plane_after(const GcodeBlock& b, const InterpState& s) {
  const int g = b.g[kGPlane];
  if (g < 0) return s.plane;
  return g == 170 ? Plane::kXY : g == 180 ? Plane::kZX : Plane::kYZ;
}

}  // namespace

uint16_t facets_written(const char* text, size_t len) {
  uint16_t f = 0;
  GcodeLooseScanner sc(text, len);
  GcodeLooseWord w;
  while (sc.next(&w)) {
    int64_t tenths = -1;
    if (w.known && !decimal_to_tenths(w.value, &tenths)) tenths = -1;
    switch (w.letter) {
      case 'O':
        // An o-word (a call, a loop, a subroutine's start) may do anything;
        // an O after other words is a typo and names nothing.
        if (w.first) return kFacetAll;
        break;
      case 'G': f |= tenths < 0 ? kFacetGcode : g_facets(tenths); break;
      case 'M':
        if (tenths < 0 || tenths == 20 || tenths == 300) f |= kFacetEnd;
        if (tenths < 0 || tenths == 60 || tenths == 610) f |= kFacetTool;
        break;
      case '@': case '^': f |= kFacetX | kFacetY; break;
      case 'X': f |= kFacetX; break;
      case 'Y': f |= kFacetY; break;
      case 'Z': f |= kFacetZ; break;
      case 'F': f |= kFacetFeed; break;
      case 'T': f |= kFacetTool; break;
      case 'H': f |= kFacetOffsets; break;
      case 'R': case 'P': case 'Q': case 'L': case 'I': case 'J': case 'K':
        f |= kFacetMotion;  // sticky cycle values (G87 keeps I, J, K)
        break;
      default: break;
    }
  }
  return f;
}

uint16_t facets_set(const GcodeBlock& b, const InterpState& s, uint16_t suspect) {
  uint16_t f = 0;
  const int g0 = b.g[kGNonModal];
  const Plane pl = plane_after(b, s);
  const char plane_letter = kAxisLetter[plane_axis_c(pl)];
  const int gm = b.g[kGMotion];
  if (gm >= 0) {
    // A cycle's sticky values are fresh only when the block gives them.
    // G5 and G5.1 leave the modal motion as it was (interp_spline.cpp).
    const bool fresh = gm == 50 || gm == 51 ? false : !is_cycle(gm) || (b.has_word('R') && b.has_word(plane_letter) &&
                                         ((gm != 730 && gm != 830) || b.has_word('Q')) &&
                                         ((gm != 820 && gm != 860 && gm != 880 && gm != 890) || b.has_word('P')) &&
                                         (gm != 870 || (b.has_word('I') && b.has_word('J') && b.has_word('K'))));
    if (fresh) f |= kFacetMotion;
  }
  if (b.g[kGFeedMode] >= 0 || b.has_word('F')) f |= kFacetFeed;
  if (b.g[kGPlane] >= 0) f |= kFacetPlane;
  if (b.g[kGUnits] >= 0) f |= kFacetUnits;
  if (b.g[kGDistance] >= 0) f |= kFacetDistance;
  if (b.g[kGArcDistance] >= 0) f |= kFacetArcDistance;
  if (b.g[kGCutterComp] >= 0) f |= kFacetComp;
  if (b.has_word('T') || b.m[kMToolChange] == 610) f |= kFacetTool;
  // Offsets: a coordinate system, a tool length offset, or G10/G92 (whose
  // values come from the current point when it is trusted).
  int64_t l = 0;
  const bool l20 = b.has_word('L') && decimal_to_int(b.val('L'), &l) && l == 20;
  const bool from_point = g0 == 920 || (g0 == 100 && l20);
  if (b.g[kGCoordSystem] >= 0 || (b.g[kGToolLength] >= 0 && b.g[kGToolLength] != 430) ||
      (b.g[kGToolLength] == 430 && (b.has_word('H') || !(suspect & kFacetTool))) || g0 == 921 || g0 == 922 ||
      g0 == 923 || (g0 == 100 && !from_point) || (from_point && !(suspect & kFacetPosition)))
    f |= kFacetOffsets;
  // Axes moved to an absolute position.
  const bool incremental = b.g[kGDistance] >= 0 ? b.g[kGDistance] == 910 : s.incremental;
  const bool axis_user0 = g0 == 100 || g0 == 920 || b.g[kGToolLength] == 431 || b.g[kGToolLength] == 432;
  const int motion = gm >= 0 ? gm : (b.has_axis() && !axis_user0 && g0 != 280 && g0 != 300) ? s.motion : -1;
  for (int ax = 0; ax < 3; ++ax) {
    const bool word = b.has_word(kAxisLetter[ax]);
    bool set = false;
    if (g0 == 280 || g0 == 300) set = word || !b.has_axis();  // to the stored home
    else if (g0 == 530) set = word;                            // machine coordinates
    else if (motion == 0 || motion == 10 || motion == 20 || motion == 30 || motion == 50 || motion == 51)
      set = word && !incremental;
    else if (is_cycle(motion)) set = word && !incremental && kAxisLetter[ax] != plane_letter;
    if (set) f |= axis_facet(ax);
  }
  return f;
}

uint16_t suspect_after(uint16_t suspect, uint16_t set) {
  suspect &= static_cast<uint16_t>(~(set & ~kFacetPosition));
  // An absolute position means what the program meant only in its units,
  // distance mode and frame.
  if (!(suspect & (kFacetUnits | kFacetDistance | kFacetOffsets)))
    suspect &= static_cast<uint16_t>(~(set & kFacetPosition));
  return suspect;
}

ErrorFacets error_facets(GcodeError e, const GcodeBlock& b) {
  constexpr uint16_t kWhere = kFacetPosition | kFacetUnits | kFacetDistance | kFacetOffsets;
  switch (e) {
    case GcodeError::kFeedZero:
    case GcodeError::kFeedPerRevNoSpeed:
    case GcodeError::kInverseTimeNoF:
    case GcodeError::kCycleInverseTime:
      return {kFacetFeed, 0, kFacetFeed};
    case GcodeError::kArcNoCentre:
      // A modal arc on a line meant for another move blames the motion mode.
      return {kFacetMotion | kFacetPlane, 0, static_cast<uint16_t>(b.g[kGMotion] < 0 ? kFacetMotion : 0)};
    case GcodeError::kArcWordWrongPlane:
      return {kFacetMotion | kFacetPlane, 0, 0};
    case GcodeError::kAxisWordsUnused:
    case GcodeError::kG53BadMotion:
      return {kFacetMotion, 0, kFacetMotion};
    case GcodeError::kArcRAndIjk:
      return {kFacetMotion, 0, 0};
    case GcodeError::kWordUnused:
      // Whether R, P, Q, L are used depends on the modal motion of a move.
      return {static_cast<uint16_t>(b.has_axis() ? kFacetMotion : 0), 0, 0};
    case GcodeError::kArcRadiusMismatch:
    case GcodeError::kArcZeroRadius:
    case GcodeError::kArcRSameEnds:
    case GcodeError::kArcRTooSmall:
      // The arc's start is the position before the block, whatever it sets.
      return {kWhere | kFacetArcDistance | kFacetPlane | kFacetMotion, kFacetPosition, 0};
    case GcodeError::kCycleRBelowZ:
    case GcodeError::kCyclePeckCount:
      // So is the initial level an incremental R counts from.
      return {kWhere | kFacetPlane | kFacetMotion, kFacetPosition, 0};
    case GcodeError::kPositionOutOfRange:
      return {kWhere, 0, 0};
    case GcodeError::kProbeTooClose:
    case GcodeError::kPolarNoAngle:
    case GcodeError::kPolarIncrementalOrigin:
      return {kWhere, kFacetPosition, 0};
    case GcodeError::kPolarPlane:
      return {0, kFacetPlane, 0};  // LinuxCNC asks the plane before the block's G17-G19
    case GcodeError::kSplinePlane:
      return {kFacetPlane, 0, 0};
    case GcodeError::kCycleNoR:
    case GcodeError::kCycleNoZ:
    case GcodeError::kCycleNoQ:
    case GcodeError::kCycleNoP:
    case GcodeError::kCycleQNotPositive:
    case GcodeError::kCycleNoIjk:
      // Whether the sticky values were there: the motion before the block.
      return {kFacetPlane, kFacetMotion, 0};
    case GcodeError::kCompForbidden:
    case GcodeError::kCompChangePlane:
      // Compensation left on by mistake (or a G40 line that failed).
      return {kFacetComp, 0, kFacetComp};
    case GcodeError::kCompOnWhenOn:
      return {kFacetComp, 0, 0};
    case GcodeError::kCompEntryTooShort:
    case GcodeError::kCompEntryArcTooShort:
    case GcodeError::kCompArcTooSmall:
    case GcodeError::kCompConcaveStraight:
    case GcodeError::kCompConcaveArc:
    case GcodeError::kCompLineArcGouge:
    case GcodeError::kCompArcSameCentre:
    case GcodeError::kCompArcArcGouge:
    case GcodeError::kCompArcLineGouge:
    case GcodeError::kCompArcAfterExit:
    case GcodeError::kCompQueueFull:
    case GcodeError::kCompInternal:
      // The corner is made with the moves before the block (and the tool).
      return {kWhere | kFacetComp | kFacetPlane | kFacetMotion | kFacetTool, kFacetPosition, 0};
    case GcodeError::kG43NoTool:
      return {kFacetTool, 0, kFacetTool};
    case GcodeError::kToolUnknown: {
      // G43 without H: the tool in the spindle; with H, the block's own word.
      const uint16_t f = b.has_word('H') ? 0 : kFacetTool;
      return {f, 0, f};
    }
    default:
      return {0, 0, 0};
  }
}

}  // namespace interp_detail
}  // namespace dexmill
