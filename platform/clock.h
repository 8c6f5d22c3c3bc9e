// Wall-clock time for progress and stage timings (never for results: those
// must not depend on time).
#ifndef DEXMILL_PLATFORM_CLOCK_H
#define DEXMILL_PLATFORM_CLOCK_H

namespace dexmill {

// Monotonic seconds from an arbitrary origin.
double clock_now_s();
// Sleeps for `s` seconds (nothing for s <= 0).
void clock_sleep_s(double s);

}  // namespace dexmill

#endif
