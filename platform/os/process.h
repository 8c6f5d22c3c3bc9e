// What a process owes the machine it runs on: standard descriptors that are
// really open, and no debris when it is interrupted.
//
// - A closed standard input, output or error (`dexmill run - <&-`) would be
//   taken by the next file opened (a temporary spool would become "standard
//   input"): they are opened on /dev/null instead, and the caller is told
//   which were closed. Standard output is opened read-only, so that a write
//   to it fails (EBADF, as on the closed descriptor) rather than vanish:
//   an output sent to a closed standard output is lost, an I/O error.
// - Standard output is checked at the end (close_standard_output): a
//   write, flush or close that failed (/dev/full, a closed pipe) is an I/O
//   error, whichever code wrote it.
// - On SIGINT, SIGTERM and SIGHUP the temporary files registered here (an
//   output being written, the spool of standard input) are removed and the
//   signal is raised again with its default action, so the exit status says
//   what stopped the run (130, 143, 129). SIGKILL cannot be caught: an output
//   killed that way leaves its temporary, which the next write of the same
//   output removes (platform/os/output_file.h).
#ifndef DEXMILL_PLATFORM_OS_PROCESS_H
#define DEXMILL_PLATFORM_OS_PROCESS_H

#include <string>

namespace dexmill {

// Opens /dev/null on each of descriptors 0, 1, 2 that is closed; returns a
// bit mask of those that were (bit 0: standard input), which
// standard_input_closed() remembers.
unsigned fix_standard_descriptors();
// The process started with standard input closed: "-" has nothing to read
// (an I/O error, not an empty program).
bool standard_input_closed();
// Standard input is a terminal (a person at it, not a file or a pipe):
// what `dexmill run` with no FILE runs the built-in demo for.
bool standard_input_is_terminal();
// The process started with standard output closed: what goes to "-" is
// lost.
bool standard_output_closed();
// False with "standard output is closed" when it is; what a command that
// will write to standard output checks before its work.
bool standard_output_usable(std::string* err);
// Flushes and closes standard output; false with the message ("cannot
// write standard output: No space left on device", "... it is closed")
// when anything written to it was lost.
bool close_standard_output(std::string* err);

// Installs the SIGINT, SIGTERM and SIGHUP handlers, and ignores SIGXFSZ
// (a write past `ulimit -f` fails with EFBIG instead of killing).
void install_cleanup_handlers();

// Registers a file to remove if a signal stops the process; returns its
// slot, or -1 when all kCleanupSlots are taken (the file is then left, as
// without the handler). cleanup_unregister(-1) does nothing.
// SIGINT, SIGTERM and SIGHUP held off for a scope, then acted on: what
// creates a temporary and registers it (or renames one and unregisters
// it) runs under one, so that no signal falls between the two and leaves
// a file the clean-up does not know of.
class StopSignalsHeld {
 public:
  StopSignalsHeld();
  ~StopSignalsHeld();
  StopSignalsHeld(const StopSignalsHeld&) = delete;
  StopSignalsHeld& operator=(const StopSignalsHeld&) = delete;

 private:
  unsigned char was_[128];  // the caller's signal mask (a sigset_t)
};

constexpr int kCleanupSlots = 32;
int cleanup_register(const char* path);
void cleanup_unregister(int slot);
// Removes every registered file now (what the signal handler does; async-
// signal-safe): for a process about to end without unwinding, such as on
// running out of memory (tools/cli/main.cpp).
void cleanup_remove_all();

}  // namespace dexmill

#endif
