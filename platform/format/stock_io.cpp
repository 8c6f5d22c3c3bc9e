// platform/format/stock_io.h: stock files to and from disk.
#include "platform/format/stock_io.h"

#include <cerrno>
#include <cstring>
#include <memory>

#include "platform/os/output_file.h"

namespace dexmill {
namespace {

bool to_file(void* ctx, const uint8_t* p, size_t n) {
  static_cast<OutputFile*>(ctx)->write(p, n);
  return true;  // failures are remembered by the file and reported by commit()
}

}  // namespace

bool write_stock_file(const char* path, const StockMeta& m, const StockColumns& c, std::string* err) {
  OutputFile f;
  if (f.open(path)) {
    const StockError e = stock_write(m, c, to_file, &f);
    if (e != StockError::kOk) {
      *err = std::string("cannot write '") + path + "': " + stock_error_message(e);
      return false;  // the temporary is removed; an old file stays
    }
    if (f.commit()) return true;
  }
  *err = f.error();
  return false;
}

StockFileReader::~StockFileReader() {
  if (f_) std::fclose(f_);
}

std::string StockFileReader::error_text(StockError e) const {
  std::string s = path_ + ":1:" + std::to_string(reader_.offset() + 1) + ": error: " + stock_error_message(e);
  if (*reader_.detail()) s += std::string(" (") + reader_.detail() + ")";
  return s;
}

// Feeds what is read until the reader waits for its columns or the file
// ends (then finish() says whether it ended where it should).
bool StockFileReader::feed_until_bound_or_end(std::string* err) {
  for (;;) {
    if (at_ == have_) {
      have_ = std::fread(buf_.data(), 1, buf_.size(), f_);
      at_ = 0;
      if (have_ == 0) {
        if (std::ferror(f_)) {
          *err = "dexmill: error: cannot read '" + path_ + "': " + std::strerror(errno);
          io_error_ = true;
          return false;
        }
        const StockError e = reader_.finish();
        if (e != StockError::kOk) {
          *err = error_text(e);
          return false;
        }
        return true;
      }
    }
    size_t used = 0;
    const StockError e = reader_.feed(buf_.data() + at_, have_ - at_, &used);
    at_ += used;
    if (e != StockError::kOk) {
      *err = error_text(e);
      return false;
    }
    if (reader_.header_done() && !reader_.bound()) return true;
  }
}

bool StockFileReader::open(const std::string& path, std::string* err) {
  path_ = path;
  f_ = std::fopen(path.c_str(), "rb");
  if (!f_) {
    *err = "dexmill: error: cannot read '" + path + "': " + std::strerror(errno);
    io_error_ = true;
    return false;
  }
  if (!feed_until_bound_or_end(err)) return false;
  if (!reader_.header_done()) {  // ended inside the header: finish() said so
    *err = error_text(StockError::kTruncated);
    return false;
  }
  return true;
}

bool StockFileReader::read_columns(const StockColumns& c, std::string* err) {
  if (!reader_.bind(c)) {
    *err = "dexmill: error: " + path_ + ": the stock's columns cannot be read here";
    return false;
  }
  if (!feed_until_bound_or_end(err)) return false;
  if (!reader_.done()) {
    *err = error_text(StockError::kTruncated);
    return false;
  }
  return true;
}

}  // namespace dexmill
