// The run's tools by precedence; see tool_choice.h.
#include "core/sim/tool_choice.h"

namespace dexmill {

const char* tool_source_name(ToolSource s) {
  switch (s) {
    case ToolSource::kOption: return "option";
    case ToolSource::kTable: return "table";
    case ToolSource::kComment: return "comment";
    case ToolSource::kDefault: return "default";
  }
  return "default";
}

ToolSource ToolChoice::source(int32_t number, const CommentTool** comment) const {
  if (comment) *comment = nullptr;
  if (option_ && !table_) return ToolSource::kOption;
  Tool t;
  if (table_ && table_->tool(number, &t)) return ToolSource::kTable;
  if (const CommentTool* c = comments_.find(number)) {
    if (comment) *comment = c;
    return ToolSource::kComment;
  }
  return table_ ? ToolSource::kTable : ToolSource::kDefault;
}

bool ToolChoice::tool(int32_t number, Tool* out) const {
  const CommentTool* c = nullptr;
  switch (source(number, &c)) {
    case ToolSource::kTable: return table_->tool(number, out);
    case ToolSource::kComment: *out = c->tool; return true;
    case ToolSource::kOption:
    case ToolSource::kDefault: *out = tool_; return true;
  }
  return false;
}

Tool ToolChoice::initial(ToolSource* source, const CommentTool** comment) const {
  const CommentTool* c = option_ ? nullptr : comments_.find(kSpindleToolNumber);
  if (source) *source = option_ ? ToolSource::kOption : c ? ToolSource::kComment : ToolSource::kDefault;
  if (comment) *comment = c;
  return c ? c->tool : tool_;
}

bool ToolChoice::tool_length_nm(int32_t number, int64_t* z_nm) const {
  if (offsets_ && offsets_->tool_length_nm(number, z_nm)) return true;
  Tool t;
  if (offsets_ && !tool(number, &t)) return false;  // neither the table nor a comment knows it
  *z_nm = 0;
  return true;
}

bool ToolChoice::tool_radius_nm(int32_t number, int64_t* r_nm) const {
  if (offsets_ && offsets_->tool_radius_nm(number, r_nm)) return true;
  Tool t;
  if (!tool(number, &t)) return false;
  *r_nm = t.diameter_nm / 2;
  return true;
}

}  // namespace dexmill
