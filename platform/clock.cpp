#include "platform/clock.h"

#include <chrono>
#include <thread>

namespace dexmill {

double clock_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void clock_sleep_s(double s) {
  if (s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(s));
}

}  // namespace dexmill
