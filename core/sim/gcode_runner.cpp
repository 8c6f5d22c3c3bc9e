// Lines into the interpreter; see gcode_runner.h.
#include "core/sim/gcode_runner.h"

namespace dexmill {

void GcodeRunner::show_file() {
  shown_file_ = input_->file_index();
  messages_->set_file(input_->name());
}

bool GcodeRunner::step() {
  if (done_) return false;
  const char* text = nullptr;
  size_t len = 0;
  uint32_t line_no = 0;
  const LineReader::Read r = input_->next(&text, &len, &line_no);
  waiting_ = r == LineReader::Read::kWait;
  if (waiting_) return false;
  if (r == LineReader::Read::kEof) {
    done_ = true;
    GcodeDiag d{};
    // What is left unclosed is reported at its line in the program (a
    // subroutine file may have ended before its sub was found).
    if (shown_file_ != 0) messages_->set_file(input_->program_name());
    if (interp_->end_of_input(last_line_, &d) != GcodeError::kOk) messages_->error(d);
    return false;
  }
  if (r == LineReader::Read::kIoError) {
    io_error_ = true;
    done_ = true;
    return false;
  }
  if (r == LineReader::Read::kEndless) {
    done_ = true;  // its over-long line was the error
    return false;
  }
  GcodeDiag d{};
  if (r == LineReader::Read::kNotText) {
    // One error for the whole input, however many lines it would make.
    d.code = input_->not_text(d.word);
    d.line = 1;
    d.col = 1;
    messages_->error(d);
    done_ = true;
    return false;
  }
  ++lines_;
  if (input_->file_index() == 0 && line_no > last_line_) last_line_ = line_no;
  if (input_->file_index() != shown_file_) show_file();
  GcodeError e;
  if (r == LineReader::Read::kTooLong) {
    e = GcodeError::kLineTooLong;
    d.code = e;
    d.line = line_no;
    d.col = static_cast<uint16_t>(kGcodeMaxLine + 1);
    d.a_nm = static_cast<int64_t>(kGcodeMaxLine);
    if (interp_->ended()) e = GcodeError::kOk;  // nothing after the end is read
    interp_->line_not_read();
  } else {
    e = interp_->execute_line(text, len, line_no, &d);
  }
  if (e != GcodeError::kOk && d.follow_on) ++follow_ons_;  // maybe a consequence of an error already reported
  if (e != GcodeError::kOk && (!d.follow_on || show_follow_ons_)) {
    if (!d.line) d.line = line_no;  // the interpreter names another line for an endless loop
    messages_->error(d);
    if (stop_at_first_error_) {
      done_ = true;
      return false;
    }
  }
  // After M2/M30 the interpreter ignores lines (warning once if they hold
  // code), so reading on is cheap and tells the user what was skipped.
  return true;
}

}  // namespace dexmill
