// The embedding API's colour modes (dexmill.h dm_view_set_colour): the
// modes of display/colour/ over the simulation's grid, in the caller's
// memory, with the legends of display/view/colour_legend.h, set up as
// `dexmill run --color MODE` sets them up (tools/run/run_colours.cpp,
// run_views.cpp), so the frames are its images' bits.
#include <new>

#include "display/api/handles.h"
#include "display/colour/error_colours.h"
#include "display/colour/material_colours.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"
#include "display/view/colour_legend.h"

using namespace dexmill;
using namespace dexmill::api;

static_assert(kErrorBands <= kMaxColourClasses, "one ramp block holds every mode's");

namespace dexmill {
namespace api {

// A mode's state: the head of its caller memory; its classes, ramps and
// (material) texture follow.
struct ViewColour {
  int32_t mode = DM_COLOUR_PLAIN;
  const dm_sim* sim = nullptr;
  uint8_t* cls = nullptr;
  // tool: the provenance's classes (one a tool, kProvenanceMaxTools of
  // them, so that dm_column names its tool) folded into the palette's.
  const ToolProvenance<height_t>* prov = nullptr;
  int32_t legend_tools = -1;  // prov->ntools when the legend was made
  SurfaceColours tool;
  SlopeColours<height_t> slope;
  ThinColours<height_t> thin;
  MaterialColours<height_t> material;
  ErrorColours<height_t> error;
  ViewLegend legend;
  bool has_legend = false;
};

}  // namespace api
}  // namespace dexmill

namespace {

size_t up8(size_t n) { return (n + 7) & ~size_t{7}; }

constexpr int64_t kThinDefaultNm = DM_NM_PER_MM;  // the CLI's --thin default
constexpr int64_t kThinMaxNm = 1000LL * DM_NM_PER_MM;

size_t cells_of(const DexelGrid<height_t>& g) { return static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny); }
size_t luts_bytes() { return static_cast<size_t>(kMaxColourClasses) * kShadeLevels * sizeof(uint32_t); }

// The mode's memory for this view, or its status.
dm_status bytes_of(const dm_view* view, const dm_colour* c, size_t* bytes) {
  *bytes = 0;
  const int32_t mode = c ? c->mode : static_cast<int32_t>(DM_COLOUR_PLAIN);
  if (mode < DM_COLOUR_PLAIN || mode > DM_COLOUR_ERROR || (c && c->reserved != 0)) return DM_E_ARGUMENT;
  if (mode == DM_COLOUR_THIN && (c->thin_nm < 0 || (c->thin_nm != 0 && c->thin_nm < 1000) || c->thin_nm > kThinMaxNm))
    return DM_E_ARGUMENT;
  const dm_sim* s = view->sim;
  const SimJob& job = s->sim->job();
  if ((mode == DM_COLOUR_TOOL && !s->sim->provenance()) || (mode == DM_COLOUR_MATERIAL && !job.material) ||
      (mode == DM_COLOUR_ERROR && !job.design))
    return DM_E_COLOUR;
  if (mode == DM_COLOUR_PLAIN) return DM_OK;
  const DexelGrid<height_t>& g = s->sim->grid();
  *bytes = up8(sizeof(ViewColour)) + up8(cells_of(g)) + luts_bytes() +
           (mode == DM_COLOUR_MATERIAL ? up8(material_texture_bytes(g)) : 0);
  return DM_OK;
}

// tool: the palette's class of each provenance class over r (and as far
// as a class may reach: the renderer redraws that far past a change).
void fold_tool_classes(void* ctx, GridRect r, uint8_t* cls) {
  const ViewColour& c = *static_cast<const ViewColour*>(ctx);
  const DexelGrid<height_t>& g = *c.prov->grid;
  const GridRect a = clip_to_grid(g, GridRect{r.i0 - kClassReach, r.j0 - kClassReach, r.i1 + kClassReach,
                                              r.j1 + kClassReach});
  for (int32_t j = a.j0; j < a.j1; ++j)
    for (int32_t i = a.i0; i < a.i1; ++i) {
      const size_t at = static_cast<size_t>(j) * static_cast<size_t>(g.nx) + static_cast<size_t>(i);
      const uint8_t p = c.prov->cls[at];
      cls[at] = p == 0 ? 0 : tool_colours_class_of(p - 1);
    }
}

// The tool legend's names: the job's numbered tools, or (none) every T
// the job's tool, as dm_job says.
bool job_tool(const void* ctx, int32_t number, Tool* out) {
  const dm_sim& s = *static_cast<const dm_sim*>(ctx);
  if (s.in.library.n == 0) {
    *out = s.sim->job().tool;
    return true;
  }
  return s.in.library.tool(number, out);
}

