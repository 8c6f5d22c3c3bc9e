// The tool a comment of a program describes, where CAM posts write one
// (what `dexmill run` cuts with when no --tool or --tools says otherwise;
// core/sim/tool_choice.h):
//
//   spec     (T1 ball:3.175)  a --tool spec word (core/tool/spec.h), mm
//   fusion   (T1 D=3.175 CR=0. TAPER=45deg - ZMIN=-1 - chamfer mill)
//            Autodesk Fusion's tool list: D, CR, the taper (a chamfer
//            mill's half angle, a drill's point angle) and the tool type
//   apt      (TOOL/MILL,3.17, 0.00, 10.00, 45.00)  CutViewer's and APT's
//            diameter, corner radius, height and taper half angle (Carbide
//            Create, Vectric, OpenVoronoi examples); (TOOL/DRILL,D,ANGLE)
//   table    (T1 P1 D6.0 Z+30 ;ball nose) a LinuxCNC tool table line, or
//            (1 1 -1.1901 0.250 3/4 center drill) its old columns T P Z D
//   cambam   ( T0 : 1.0 )  CamBam's tool number and diameter
//   pcb2gcode (MSG, Change tool bit to drill size 0.8mm), mill/cutter diameter
//   pycam    ;tool_radius = 0.79375 after ;shape = CylindricalCutter
//   named    a tool named by its kind and one size: Estlcam's
//            (HSS, 2-Flute Endmill, 2mm) and (Change tool: End mill 3mm),
//            Vectric's (1 = End Mill {6 mm}) and (Tool: Ball Nose {0.125 inch}),
//            CAMotics' (Tool: 1/4 in Carbide End Mill), UGS's ; Tool: 3.0mm,
//            FreeCAD's (5mm Endmill001), (Bit diameter: 1/8")
//
// Conservative by design: a wrong tool is worse than none, so a comment
// that could mean something else is no tool. A named tool needs a kind
// word (end mill, ball, bull nose, V-bit with its angle, drill, bit,
// cutter, or a "Tool:" label) and exactly one size with its unit (or after
// "diameter"), in at most 10 words, none of them a word that makes the size
// something else (depth, stock, safe, height, step, pass, offset, feed,
// hole, size, width, length, ...). Taps, thread mills, probes, boring bars,
// dovetail, lollipop, tapered and chamfer mills named in free text are no
// tool: their shape is not one dexmill cuts. Drills are V-bits of their
// point angle (118 degrees unless given).
//
// Lengths without a unit are in the program's units where the tool is
// loaded, which the caller knows (tool_comment_tool). A name whose size has
// no unit ((1/4 endmill), at most 6 words, one amount that is not a count
// such as "2 flute") or whose only kind word is "mill" is weak: the caller
// believes it only on the line of the M6 that loads the tool.
#ifndef DEXMILL_CORE_TOOL_TOOL_COMMENT_H
#define DEXMILL_CORE_TOOL_TOOL_COMMENT_H

#include <stddef.h>
#include <stdint.h>

#include "core/tool/tool.h"

namespace dexmill {

enum class ToolCommentForm : uint8_t {
  kNone = 0,
  kSpec,
  kFusion,
  kApt,
  kTable,
  kCamBam,
  kPcb2gcode,
  kPycam,
  kNamed,
};

// The form's name as above ("fusion"); "none" for kNone.
const char* tool_comment_form_name(ToolCommentForm f);

enum class CommentUnit : uint8_t {
  kProgram = 0,  // the program's G20/G21 where the tool is loaded
  kMm = 1,
  kInch = 2,
};

// What a comment says of a tool, before its units are known.
struct ToolComment {
  ToolCommentForm form = ToolCommentForm::kNone;
  int32_t number = -1;           // the T number it names; -1: none
  ToolKind kind = ToolKind::kFlat;
  CommentUnit unit = CommentUnit::kProgram;
  int64_t diameter_e9 = 0;       // in `unit`, 1e-9 of it
  int64_t corner_e9 = 0;         // kBullNose
  int32_t tip_angle_mdeg = 0;    // kVBit: included angle
  Tool spec{};                   // kSpec: the tool whole
  // A name whose size has no unit, or whose kind is only "mill" ((1/4
  // endmill), (0.0625 mill)): too weak to believe but on the line of the
  // M6 that loads the tool.
  bool weak = false;
};

// What earlier comments said that a later one completes (PyCAM writes the
// cutter's shape and its radius on separate lines).
struct ToolCommentState {
  bool pycam_shape = false;
  ToolKind pycam_kind = ToolKind::kFlat;
  int64_t pycam_corner_e9 = 0;
};

// Reads one comment's text s[0, n) (what is between its parentheses, or
// after ';'). True with *out when it describes a tool.
bool tool_comment_read(const char* s, size_t n, ToolCommentState* state, ToolComment* out);

// The tool, with lengths the comment gave no unit for in inch (G20) or mm:
// false when it is out of range (core/tool/spec.h tool_spec_complete).
bool tool_comment_tool(const ToolComment& c, bool inch, Tool* out);

// What a tool table row's remark (";ball nose", ";3 mm drill", ";vbit
// 60deg") says of its shape, the diameter being the row's D.
enum class RemarkShape : uint8_t {
  kNone = 0,   // no kind word: the row is cut as a flat end mill, as a table means
  kNamed,      // a shape dexmill cuts: *kind and *tip_angle_mdeg set
  kUnusable,   // a kind it cannot complete (a bull nose without its radius, a
               // V-bit without its angle) or does not cut (a tap, a probe)
};

// The same kind words as the program comments' named tools (tool_comment.h
// above), read from s[0, n).
RemarkShape tool_remark_shape(const char* s, size_t n, ToolKind* kind, int32_t* tip_angle_mdeg);

}  // namespace dexmill

#endif
