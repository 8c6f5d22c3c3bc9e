// web_colour.cpp - the page's colour modes (`--color`, `--thin`,
// `--material`, `--design` of `dexmill run`; platform/web/page_colour.js)
// over the C API's dm_view_set_colour: the job made again when the mode
// needs what it is made with (tool: provenance; a material preset; a
// design, read from its STL file's bytes by dm_design_from_stl), the
// mode's memory behind the job's in the arena (web_job.h arena_used), and
// the presets' names for the page's list.
#include <string.h>

#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"

using namespace dexmill::web;

extern "C" int32_t web_create(int32_t w, int32_t h, int32_t preset, int32_t flags, int32_t decorations);

namespace {

char g_material[64];  // dm_job.material's text, NUL terminated

// A design read for the next web_colour: its STL bytes at g_design_at in
// the arena, then its triangles; past what the job made again takes.
size_t g_design_at = 0, g_design_bytes = 0;
uint32_t g_design_n = 0;
bool g_design_ready = false;

// The modes by the CLI's names (tools/CLI.md --color), DM_COLOUR_* in order.
const char* const kModes[] = {"plain", "slope", "tool", "material", "thin", "error"};
static_assert(sizeof kModes / sizeof kModes[0] == DM_COLOUR_ERROR + 1, "a name a mode");

int32_t mode_of(const char* text, size_t n) {
  for (int32_t k = 0; k <= DM_COLOUR_ERROR; ++k)
    if (strlen(kModes[k]) == n && memcmp(kModes[k], text, n) == 0) return k;
  return -1;
}

}  // namespace

// Material preset k's name (NUL terminated), null past the last.
WEB_EXPORT(web_material_name) const char* web_material_name(int32_t k) { return dm_material_preset_name(k); }

// The job's colour mode, after web_create: web_text() holds the mode's name
// [0, nmode), the material preset's [nmode, nmode + nmaterial) (0: none)
// and --thin's mm [.., + nthin) (0: 1 mm); preset, flags and decorations
// are web_create's, for the job made again with provenance or a material.
WEB_EXPORT(web_colour) int32_t web_colour(int32_t nmode, int32_t nmaterial, int32_t nthin, int32_t preset,
                                          int32_t flags, int32_t decorations) {
  if (nmode < 0 || nmaterial < 0 || nthin < 0 || static_cast<size_t>(nmode) + nmaterial + nthin > kTextBytes ||
      static_cast<size_t>(nmaterial) >= sizeof g_material || !g.view)
    return DM_E_ARGUMENT;
  const int32_t mode = mode_of(g_text, static_cast<size_t>(nmode));
  if (mode < 0) return DM_E_ARGUMENT;
  dm_colour c{mode, 0, 0};
  if (nthin > 0)
    if (const dm_status s = dm_mm_to_nm(g_text + nmode + nmaterial, static_cast<size_t>(nthin), &c.thin_nm)) return s;
  if (mode == DM_COLOUR_TOOL || nmaterial > 0 || g_design_ready) {
    memcpy(g_material, g_text + nmode, static_cast<size_t>(nmaterial));
    g_material[nmaterial] = '\0';
    g.job.material = nmaterial > 0 ? g_material : nullptr;
    g.job.provenance = mode == DM_COLOUR_TOOL;
    if (g_design_ready) {
      char* arena = static_cast<char*>(arena_reserve(0));
      g.job.design = reinterpret_cast<const dm_triangle*>(arena + g_design_at + round8(g_design_bytes));
      g.job.ndesign = g_design_n;
      g_design_ready = false;  // this job's; the next job reads its own
    }
    if (const dm_status s = web_create(g.frame.width, g.frame.height, preset, flags, decorations)) return s;
  }
  size_t bytes = 0;
  if (const dm_status s = dm_view_colour_bytes(g.view, &c, &bytes)) return s;
  char* arena = static_cast<char*>(arena_reserve(g.arena_used + bytes));
  if (!arena) return DM_E_MEMORY;
  if (const dm_status s = dm_view_set_colour(g.view, &c, bytes ? arena + g.arena_used : nullptr, bytes)) return s;
  g.arena_used += round8(bytes);
  return DM_OK;
}

// Where the page writes a design's STL file of n bytes (null: no memory):
// behind the job's memory and what a job made again with a design, a
// material and provenance would add, so that making it leaves the file and
// its triangles be (dm_create reads them, and only then).
WEB_EXPORT(web_design_buffer) char* web_design_buffer(int32_t n) {
  g_design_ready = false;
  if (n < 0 || !g.view) return nullptr;
  dm_job j = g.job;
  j.design = reinterpret_cast<const dm_triangle*>(g_text);  // sizing reads no triangle
  j.ndesign = 1;
  j.material = dm_material_preset_name(0);
  j.provenance = 1;
  size_t sim_bytes = 0;
  if (dm_required_bytes(&j, &sim_bytes) != DM_OK) return nullptr;
  g_design_at = round8(sim_bytes) + g.arena_used;  // the frame and view are the job's now
  g_design_bytes = static_cast<size_t>(n);
  char* arena = static_cast<char*>(arena_reserve(g_design_at + round8(g_design_bytes)));
  return arena ? arena + g_design_at : nullptr;
}

// The design's triangles from the bytes written at web_design_buffer, for
// the job web_colour makes again: how many, or minus DM_E_DESIGN (not an
// STL file, or none in it) or DM_E_MEMORY.
WEB_EXPORT(web_design_read) int32_t web_design_read() {
  const char* bytes = static_cast<const char*>(arena_reserve(0)) + g_design_at;
  uint32_t n = 0;
  if (const dm_status s = dm_design_from_stl(bytes, g_design_bytes, nullptr, 0, &n)) return -s;
  if (n > INT32_MAX) return -DM_E_DESIGN;
  char* arena = static_cast<char*>(
      arena_reserve(g_design_at + round8(g_design_bytes) + static_cast<size_t>(n) * sizeof(dm_triangle)));
  if (!arena) return -DM_E_MEMORY;
  dm_triangle* out = reinterpret_cast<dm_triangle*>(arena + g_design_at + round8(g_design_bytes));
  if (const dm_status s = dm_design_from_stl(arena + g_design_at, g_design_bytes, out, n, &n)) return -s;
  g_design_n = n;
  g_design_ready = true;
  return static_cast<int32_t>(n);
}
