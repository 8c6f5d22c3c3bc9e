// Reading a .dxstock file in tests (core/stock/stock_file.h), with the
// core's reader: its meta and every layer, heights as 16-bit words.
#ifndef DEXMILL_TESTS_STOCK_UTIL_H
#define DEXMILL_TESTS_STOCK_UTIL_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/stock/stock_file.h"

namespace t {

struct StockFileColumns {
  dexmill::StockMeta meta;
  std::vector<uint16_t> top, bottom;
  std::vector<uint8_t> cls, program;
  std::vector<uint32_t> line;
  bool ok = false;  // read whole and of 16-bit heights
};
StockFileColumns read_stock_file(const std::string& path);

}  // namespace t

#endif
