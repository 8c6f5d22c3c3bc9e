// --sheet FILE.html (platform/report/sheet_html.h): the pictures the sheet
// shows rendered from the final grid (iso and top views, the error view
// and a close-up crop around each of the worst gouges when a design is
// given), the load plot when engagement was measured, and the page drawn
// from the report into the run's output set (platform/os/output_set.h).
#ifndef DEXMILL_TOOLS_RUN_RUN_SHEET_H
#define DEXMILL_TOOLS_RUN_RUN_SHEET_H

#include "platform/report/run_report.h"
#include "tools/run/run_options.h"
#include "tools/run/run_setup.h"

namespace dexmill {
namespace cli {

// Writes the sheet of `rep` (the report as complete as it is when the
// other outputs are written); kExitOk, or the exit code with the message
// printed (a picture the renderer refuses, a file that cannot be written).
int write_sheet(const RunOptions& o, RunSetup* su, const RunReport& rep);

}  // namespace cli
}  // namespace dexmill

#endif
