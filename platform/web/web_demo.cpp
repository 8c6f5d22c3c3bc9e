// web_demo.cpp - the built-in demo's exports (display/api/dexmill.h
// dm_demo_program, dm_demo_text): its program written into the arena
// behind the job there is (platform/web/page_scan.js copies it out and
// cuts it as a file), its stock and tool table as the CLI's texts.
#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"

using namespace dexmill::web;

namespace {
char* g_demo = nullptr;  // the program, until the next job takes the arena
}

// Writes the demo's program: its length in bytes (web_demo_text_at() then
// holds it), or minus DM_E_MEMORY.
WEB_EXPORT(web_demo_program) int32_t web_demo_program() {
  const size_t n = dm_demo_program(nullptr, 0), at = round8(g.arena_used);
  char* base = static_cast<char*>(arena_reserve(at + n + 1));
  if (!base) return -DM_E_MEMORY;
  g_demo = base + at;
  (void)dm_demo_program(g_demo, n + 1);
  return static_cast<int32_t>(n);
}
WEB_EXPORT(web_demo_text_at) const char* web_demo_text_at() { return g_demo; }

// DM_DEMO_STOCK, DM_DEMO_TOOL_TABLE, ...: NUL terminated (null for another).
WEB_EXPORT(web_demo_text) const char* web_demo_text(int32_t which) { return dm_demo_text(which); }
