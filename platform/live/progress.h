// A one-line progress bar on a terminal:
//   dexmill: [#########-----------]  45%  12345 moves  8.1k moves/s  1.5 s
// redrawn in place at most ten times a second, erased by finish(). It stays
// silent when disabled (-q) or when the stream is not a terminal, and only
// appears once a run has taken half a second, so short runs print nothing.
#ifndef DEXMILL_PLATFORM_LIVE_PROGRESS_H
#define DEXMILL_PLATFORM_LIVE_PROGRESS_H

#include <cstdint>
#include <cstdio>

namespace dexmill {

class Progress {
 public:
  // enabled: the caller's wish (false for -q); the bar also needs `out` to
  // be a terminal.
  Progress(std::FILE* out, bool enabled);
  ~Progress() { finish(); }

  // done/total: bytes of the file (total < 0: unknown, no percentage).
  void update(uint64_t done, int64_t total, uint64_t moves);
  // Erases the bar (if it was drawn).
  void finish();
  bool active() const { return enabled_; }

 private:
  std::FILE* out_;
  bool enabled_;
  bool drawn_ = false;
  double start_s_, last_s_ = 0;
  uint32_t calls_ = 0;
};

// The bar's text for given figures (what update() prints after '\r'),
// without the terminal: exposed for tests.
int progress_format(char* buf, int n, uint64_t done, int64_t total, uint64_t moves, double elapsed_s);

}  // namespace dexmill

#endif
