// The number of an F word `dexmill optimize` writes: a feed in nm/min as
// the program's units read it (mm/min, or inch/min under G20), chosen so
// that the reader (core/math/decimal.h, decimal_to_nm) takes it back to at
// most the feed asked for, never above: a lowered feed must not come back
// over the material's limit by rounding.
#ifndef DEXMILL_TOOLS_CAM_FEED_WORD_H
#define DEXMILL_TOOLS_CAM_FEED_WORD_H

#include <cstdint>
#include <string>

#include "core/math/decimal.h"

namespace dexmill {
namespace cli {

// A decimal as G-code text: "1200", "47.244", "-0.5" (no trailing zeros,
// no exponent).
std::string decimal_text(Decimal d);

struct FeedNumber {
  std::string text;        // "1200", "47.244": no sign, no trailing zeros
  int64_t nm_per_min = 0;  // what the reader makes of it: <= the feed asked for
};

// The feed `nm_per_min` (>= 0) with the fewest decimals that reads back
// exactly, else the largest value with `max_decimals` (0..6) that reads
// back below it. A lowered feed is written with 3 decimals in mm and 4 in
// inch at most (a controller's usual resolution; 0.0001 in/min is 2.5 um/min
// under a limit), a restored one with 6 so that it comes back exact.
FeedNumber feed_number(int64_t nm_per_min, bool inch, int max_decimals);

}  // namespace cli
}  // namespace dexmill

#endif
