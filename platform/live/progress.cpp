#include "platform/live/progress.h"

#include <unistd.h>

#include "platform/os/clock.h"

namespace dexmill {

int progress_format(char* buf, int n, uint64_t done, int64_t total, uint64_t moves, double elapsed_s) {
  constexpr int kBar = 24;
  char bar[kBar + 1];
  int pct = -1;
  if (total > 0) {
    pct = static_cast<int>(done * 100 / static_cast<uint64_t>(total));
    if (pct > 100) pct = 100;
  }
  const int fill = pct < 0 ? 0 : pct * kBar / 100;
  for (int k = 0; k < kBar; ++k) bar[k] = k < fill ? '#' : '-';
  bar[kBar] = 0;
  const double rate = elapsed_s > 0 ? static_cast<double>(moves) / elapsed_s : 0;
  char pcts[16] = "  ?%";
  if (pct >= 0) std::snprintf(pcts, sizeof pcts, "%3d%%", pct);
  const char* unit = rate >= 1e6 ? "M" : (rate >= 1e3 ? "k" : "");
  const double shown = rate >= 1e6 ? rate / 1e6 : (rate >= 1e3 ? rate / 1e3 : rate);
  return std::snprintf(buf, static_cast<std::size_t>(n), "dexmill: [%s] %s  %llu moves  %.1f%s moves/s  %.1f s", bar,
                       pcts, static_cast<unsigned long long>(moves), shown, unit, elapsed_s);
}

Progress::Progress(std::FILE* out, bool enabled)
    : out_(out), enabled_(enabled && out && isatty(fileno(out))), start_s_(clock_now_s()) {}

void Progress::update(uint64_t done, int64_t total, uint64_t moves) {
  if (!enabled_) return;
  // Reading the clock is cheap but not free: look every 64 calls.
  if ((++calls_ & 63) != 0) return;
  const double now = clock_now_s();
  if (now - start_s_ < 0.5 || now - last_s_ < 0.1) return;
  last_s_ = now;
  char line[160];
  progress_format(line, sizeof line, done, total, moves, now - start_s_);
  std::fprintf(out_, "\r%s\x1b[K", line);
  std::fflush(out_);
  drawn_ = true;
}

void Progress::finish() {
  if (!drawn_) return;
  std::fprintf(out_, "\r\x1b[K");
  std::fflush(out_);
  drawn_ = false;
}

}  // namespace dexmill
