// Whether a program that never says G20/G21 reads like inches: the
// evidence the interpreter gathers from the moves it makes before the
// program sets its units, and the rule that judges it. Numbers are in nm as
// read, so 1 "unit" is 1 mm when the default is mm: the rule asks whether
// the numbers as written are too small for millimetres.
//
// The rule, chosen on the real programs of the project's corpus (17 inch
// programs with their G20 taken out, all flagged; 34 mm programs with their
// G21 taken out, none flagged; the figures are in units_guess.cpp):
//   the program made feed moves at a feed it wrote (not --default-feed),
//   every move lies within 20 units across in X and in Y,
//   no feed is 2000 units/min or more (2000 in/min is beyond any mill's
//   cutting feed; mm programs for small routers go that fast), and
//   either no move goes above Z 2.5 (an inch program clears the stock by
//   0.1 to 1.6; a mm one by 2 to 100, and one under 20 mm across by 4 or
//   more) or no feed is 50 units/min or more (50 mm/min is a crawl).
#ifndef DEXMILL_CORE_INTERP_UNITS_GUESS_H
#define DEXMILL_CORE_INTERP_UNITS_GUESS_H

#include <stdint.h>

#include "core/canon/canon.h"

namespace dexmill {

constexpr int64_t kInchLookExtentNm = 20000000;            // 20 units across
constexpr int64_t kInchLookTopNm = 2500000;                // Z 2.5
constexpr int64_t kInchLookSlowFeedNmPerMin = 50000000;    // 50 units/min
constexpr int64_t kInchLookFastFeedNmPerMin = 2000000000;  // 2000 units/min

struct UnitsEvidence {
  bool moved = false;  // a move was made (the box and top below are valid)
  int64_t x_lo_nm = 0, x_hi_nm = 0, y_lo_nm = 0, y_hi_nm = 0;
  int64_t top_nm = 0;              // the highest Z of any move's ends
  bool fed = false;                // a feed move at a feed the program wrote
  int64_t feed_max_nm_per_min = 0;  // the fastest such
  // The wider of the X and Y spans, nm (0 before any move).
  int64_t extent_nm() const;
};

// Adds a record (moves only count); `programmed_feed`: its feed is one
// the program wrote (not a controller's default).
void units_evidence_add(UnitsEvidence* e, const CanonRecord& r, bool programmed_feed);

// The rule above.
bool units_look_like_inch(const UnitsEvidence& e);

// What a reader can say of a program's units.
enum class UnitsVerdict : uint8_t {
  kSet = 0,       // the program set them before its first move (or made none)
  kGiven = 1,     // it did not, and the caller chose them (InterpOptions::units_given)
  kDefault = 2,   // it did not: read in the default
  kLookInch = 3,  // it never did, the default is mm, and its numbers look like inches
};

}  // namespace dexmill

#endif
