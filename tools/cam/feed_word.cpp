#include "tools/cam/feed_word.h"


namespace dexmill {
namespace cli {

std::string decimal_text(Decimal d) {
  while (d.frac > 0 && d.mant % 10 == 0) {
    d.mant /= 10;
    --d.frac;
  }
  if (d.mant < 0) return "-" + decimal_text(Decimal{-d.mant, d.frac});
  const int64_t unit = pow10_i64(d.frac);
  std::string t = std::to_string(d.mant / unit);
  if (d.frac > 0) {
    const std::string frac = std::to_string(d.mant % unit);
    t += "." + std::string(d.frac - frac.size(), '0') + frac;
  }
  return t;
}

FeedNumber feed_number(int64_t nm_per_min, bool inch, int max_decimals) {
  const int64_t nm_per_unit = inch ? 25400000 : 1000000;
  Decimal d{0, 0};
  for (int frac = 0; frac <= max_decimals; ++frac) {
    // floor(feed x 10^frac / unit): its exact value is at most the feed, so
    // the reader's round-to-nearest gives at most the feed too (an integer).
    const unsigned __int128 scaled = static_cast<unsigned __int128>(nm_per_min) * static_cast<uint64_t>(pow10_i64(frac));
    d = Decimal{static_cast<int64_t>(scaled / static_cast<uint64_t>(nm_per_unit)), static_cast<uint8_t>(frac)};
    if (decimal_to_nm(d, inch) == nm_per_min) break;
  }
  FeedNumber out;
  out.nm_per_min = decimal_to_nm(d, inch);
  out.text = decimal_text(d);
  return out;
}

}  // namespace cli
}  // namespace dexmill
