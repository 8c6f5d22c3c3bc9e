// `dexmill run A.nc [--setup T] B.nc ...`: programs in order on one stock.
// Each program runs as `dexmill run` runs one (tools/run/run_job.h); between
// two, the stock goes through a stock file in the temporary folder
// (core/stock/stock_file.h: exact), so the next starts from the last one's
// stock, where its tool was left, turned by the --setup options given
// before it. The options' outputs (images, heightmap, STL, report, the
// summary, --save-stock) are the last program's, whose report holds the
// chain; the programs before it print only their diagnostics.
#ifndef DEXMILL_TOOLS_RUN_RUN_CHAIN_H
#define DEXMILL_TOOLS_RUN_RUN_CHAIN_H

#include "platform/input/file_guard.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// The exit status of the first program that fails, or the last one's.
int run_chain(const RunOptions& o);

}  // namespace cli
}  // namespace dexmill

#endif
