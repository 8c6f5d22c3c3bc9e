#include "platform/os/process.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace dexmill {

namespace {

// Paths the handler removes; a slot's path is complete before its flag is
// set, and the handler reads nothing else (async-signal-safe: unlink only).
constexpr int kPathBytes = 4096;
char g_paths[kCleanupSlots][kPathBytes];
volatile sig_atomic_t g_used[kCleanupSlots];
unsigned g_closed_at_start = 0;

extern "C" void on_stop_signal(int sig) {
  cleanup_remove_all();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

unsigned fix_standard_descriptors() {
  unsigned closed = 0;
  for (int fd = 0; fd <= 2; ++fd) {
    if (fcntl(fd, F_GETFD) != -1) continue;
    closed |= 1u << fd;
    // open() returns the lowest free descriptor: this one. Standard output
    // read-only: writes to it fail (platform/os/process.h).
    const int got = open("/dev/null", fd == 2 ? O_WRONLY : O_RDONLY);
    if (got != fd && got >= 0) close(got);
  }
  g_closed_at_start |= closed;
  return closed;
}

bool standard_input_closed() { return (g_closed_at_start & 1u) != 0; }
bool standard_input_is_terminal() { return !standard_input_closed() && isatty(0) == 1; }
bool standard_output_closed() { return (g_closed_at_start & 2u) != 0; }

bool standard_output_usable(std::string* err) {
  if (!standard_output_closed()) return true;
  *err = "standard output is closed";
  return false;
}

bool close_standard_output(std::string* err) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0 && !std::ferror(stdout);
  const int flush_errno = errno;
  const bool closed = std::fclose(stdout) == 0;
  const int close_errno = errno;
  if (flushed && closed) return true;
  if (standard_output_closed()) {
    *err = "cannot write standard output: it is closed";
  } else {
    // An error met by an earlier write keeps no errno: then the flush's or
    // the close's is the cause, or none is known.
    const int e = !flushed ? flush_errno : close_errno;
    *err = std::string("cannot write standard output") + (e ? std::string(": ") + std::strerror(e) : std::string());
  }
  return false;
}

void install_cleanup_handlers() {
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
  // A file grown past `ulimit -f` then fails to write with EFBIG, which is
  // reported (and its temporary removed), instead of SIGXFSZ killing the
  // process and leaving the temporary.
  std::signal(SIGXFSZ, SIG_IGN);
}

StopSignalsHeld::StopSignalsHeld() {
  static_assert(sizeof(sigset_t) <= sizeof(was_), "sigset_t fits");
  sigset_t stops;
  sigemptyset(&stops);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stops, sig);
  sigprocmask(SIG_BLOCK, &stops, reinterpret_cast<sigset_t*>(was_));
}

StopSignalsHeld::~StopSignalsHeld() { sigprocmask(SIG_SETMASK, reinterpret_cast<sigset_t*>(was_), nullptr); }

int cleanup_register(const char* path) {
  if (std::strlen(path) >= static_cast<size_t>(kPathBytes)) return -1;
  for (int k = 0; k < kCleanupSlots; ++k) {
    if (g_used[k]) continue;
    std::memcpy(g_paths[k], path, std::strlen(path) + 1);
    g_used[k] = 1;
    return k;
  }
  return -1;
}

void cleanup_unregister(int slot) {
  if (slot >= 0 && slot < kCleanupSlots) g_used[slot] = 0;
}

void cleanup_remove_all() {
  for (int k = 0; k < kCleanupSlots; ++k)
    if (g_used[k]) unlink(g_paths[k]);
}

}  // namespace dexmill
