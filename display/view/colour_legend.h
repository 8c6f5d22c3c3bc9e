// The legends of the colour modes (display/colour/*.h), written once into
// a ViewLegend's fixed labels: what `dexmill run --color slope|tool|thin|
// engagement|error` draws under its pictures and what the embedding API's
// dm_view_set_colour draws (display/api/dexmill.h), the same bytes. The
// material mode has none. Integer only, no heap: every label is cut at
// kViewLabelBytes - 1 bytes.
#ifndef DEXMILL_DISPLAY_VIEW_COLOUR_LEGEND_H
#define DEXMILL_DISPLAY_VIEW_COLOUR_LEGEND_H

#include <stddef.h>
#include <stdint.h>

#include "core/tool/tool.h"
#include "display/view/stock_view.h"

namespace dexmill {

// The number the tool in the spindle before any M6 is listed under in the
// provenance's tool order (core/sim/job.h provenance_first_tool): named by
// its shape alone.
constexpr int32_t kLegendInitialTool = -1;

// Every field empty (no swatches, no labels, no captions).
void colour_legend_clear(ViewLegend* l);
// --color slope: the bands' limits in degrees.
void colour_legend_slope(ViewLegend* l);
// --color thin --thin MM: thinnest on the left, the limits half and whole.
void colour_legend_thin(ViewLegend* l, int64_t thin_nm);
// --color engagement: the load limit's percentages (by_limits) or the
// engaged angle's degrees.
void colour_legend_engagement(ViewLegend* l, bool by_limits);
// --color error: gouges on the left, dark to light, within tolerance
// white, then material left; the limits tol_nm's multiples.
void colour_legend_error(ViewLegend* l, int64_t tol_nm);

// What the tool legend names a tool number by: tool(ctx, number, &t) true
// with its tool, false for an unknown number (then its number alone);
// `initial` the tool before any M6.
struct ToolLegendNames {
  bool (*tool)(const void* ctx, int32_t number, Tool* out) = nullptr;
  const void* ctx = nullptr;
  Tool initial{};
};
// --color tool: "uncut", then a swatch per colour in use named by its
// tools, tools[0, ntools) in the order they first cut (core/sim/provenance.h):
// "T1 FLAT 6"; with more tools than colours, the numbers sharing a colour
// alone, "T1/T8".
void colour_legend_tool(ViewLegend* l, const int32_t* tools, int32_t ntools, const ToolLegendNames& names);

// "flat 6" for flat:6,len=20...: the kind and diameter of a tool's spec,
// NUL terminated in buf[0, n); its length.
size_t tool_short_name(const Tool& t, char* buf, size_t n);

}  // namespace dexmill

#endif
