// web_colour.cpp - the page's colour modes (`--color`, `--thin`,
// `--material` of `dexmill run`; platform/web/page_colour.js) over the C
// API's dm_view_set_colour: the job made again when the mode needs what it
// is made with (tool: provenance; a material preset), the mode's memory
// behind the job's in the arena (web_job.h arena_used), and the presets'
// names for the page's list.
#include <string.h>

#include "display/api/dexmill.h"
#include "platform/web/web_arena.h"
#include "platform/web/web_job.h"

using namespace dexmill::web;

extern "C" int32_t web_create(int32_t w, int32_t h, int32_t preset, int32_t flags, int32_t decorations);

namespace {

char g_material[64];  // dm_job.material's text, NUL terminated

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
  if (mode == DM_COLOUR_TOOL || nmaterial > 0) {
    memcpy(g_material, g_text + nmode, static_cast<size_t>(nmaterial));
    g_material[nmaterial] = '\0';
    g.job.material = nmaterial > 0 ? g_material : nullptr;
    g.job.provenance = mode == DM_COLOUR_TOOL;
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
