// The few lines `dexmill run` prints on standard output when it was asked
// for no output file: what it cut, and what to add for more. The same
// numbers as the JSON report (platform/report/report_json.h), from the same
// record.
#ifndef DEXMILL_PLATFORM_REPORT_REPORT_SUMMARY_H
#define DEXMILL_PLATFORM_REPORT_REPORT_SUMMARY_H

#include <string>

#include "platform/report/run_report.h"

namespace dexmill {

std::string report_summary_text(const RunReport& r);

}  // namespace dexmill

#endif