void tool_legend(ViewColour* c) {
  ToolLegendNames names;
  names.tool = job_tool;
  names.ctx = c->sim;
  names.initial = c->sim->sim->job().tool;
  c->legend_tools = c->prov->ntools;
  colour_legend_tool(&c->legend, c->prov->tool, c->prov->ntools, names);
}

// Sets the mode up in mem (sized by bytes_of); the renderer's colours.
const SurfaceColours* set_up(ViewColour* c, const dm_colour& in, char* mem) {
  const dm_sim& s = *c->sim;
  const DexelGrid<height_t>& g = s.sim->grid();
  c->mode = in.mode;
  c->cls = reinterpret_cast<uint8_t*>(mem + up8(sizeof(ViewColour)));
  uint32_t* luts = reinterpret_cast<uint32_t*>(mem + up8(sizeof(ViewColour)) + up8(cells_of(g)));
  for (size_t k = 0; k < cells_of(g); ++k) c->cls[k] = 0;
  c->has_legend = true;
  switch (in.mode) {
    case DM_COLOUR_SLOPE:
      slope_colours_init(&c->slope, g, c->cls, luts);
      colour_legend_slope(&c->legend);
      return &c->slope.colours;
    case DM_COLOUR_TOOL:
      c->prov = s.sim->provenance();
      tool_colours_init(&c->tool, *c->prov, luts);
      c->tool.cls = c->cls;  // folded from the provenance's (fold_tool_classes)
      c->tool.classify = fold_tool_classes;
      c->tool.ctx = c;
      tool_legend(c);
      return &c->tool;
    case DM_COLOUR_MATERIAL: {
      c->has_legend = false;
      material_colours_init(&c->material, g, s.material, c->cls, luts);
      // Textured, uncut tops tinted (a block stock, as the CLI's).
      void* texture = mem + up8(sizeof(ViewColour)) + up8(cells_of(g)) + luts_bytes();
      material_colours_texture(&c->material, texture, static_cast<uint32_t>(s.sim->job().plan.top_lsb));
      return &c->material.colours;
    }
    case DM_COLOUR_THIN: {
      const int64_t thin_nm = in.thin_nm ? in.thin_nm : kThinDefaultNm;
      thin_colours_init(&c->thin, g, thin_nm, c->cls, luts);
      colour_legend_thin(&c->legend, thin_nm);
      return &c->thin.colours;
    }
    default: {  // error
      for (size_t k = 0; k < cells_of(g); ++k) c->cls[k] = kBandNone;
      const AssessOptions& opt = s.sim->job().assess;
      error_colours_init(&c->error, g, *s.sim->job().design, opt, c->cls, luts);
      colour_legend_error(&c->legend, opt.tol_nm);
      return &c->error.colours;
    }
  }
}

}  // namespace

namespace dexmill {
namespace api {

void view_colour_update(dm_view* v) {
  ViewColour* c = v->colour;
  if (c && c->mode == DM_COLOUR_TOOL && c->prov->ntools != c->legend_tools) tool_legend(c);
}

}  // namespace api
}  // namespace dexmill

extern "C" {

dm_status dm_view_colour_bytes(const dm_view* view, const dm_colour* colour, size_t* bytes) {
  if (!view || view->tag != kViewTag || !bytes) return DM_E_ARGUMENT;
  *bytes = 0;
  if (!live(view)) return DM_E_STATE;
  return bytes_of(view, colour, bytes);
}

dm_status dm_view_set_colour(dm_view* view, const dm_colour* colour, void* mem, size_t bytes) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  size_t need = 0;
  if (const dm_status s = bytes_of(view, colour, &need)) return s;
  if (need > 0 && (!mem || (reinterpret_cast<uintptr_t>(mem) & 7) != 0 || bytes < need)) return DM_E_MEMORY;
  view->colour = nullptr;
  if (need == 0) {  // plain
    stock_view_set_colours(&view->v, nullptr);
    stock_view_set_legend(&view->v, nullptr);
    return DM_OK;
  }
  ViewColour* c = new (mem) ViewColour();
  c->sim = view->sim;
  const SurfaceColours* sc = set_up(c, *colour, static_cast<char*>(mem));
  view->colour = c;
  stock_view_set_colours(&view->v, sc);
  stock_view_set_legend(&view->v, c->has_legend ? &c->legend : nullptr);
  return DM_OK;
}

}  // extern "C"
