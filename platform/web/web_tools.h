// web_tools.h - the tool table the module holds (web_tools.cpp), for the
// files of exports that set a job up with it (web_scan.cpp).
#ifndef DEXMILL_PLATFORM_WEB_WEB_TOOLS_H
#define DEXMILL_PLATFORM_WEB_WEB_TOOLS_H

#include "display/api/dexmill.h"

namespace dexmill {
namespace web {

// The table's tools (none when no table was read) as the job's numbered tools.
void table_to_job(dm_job* job);

}  // namespace web
}  // namespace dexmill

#endif
