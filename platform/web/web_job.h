// web_job.h - the one job the module holds (web_api.cpp makes and ends
// it), shared by the files that add exports over it (web_*.cpp, one topic
// each), and the one text buffer the page writes into (web_text()).
#ifndef DEXMILL_PLATFORM_WEB_WEB_JOB_H
#define DEXMILL_PLATFORM_WEB_WEB_JOB_H

#include <stddef.h>
#include <stdint.h>

#include "display/api/dexmill.h"

#define WEB_EXPORT(name) extern "C" __attribute__((export_name(#name)))

namespace dexmill {
namespace web {

// The program's pieces (dexmill.js slices the file at this size); lent to
// dm_feed until dm_input_taken, as dexmill.h says.
constexpr size_t kTextBytes = 64 * 1024;
extern char g_text[kTextBytes];

struct WebJob {
  dm_job job;
  dm_sim* sim;
  dm_view* view;
  dm_frame frame;
  dm_progress progress;
  size_t arena_used;  // bytes of the arena the job holds (web_create), for what a topic adds behind it
};
extern WebJob g;

inline size_t round8(size_t n) { return (n + 7) & ~static_cast<size_t>(7); }

}  // namespace web
}  // namespace dexmill

#endif
