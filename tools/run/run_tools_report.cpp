// The run's tools reported; see run_tools_report.h.
#include "tools/run/run_tools_report.h"

#include <cstdio>

#include "core/tool/spec.h"

namespace dexmill {
namespace cli {
namespace {

std::string spec_of(const Tool& t) {
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  return spec;
}

std::string tool_name(int32_t number) {
  return number == kSpindleToolNumber ? std::string("the tool before any M6") : "T" + std::to_string(number);
}

// "A", "A and B", "A, B and C".
std::string listed(const std::vector<std::string>& names) {
  std::string o;
  for (size_t k = 0; k < names.size(); ++k)
    o += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return o;
}

// Comments that disagreed, when it mattered: the tool is not a comment's.
void doubts(const ProgramScan& s, const ToolChoice& c, RunMessages* msgs) {
  const CommentTools::Doubt& a = c.comments().ambiguous();
  if (a.count) {
    ToolSource src = ToolSource::kDefault;
    if (a.number == kSpindleToolNumber) (void)c.initial(&src);
    else src = c.source(a.number);
    const bool used = a.number == kSpindleToolNumber ? s.cuts[0] : true;
    if (used && src != ToolSource::kComment)
      msgs->warning_text(a.line_a, 1, "the comments on lines " + std::to_string(a.line_a) + " and " +
                                          std::to_string(a.line_b) + " describe different tools for " +
                                          tool_name(a.number) + "; neither is used");
  }
  const CommentTools::Doubt& f = c.comments().conflicts();
  if (f.count) {
    const CommentTool* ct = c.comments().find(f.number);
    if (ct && c.source(f.number) == ToolSource::kComment)
      msgs->warning_text(f.line_b, 1, "the comment on line " + std::to_string(f.line_b) + " describes " +
                                          tool_name(f.number) + " otherwise than line " + std::to_string(f.line_a) +
                                          " did; " + spec_of(ct->tool) + " from line " + std::to_string(ct->line) +
                                          " is used");
  }
}

}  // namespace

void report_tools(const ProgramScan& s, const ToolChoice& c, const std::string& file, RunMessages* msgs,
                  RunReport* rep) {
  std::vector<std::string> guessed;
  uint32_t guess_line = 0;
  std::string guess_spec;
  for (int k = s.cuts[0] ? 0 : 1; k < s.ntools; ++k) {
    const int32_t number = k == 0 ? kSpindleToolNumber : s.numbers[k];
    const CommentTool* ct = nullptr;
    ToolSource src = ToolSource::kDefault;
    if (k == 0) (void)c.initial(&src, &ct);
    else src = c.source(number, &ct);
    const std::string spec = spec_of(s.tools[k]);
    rep->tools_used.push_back(ReportToolUse{number, spec, tool_source_name(src), ct ? ct->line : 0,
                                            ct ? tool_comment_form_name(ct->form) : "", s.tools[k].length_nm,
                                            s.first_lines[k], s.last_lines[k]});
    if (ct && msgs->printing())
      std::fprintf(stderr, "%s:%u: note: %s %s from the comment on line %u (%s)\n", file.c_str(), ct->line,
                   k == 0 ? "the first tool (before any M6)" : ("tool T" + std::to_string(number)).c_str(), spec.c_str(),
                   ct->line, tool_comment_form_name(ct->form));
    if (src == ToolSource::kDefault && s.cuts[k]) {
      guessed.push_back(tool_name(number));
      if (!guess_line || s.first_lines[k] < guess_line) guess_line = s.first_lines[k];
      guess_spec = spec;
    }
  }
  if (!guessed.empty()) {
    const bool one = guessed.size() == 1;
    msgs->warning_text(guess_line ? guess_line : 1, 1,
                       listed(guessed) + (one ? " is" : " are") + " cut as " + guess_spec +
                           ", a guess: no --tool, --tools table or tool comment of the program gives " +
                           (one ? "it" : "them") + " (give one with --tool SPEC or --tools FILE)");
  }
  doubts(s, c, msgs);
}

}  // namespace cli
}  // namespace dexmill
