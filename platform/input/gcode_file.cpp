// The hosted G-code reader; see gcode_file.h.
#include "platform/input/gcode_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "core/gcode/lex.h"
#include "platform/input/file_guard.h"
#include "platform/os/process.h"
#include "platform/input/program_input.h"

namespace dexmill {

GcodeFile::GcodeFile() : tee_limit_(kDefaultMaxCopyBytes) {}

GcodeFile::~GcodeFile() {
  if (tee_) std::fclose(tee_);
  files_[cur_].f = f_;
  files_[cur_].owned = owned_;
  for (uint16_t k = 0; k < nfiles_; ++k)
    if (files_[k].f && files_[k].owned) std::fclose(files_[k].f);
}

bool GcodeFile::open(const char* path, const char* shown) {
  reader_.set_source(this);
  if (!open_one(path)) return false;
  if (shown) std::snprintf(name_, sizeof name_, "%s", shown);
  files_[0].name = name_;
  return true;
}

bool GcodeFile::open_one(const char* path) {
  if (!std::strcmp(path, "-")) {
    if (standard_input_closed()) {
      std::snprintf(error_, sizeof error_, "standard input is closed: there is no program to read");
      return false;
    }
    f_ = stdin;
    owned_ = false;
    std::snprintf(name_, sizeof name_, "<stdin>");
  } else {
    f_ = std::fopen(path, "rb");
    if (!f_) {
      std::snprintf(error_, sizeof error_, "cannot open '%s': %s", path, std::strerror(errno));
      return false;
    }
    owned_ = true;
    std::snprintf(name_, sizeof name_, "%s", path);
  }
  struct stat st;
  if (fstat(fileno(f_), &st) == 0) {
    if (S_ISREG(st.st_mode)) total_ = static_cast<int64_t>(st.st_size);
    // A pipe or a device cannot seek: what is read is copied (an anonymous
    // temporary file) as it is read, so a loop can go back. Memory stays
    // flat; the copy grows only as far as the program is read.
    else tee_ = std::tmpfile();
    if (S_ISDIR(st.st_mode)) {
      std::snprintf(error_, sizeof error_, "cannot read '%s': Is a directory", path);
      return false;
    }
  }
  return true;
}

GcodeFile::Fill GcodeFile::read_bytes(char* buf, std::size_t n, std::size_t* got) {
  if (refused_) return Fill::kError;
  std::size_t k;
  if (cur_ == 0 && tee_ && read_off_ < teed_) {
    // Read again after a seek back: from the copy.
    const uint64_t want = teed_ - read_off_ < n ? teed_ - read_off_ : n;
    k = std::fseek(tee_, static_cast<long>(read_off_), SEEK_SET) == 0
            ? std::fread(buf, 1, static_cast<std::size_t>(want), tee_)
            : 0;
    if (k == 0) {
      std::snprintf(error_, sizeof error_, "cannot read back '%s': %s", name_, std::strerror(errno));
      return Fill::kError;
    }
  } else {
    k = std::fread(buf, 1, n, f_);
    if (cur_ == 0 && tee_ && k) {
      // Keep what a pipe gave, for loops and calls to read again, up to the
      // limit (header): past it, reading goes on without a copy.
      if (teed_ + k > tee_limit_ || std::fseek(tee_, 0, SEEK_END) != 0 || std::fwrite(buf, 1, k, tee_) != k) {
        std::fclose(tee_);
        tee_ = nullptr;  // a later seek back fails with an error naming the line
      } else {
        teed_ += k;
      }
    }
  }
  read_off_ += k;
  *got = k;
  if (k) return Fill::kBytes;
  if (std::ferror(f_)) {
    std::snprintf(error_, sizeof error_, "cannot read '%s': %s", name_, std::strerror(errno));
    return Fill::kError;
  }
  return Fill::kEnd;
}

bool GcodeFile::seek_bytes(uint64_t offset) {
  if (cur_ == 0 && tee_) {
    if (offset > teed_) return false;
  } else if (std::fseek(f_, static_cast<long>(offset), SEEK_SET) != 0) {
    return false;
  }
  read_off_ = offset;
  return true;
}

// Makes `file` the one read (the reader restarts in it: the caller says where).
void GcodeFile::switch_to(uint16_t file) {
  if (file == cur_) return;
  Opened& was = files_[cur_];
  was.f = f_;
  was.owned = owned_;
  was.state = reader_.file_state();
  was.read_off = read_off_;
  const Opened& to = files_[file];
  f_ = to.f;
  owned_ = to.owned;
  reader_.set_file_state(to.state);
  read_off_ = to.read_off;
  std::snprintf(name_, sizeof name_, "%s", to.name.c_str());
  cur_ = file;
}

bool GcodeFile::seek(const SourcePos& p) {
  if (p.file >= nfiles_ || p.line == 0) return false;
  // A loop's head is usually still in the buffer: no read at all.
  if (p.file == cur_ && reader_.seek_in_buffer(p.offset, p.line)) return true;
  switch_to(p.file);
  if (!seek_bytes(p.offset)) return false;
  reader_.restart(p.offset, p.line);
  return true;
}

bool GcodeFile::open_subroutine(const char* name, SourcePos* start) {
  if (nfiles_ > kSubFilesMax) return false;
  for (const std::string& dir : sub_path_) {
    const std::string path = dir + "/" + name + ".ngc";
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) continue;
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
      std::fclose(f);
      continue;
    }
    if (guard_ && guard_->register_input(path, "subroutine") != FileGuard::Verdict::kOk) {
      // Nothing more is read: the reader's buffer is dropped, so the next
      // line is a read, which fails.
      std::fclose(f);
      std::snprintf(error_, sizeof error_, "%s", guard_->message().c_str());
      refused_ = true;
      reader_.restart(reader_.next_offset(), reader_.line_number() + 1);
      return false;
    }
    const uint16_t k = nfiles_++;
    files_[k] = Opened{f, true, LineReader::FileState{}, 0, path};
    switch_to(k);
    reader_.restart(0, 1);
    *start = SourcePos{0, 1, k};
    return true;
  }
  return false;
}

