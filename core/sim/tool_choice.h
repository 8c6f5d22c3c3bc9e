// Which tool cuts for each T of a run, and where it comes from, by one
// precedence: a tool option (the CLI's --tool: every T, unless a tool table
// is given, and the tool before any M6), a tool table (--tools), the
// program's own comments (core/sim/comment_tools.h), and last a default,
// which is a guess a front end must say it made.
//
// It is the run's tool library and offsets (core/sim/job.h SimJob.library
// and .offsets): G43 lengths come from the table (0 for a tool it lacks),
// G41/G42 radii from the table, else half the diameter of the tool chosen.
// The comments are filled by the first pass (core/sim/scan.h
// ProgramScan::set_tool_choice); a lookup during that pass sees the
// comments read so far, and the cut sees them all.
#ifndef DEXMILL_CORE_SIM_TOOL_CHOICE_H
#define DEXMILL_CORE_SIM_TOOL_CHOICE_H

#include <stdint.h>

#include "core/cut/mill.h"
#include "core/interp/interp.h"
#include "core/sim/comment_tools.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class ToolSource : uint8_t { kOption = 0, kTable = 1, kComment = 2, kDefault = 3 };

// "option", "table", "comment", "default".
const char* tool_source_name(ToolSource s);

class ToolChoice final : public ToolLibrary, public ToolTable {
 public:
  // `tool` is the option's (option true) or the default; table and its
  // offsets null when there is none.
  ToolChoice(const Tool& tool, bool option, const ToolLibrary* table, const ToolTable* offsets)
      : tool_(tool), option_(option), table_(table), offsets_(offsets) {}
  ToolChoice(const ToolChoice&) = delete;
  ToolChoice& operator=(const ToolChoice&) = delete;

  CommentTools& comments() { return comments_; }
  const CommentTools& comments() const { return comments_; }

  // T `number`'s tool; false for one the table lacks that no comment gives.
  bool tool(int32_t number, Tool* out) const override;
  // Where it comes from; the comment, for kComment (else null).
  ToolSource source(int32_t number, const CommentTool** comment = nullptr) const;
  // The tool in the spindle before any M6, and where it comes from.
  Tool initial(ToolSource* source = nullptr, const CommentTool** comment = nullptr) const;

  bool tool_length_nm(int32_t number, int64_t* z_nm) const override;
  bool tool_radius_nm(int32_t number, int64_t* r_nm) const override;

 private:
  Tool tool_;
  bool option_;
  const ToolLibrary* table_;
  const ToolTable* offsets_;
  CommentTools comments_;
};

}  // namespace dexmill

#endif
