// A program fed in pieces; see chunk_input.h.
#include "core/sim/chunk_input.h"

#include <string.h>

namespace dexmill {

ByteSource::Fill ChunkInput::read_bytes(char* buf, size_t n, size_t* got) {
  *got = 0;
  if (read_off_ < stream_off_) {  // after a jump back: what the caller still has
    const uint64_t left = stream_off_ - read_off_;
    const size_t want = left < n ? static_cast<size_t>(left) : n;
    const size_t k = reread_ ? reread_(reread_ctx_, read_off_, buf, want) : 0;
    if (k == 0 || k > want) return Fill::kError;
    read_off_ += k;
    *got = k;
    return Fill::kBytes;
  }
  const size_t left = chunk_n_ - chunk_pos_;
  if (left == 0) return closed_ ? Fill::kEnd : Fill::kWait;
  const size_t k = left < n ? left : n;
  memcpy(buf, chunk_ + chunk_pos_, k);
  chunk_pos_ += k;
  stream_off_ += k;
  read_off_ = stream_off_;
  *got = k;
  return Fill::kBytes;
}

bool ChunkInput::seek_bytes(uint64_t offset) {
  if (offset > stream_off_ || (offset < stream_off_ && !reread_)) return false;
  read_off_ = offset;
  return true;
}

bool ChunkInput::seek(const SourcePos& p) {
  if (p.file != 0 || p.line == 0) return false;
  if (reader_.seek_in_buffer(p.offset, p.line)) return true;
  if (!seek_bytes(p.offset)) return false;
  reader_.restart(p.offset, p.line);
  return true;
}

}  // namespace dexmill
