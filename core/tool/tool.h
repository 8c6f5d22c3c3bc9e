// Cutter shapes and their profiles (paper §2.2.2, and past it: flat end,
// bull nose, V-bit besides the paper's ball end).
//
// Every tool is a solid of revolution about the spindle axis: a cutting part
// whose lower surface is the profile height(r) above the tip, for radial
// distance r in [0, R], then a shaft of the same diameter up to length_nm
// above the tip. The profile is what the exact sweeps use; the cutter dexel
// set (core/tool/cutter.h) samples it along vertical rays.
#ifndef DEXMILL_CORE_TOOL_TOOL_H
#define DEXMILL_CORE_TOOL_TOOL_H

#include <stdint.h>

#include "core/point.h"
#include "core/status.h"

namespace dexmill {

enum class ToolKind : uint8_t {
  kFlat = 0,      // flat end mill: height(r) = 0
  kBall = 1,      // ball end: height(r) = R - sqrt(R^2 - r^2)
  kBullNose = 2,  // corner radius rc: flat to R - rc, then a torus
  kVBit = 3,      // cone with included tip angle a: height(r) = r / tan(a/2)
};

// One piece of a tool holder: a cylinder (equal diameters) or a
// cone, stacked above the stick-out. Only its lower surface can meet the
// stock from below, so a cone narrowing upwards acts as its bottom disc.
struct HolderSegment {
  int64_t bottom_diameter_nm = 0;
  int64_t top_diameter_nm = 0;
  int64_t height_nm = 0;
};
constexpr int kHolderSegmentsMax = 4;

struct Tool {
  ToolKind kind = ToolKind::kFlat;
  int64_t diameter_nm = 0;        // cutting diameter, 2R
  int64_t corner_radius_nm = 0;   // kBullNose only: 0 < rc <= R
  int32_t tip_angle_mdeg = 0;     // kVBit only: included angle, kVBitAngleMinMdeg..kVBitAngleMaxMdeg
  int64_t flute_length_nm = 0;    // cutting length above the tip (0: as long as the tool)
  int64_t length_nm = 0;          // stick-out: tip to the top of the shaft (the holder's face)
  // What the safety checks need (core/safety/body.h); the cut ignores them.
  int64_t stick_out_nm = 0;       // stick-out as given (0: the default rule, core/tool/spec.h)
  int64_t shank_diameter_nm = 0;  // above the flutes (0: the cutting diameter)
  bool centre_cutting = true;     // false: must not plunge straight down into material
  int32_t flutes = 0;             // cutting edges, 1..kToolFlutesMax, for the chip per tooth (0: not given; 2 assumed)
  int32_t holder_segments = 0;
  HolderSegment holder[kHolderSegmentsMax] = {};
};

// The tools' ranges, which every stage after this one proves its
// arithmetic against (core/cut/sweep.h, core/tool/cutter.h):
//   diameter D:        kToolDiameterMinNm (1 um) .. kToolDiameterMaxNm (1 m)
//   corner radius rc:  1 nm .. D / 2 (bull nose)
//   tip angle:         1 .. 179.999 degrees (V-bit): its slope cot(a/2) is
//                      at most cot(0.5 deg) = 114.6 < 2^7, what the sweep's
//                      products assume; finer cones are no real bits
//   length (stick-out) and flute length: the profile's full height (R for a
//                      ball, rc, R cot(a/2)) .. kToolLengthMaxNm (10 m), so a
//                      1-degree V-bit is at most 174.5 mm across
//   shank and holder diameters <= 1 m, holder heights > 0 and <= 10 m
//   together, at most kHolderSegmentsMax segments.
// The cutting modes narrow the diameter further: the sweep to radii of
// 2^28 nm (core/cut/sweep.h), the stamp to 4095 dexels across
// (core/tool/cutter.h).
constexpr int64_t kToolDiameterMinNm = 1000;
constexpr int64_t kToolDiameterMaxNm = 1000000000;
constexpr int64_t kToolLengthMaxNm = 10000000000;
constexpr int32_t kToolFlutesMax = 64;
constexpr int32_t kToolFlutesAssumed = 2;  // what a tool that does not say is taken to have (said by the front end)
constexpr int32_t kVBitAngleMinMdeg = 1000;
constexpr int32_t kVBitAngleMaxMdeg = 179999;
Status tool_check(const Tool& t);

// Precomputed profile of a checked tool: height above the tip of the tool's
// lower surface at radial distance r, in nm, rounded to nearest. Error bound
// against the exact profile: 0.5 nm (flat, ball: exact integer root of
// R^2 - r^2), 1 nm (bull nose: r carried with 16 fraction bits), and
// 0.5 nm + 1e-8 * h (V-bit: q30 cotangent).
struct ToolProfile {
  ToolKind kind;
  int64_t radius_nm;       // R
  int64_t corner_nm;       // bull nose corner radius rc
  int32_t cone_cos_q30;    // V-bit: cos(a/2) and sin(a/2)
  int32_t cone_sin_q30;
  int64_t length_nm;       // top of the shaft above the tip
};

ToolProfile tool_profile(const Tool& t);

// height(r) in nm for 0 <= r <= R; for r > R the tool has no lower surface
// there and the result is the tool length (the shaft top).
int64_t profile_height_nm(const ToolProfile& p, int64_t r_nm);
// The same from r^2 (nm^2), exact input: what ray casts at irrational r use,
// since near r = R the profile is steep and rounding r first would cost up to
// sqrt(R) nm.
int64_t profile_height_r2_nm(const ToolProfile& p, uint64_t r2_nm2);

// True when the tool standing with its tip at `tip` cuts the column at
// (x_nm, y_nm) down to z_nm or lower, within lsb_nm: what the Mill cut
// there when it cut that tool position (a deferred end cap is charged to
// the move that brought the tool there: core/assess/gouge_watch.h,
// core/safety/safety.h).
bool profile_explains_cut(const ToolProfile& p, const PointNm& tip, int64_t x_nm, int64_t y_nm, int64_t z_nm,
                          int64_t lsb_nm);

// Height of the profile at r = R (the top of the cutting shape's curve):
// R for a ball, rc for a bull nose, R / tan(a/2) for a V-bit, 0 for flat.
int64_t profile_full_height_nm(const ToolProfile& p);

}  // namespace dexmill

#endif
