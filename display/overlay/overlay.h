// The paper's first view of the error (§2.5.1, figure 9): two surfaces drawn
// together, one of them translucent. Each is rendered opaque into a frame of
// its own with the same camera and scene frame (renderer_share_frame), then
// the translucent one is blended over the other wherever it is the nearer:
// depth-tested, one layer (no surface is seen through itself), half and
// half per channel. With the design translucent over the cut, it shows
// where the cut went below the design (overcut); with the cut translucent
// over the design, where material is left (undercut). Integer only.
#ifndef DEXMILL_DISPLAY_OVERLAY_OVERLAY_H
#define DEXMILL_DISPLAY_OVERLAY_OVERLAY_H

#include <stdint.h>

#include "display/raster/framebuffer.h"
#include "display/raster/raster.h"

namespace dexmill {

// A depth buffer as the rasterizer keeps it (raster.h).
struct DepthView {
  const uint8_t* z = nullptr;
  int32_t stride_bytes = 0;
  ZFormat format = ZFormat::kZ32;
};

// Over rectangle r (clipped to both frames): where top's depth is nearer
// than base's, base's pixel becomes the mean of the two (per channel,
// rounded down). The frames must have the same format and size and the
// depths the same format (else nothing is drawn; false).
bool overlay_blend(const FrameView& base, const DepthView& base_z, const FrameView& top, const DepthView& top_z,
                   ScreenRect r);

}  // namespace dexmill

#endif
