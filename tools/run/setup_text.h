// A setup as the command line and the setups file spell it: flip-x,
// flip-y, rotate-90|180|270, offset=X,Y,Z (mm), joined by '+' (or
// spaces), applied flips first, then the turn, then the offset
// (core/stock/stock_transform.h); and the words for a setup the chain
// recorded.
#ifndef DEXMILL_TOOLS_RUN_SETUP_TEXT_H
#define DEXMILL_TOOLS_RUN_SETUP_TEXT_H

#include <string>

#include "core/stock/stock_transform.h"

namespace dexmill {
namespace cli {

// False with *why (what was wrong, naming the word) for anything else.
bool setup_parse(const std::string& text, StockSetup* out, std::string* why);

// "flip-x+rotate-90+offset=10,0,-2", "none" for the identity.
std::string setup_text(const StockSetup& s);

// The setup a chain's program records (core/stock/stock_file.h
// StockProgram), as text; "?" for a turn no setup makes (a file of
// another writer).
std::string recorded_setup_text(const int8_t turn[9], const int64_t offset_nm[3]);

}  // namespace cli
}  // namespace dexmill

#endif
