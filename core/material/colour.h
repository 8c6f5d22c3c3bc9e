// A colour of the material layer: 8 bits per channel, sRGB as stored. The
// display has its own Rgb (display/raster/framebuffer.h) with the same fields;
// core cannot include display/, so it converts field by field.
#ifndef DEXMILL_CORE_MATERIAL_COLOUR_H
#define DEXMILL_CORE_MATERIAL_COLOUR_H

#include <stdint.h>

namespace dexmill {

struct Rgb8 {
  uint8_t r, g, b;
};

inline bool operator==(Rgb8 a, Rgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
inline bool operator!=(Rgb8 a, Rgb8 b) { return !(a == b); }

// a + (b - a) w per channel, w in q16 clamped to [0, 65536], rounded to
// nearest: every channel lies between a's and b's (the textures' palette
// tests rely on it).
inline Rgb8 rgb_mix(Rgb8 a, Rgb8 b, int32_t w_q16) {
  const uint32_t w = w_q16 < 0 ? 0u : (w_q16 > 65536 ? 65536u : static_cast<uint32_t>(w_q16));
  auto ch = [w](uint32_t x, uint32_t y) { return static_cast<uint8_t>((x * (65536u - w) + y * w + 32768u) >> 16); };
  return Rgb8{ch(a.r, b.r), ch(a.g, b.g), ch(a.b, b.b)};
}

}  // namespace dexmill

#endif
