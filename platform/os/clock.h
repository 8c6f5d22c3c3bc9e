// Wall-clock time for progress and stage timings (never for results: those
// must not depend on time).
#ifndef DEXMILL_PLATFORM_OS_CLOCK_H
#define DEXMILL_PLATFORM_OS_CLOCK_H

#include <string>

namespace dexmill {

// Monotonic seconds from an arbitrary origin.
double clock_now_s();
// The time of day in UTC, ISO 8601 to the millisecond
// ("2025-06-01T12:34:56.789Z"): what names a run in its report.
std::string clock_utc_text();
// Sleeps for `s` seconds (nothing for s <= 0).
void clock_sleep_s(double s);

}  // namespace dexmill

#endif
