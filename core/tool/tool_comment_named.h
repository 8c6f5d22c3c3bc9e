// The free-text forms of core/tool/tool_comment.h: a tool named by its kind
// and size, pcb2gcode's tool change message, and the kind words they and
// the tool table rows share. Internal to core/tool/.
#ifndef DEXMILL_CORE_TOOL_TOOL_COMMENT_NAMED_H
#define DEXMILL_CORE_TOOL_TOOL_COMMENT_NAMED_H

#include <stddef.h>
#include <stdint.h>

#include "core/tool/tool_comment.h"

namespace dexmill {

// What a text's words say the tool is.
enum class NamedKind : uint8_t {
  kNone = 0,  // no kind word
  kReject,    // a tool dexmill does not cut as one of its shapes (tap, thread mill, probe, ...)
  kFlat,
  kBall,
  kBull,
  kVBit,
  kDrill,
};

NamedKind named_kind(const char* s, size_t n);

// The point angle of a drill that names none (a twist drill's), mdeg.
constexpr int32_t kDrillPointMdeg = 118000;

// Sets c's kind (and angle) for a kind whose sizes come from elsewhere (a
// table row's D): a V-bit needs its angle in the text, a bull nose cannot be
// told; false then, and for kReject.
bool named_shape_of(NamedKind k, const char* s, size_t n, ToolComment* c);

// (MSG, Change tool bit to drill size 0.8mm) and its mill/cutter diameter.
bool read_pcb2gcode(const char* s, size_t n, ToolComment* out);

// A tool named by kind and size, with an optional number first (T1 ...,
// 1 = ..., Tool 3: ...).
bool read_named(const char* s, size_t n, ToolComment* out);

}  // namespace dexmill

#endif