std::string gcode_diag_message(const GcodeDiag& d) {
  char msg[400];
  gcode_format_message(d, msg, sizeof msg);
  return std::string(msg) + (d.follow_on ? " (may follow from an earlier error)" : "");
}

std::size_t gcode_format_diag(const char* file, const GcodeDiag& d, bool is_error, char* buf, std::size_t n) {
  int k = std::snprintf(buf, n, "%s:%u:%u: %s: %s", file, static_cast<unsigned>(d.line), static_cast<unsigned>(d.col),
                        is_error ? "error" : "warning", gcode_diag_message(d).c_str());
  return k < 0 ? 0 : (static_cast<std::size_t>(k) < n ? static_cast<std::size_t>(k) : n - 1);
}

void GcodeStderrMessages::error(const GcodeDiag& d) {
  ++errors_;
  fold_.flush();  // the warnings before it, before it
  char line[600];
  gcode_format_diag(file_, d, true, line, sizeof line);
  std::fprintf(out_, "%s\n", line);
}

void GcodeStderrMessages::warning(const GcodeDiag& d) {
  ++warnings_;
  fold_.add(file_, d.line, d.col, gcode_diag_message(d));
}

void GcodeNotes::message(uint32_t line, int kind, const char* text) {
  static const char* const kKinds[] = {"note", "debug", "print", "message"};
  const char* k = kKinds[kind >= 1 && kind <= 3 ? kind : 0];
  kept.push_back(Note{line, k, text});
  if (print_) std::fprintf(stderr, "%s:%u: %s: %s\n", file_, line, k, text);
}

void GcodeNotes::print_kept() const {
  for (const Note& n : kept) std::fprintf(stderr, "%s:%u: %s: %s\n", file_, n.line, n.kind, n.text.c_str());
}

std::unique_ptr<GcodeMemory> gcode_memory() { return std::unique_ptr<GcodeMemory>(new GcodeMemory()); }

}  // namespace dexmill
