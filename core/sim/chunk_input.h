// A program fed in pieces by its caller (the embedding API's dm_feed, a
// panel reading an SD card block by block): the LineInput a Simulation
// reads when it is not given a file. zlib's next_in/avail_in is the model:
// feed() lends a piece of text, which must stay where it is until taken()
// says every byte of it has been read into the reader's buffer; the lines
// come out as the same bytes in one piece would give them
// (core/gcode/line_reader.h).
//
// Going back (an o-word loop or call jumps to a line read before) works
// while that line is still in the reader's buffer, or through a re-reader
// the caller gives (it still has the file); otherwise the interpreter
// reports the jump it cannot make (GcodeError::kOwordSeek) at its line.
#ifndef DEXMILL_CORE_SIM_CHUNK_INPUT_H
#define DEXMILL_CORE_SIM_CHUNK_INPUT_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/line_reader.h"

namespace dexmill {

// Copies up to n bytes of the program from `offset` into buf; returns how
// many (0: none, a read error).
typedef size_t (*ChunkReReader)(void* ctx, uint64_t offset, char* buf, size_t n);

class ChunkInput final : public LineInput, private ByteSource {
 public:
  // buf: caller memory of `bytes` for the reader (LineReader::kStartBytes
  // decides on a whole file's first 64 KiB as the host does; a panel may
  // give less).
  ChunkInput(char* buf, size_t bytes) : reader_(buf, bytes) { reader_.set_source(this); }

  // Lends the next n bytes of the program (a piece not yet taken is
  // replaced: call when taken()). After close() nothing more is taken.
  void feed(const char* text, size_t n) {
    chunk_ = text;
    chunk_n_ = closed_ ? 0 : n;
    chunk_pos_ = 0;
  }
  // The program has no more bytes.
  void close() { closed_ = true; }
  bool closed() const { return closed_; }
  // Every byte lent has been read into the buffer (the piece may go).
  bool taken() const { return chunk_pos_ >= chunk_n_; }
  // Bytes of the program read from the pieces so far.
  uint64_t fed_bytes() const { return stream_off_; }
  void set_rereader(ChunkReReader fn, void* ctx) {
    reread_ = fn;
    reread_ctx_ = ctx;
  }
  // The name messages give the program.
  void set_name(const char* name) { name_ = name ? name : "<program>"; }

  // LineInput.
  LineReader::Read next(const char** text, size_t* len, uint32_t* line_no) override {
    return reader_.next(text, len, line_no);
  }
  const char* name() const override { return name_; }
  GcodeError not_text(char word[16]) const override { return reader_.not_text(word); }
  SourcePos line_start() const override { return SourcePos{reader_.line_offset(), reader_.line_number(), 0}; }
  SourcePos line_next() const override { return SourcePos{reader_.next_offset(), reader_.line_number() + 1, 0}; }
  bool seek(const SourcePos& p) override;
  uint64_t bytes_read() const { return reader_.bytes_read(); }

 private:
  Fill read_bytes(char* buf, size_t n, size_t* got) override;
  bool seek_bytes(uint64_t offset) override;

  LineReader reader_;
  const char* chunk_ = nullptr;
  size_t chunk_n_ = 0, chunk_pos_ = 0;
  bool closed_ = false;
  uint64_t stream_off_ = 0;  // the program's offset of chunk_[chunk_pos_]
  uint64_t read_off_ = 0;    // the offset the reader reads next (< stream_off_: re-read)
  ChunkReReader reread_ = nullptr;
  void* reread_ctx_ = nullptr;
  const char* name_ = "<program>";
};

}  // namespace dexmill

#endif
