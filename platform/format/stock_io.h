// Stock files (.dxstock, core/stock/stock_file.h) on the host: written as
// every output is (platform/os/output_file.h: complete or not at all), read
// in 1 MiB pieces straight into the engine's columns, so a 64 M-dexel stock
// never has a second copy in memory.
#ifndef DEXMILL_PLATFORM_FORMAT_STOCK_IO_H
#define DEXMILL_PLATFORM_FORMAT_STOCK_IO_H

#include <cstdio>
#include <string>
#include <vector>

#include "core/stock/stock_file.h"

namespace dexmill {

// Writes the stock to path; false with *err set ("cannot write ...").
bool write_stock_file(const char* path, const StockMeta& m, const StockColumns& c, std::string* err);

// A stock file being read: open() reads up to the end of its header (meta()),
// read_columns() the rest into the caller's columns. Errors are
// "PATH:1:COL: error: message", COL the byte (from 1) the reader stopped
// at (a stock file is one line of bytes to an editor), or "dexmill: error:
// cannot read ..." (io_error()).
class StockFileReader {
 public:
  StockFileReader() = default;
  ~StockFileReader();
  StockFileReader(const StockFileReader&) = delete;
  StockFileReader& operator=(const StockFileReader&) = delete;
  bool open(const std::string& path, std::string* err);
  const StockMeta& meta() const { return reader_.meta(); }
  bool read_columns(const StockColumns& c, std::string* err);
  bool io_error() const { return io_error_; }

 private:
  bool feed_until_bound_or_end(std::string* err);
  std::string error_text(StockError e) const;
  std::FILE* f_ = nullptr;
  std::string path_;
  StockReader reader_;
  std::vector<unsigned char> buf_ = std::vector<unsigned char>(size_t{1} << 20);
  size_t have_ = 0, at_ = 0;  // bytes in buf_, and the next one to feed
  bool io_error_ = false;
};

}  // namespace dexmill

#endif
