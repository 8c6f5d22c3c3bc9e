// Feeds an interpreter from a LineInput (core/gcode/line_reader.h) one line
// per step(): the input is the interpreter's source (Interp::set_source),
// so loops and calls read it again. What turns the reader's answers into
// the program's diagnostics (an input that is not text is one error, an
// over-long line is one, what is left unclosed at the end is reported at
// its line), once for every front end: `dexmill path`, `check`, the
// simulation (core/sim/simulation.h) and the embedding API.
#ifndef DEXMILL_CORE_SIM_GCODE_RUNNER_H
#define DEXMILL_CORE_SIM_GCODE_RUNNER_H

#include <stdint.h>

#include "core/gcode/line_reader.h"
#include "core/gcode/messages.h"
#include "core/interp/interp.h"

namespace dexmill {

class GcodeRunner {
 public:
  GcodeRunner(LineInput* input, Interp* interp, GcodeMessages* messages, bool stop_at_first_error)
      : input_(input), interp_(interp), messages_(messages), stop_at_first_error_(stop_at_first_error) {
    interp->set_source(input);
  }

  // Reads and interprets one line. False when there is nothing more to do:
  // end of input, an I/O error, an input that is not text (one error for it
  // all), an over-long line with no end in reach, or the first error when
  // stopping at it; also (not done()) when the input has no whole line yet
  // (waiting()). After the end of the program (M2, M30, closing %) lines
  // are still read, to warn once about code after it.
  bool step();
  // Runs step() until it returns false.
  void run_all() {
    while (step()) {
    }
  }
  bool done() const { return done_; }
  // The last step found no whole line: the input is still being fed.
  bool waiting() const { return waiting_; }
  bool io_error() const { return io_error_; }
  uint32_t lines() const { return lines_; }
  // Errors not passed to the messages because they may be only consequences
  // of earlier ones (GcodeDiag::follow_on); when not stopping at the first.
  uint32_t follow_ons() const { return follow_ons_; }
  // Passes follow-ons to the messages too (marked in their text).
  void show_follow_ons(bool on) { show_follow_ons_ = on; }

 private:
  void show_file();

  LineInput* input_;
  Interp* interp_;
  GcodeMessages* messages_;
  bool stop_at_first_error_;
  bool done_ = false;
  bool waiting_ = false;
  bool io_error_ = false;
  uint32_t lines_ = 0;
  uint32_t last_line_ = 0;  // the program file's last line number read
  uint16_t shown_file_ = 0;  // the file messages name
  uint32_t follow_ons_ = 0;
  bool show_follow_ons_ = false;
};

}  // namespace dexmill

#endif
