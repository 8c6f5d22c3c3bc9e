// The help and the man page's option lists; see option_help.h.
#include "tools/cli/option_help.h"

namespace dexmill {
namespace cli {
namespace {

constexpr std::size_t kHelpColumn = 29;  // where an option's help begins
constexpr std::size_t kHelpWidth = 79;

// The words of `text` from column `col` on, wrapped at kHelpWidth onto
// lines indented to kHelpColumn.
void put_wrapped(const char* text, std::size_t col, std::FILE* f) {
  const std::string s = text;
  std::size_t pos = 0;
  bool first = true;
  while (pos < s.size()) {
    const std::size_t end = s.find(' ', pos);
    const std::string word = s.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    pos = end == std::string::npos ? s.size() : end + 1;
    if (word.empty()) continue;
    if (!first && col + 1 + word.size() > kHelpWidth) {
      std::fprintf(f, "\n%*s", static_cast<int>(kHelpColumn), "");
      col = kHelpColumn;
    } else if (!first) {
      std::fputc(' ', f);
      ++col;
    }
    std::fputs(word.c_str(), f);
    col += word.size();
    first = false;
  }
  std::fputc('\n', f);
}

void put_option(const OptionDoc& d, std::FILE* f) {
  const std::string label = "  " + option_label(d);
  std::fputs(label.c_str(), f);
  const std::size_t col = label.size() + 2 <= kHelpColumn ? kHelpColumn : label.size() + 2;
  std::fprintf(f, "%*s", static_cast<int>(col - label.size()), "");
  put_wrapped(d.help, col, f);
}

std::string roff_bold(const char* s) { return "\\fB" + roff_text(s) + "\\fR"; }

}  // namespace

std::string option_label(const OptionDoc& d) {
  std::string s = d.alias ? std::string(d.alias) + ", " : "";
  s += d.name;
  if (d.value) s += std::string(" ") + d.value;
  return s;
}

void print_help(const CommandDoc& d, std::FILE* f) {
  std::fputs(d.text->usage, f);
  bool first = true;
  for (const SectionDoc& s : d.sections) {
    if (s.see) {
      std::fprintf(f, "\n%s:\n  every option of dexmill %s, as dexmill %s --help lists them\n",
                   s.title ? s.title : "Also", s.see, s.see);
      continue;
    }
    if (s.title) std::fprintf(f, "\n%s:\n", s.title);
    else if (first) std::fputc('\n', f);
    for (const OptionDoc& o : s.options) put_option(o, f);
    first = false;
  }
  if (d.text->epilogue) std::fprintf(f, "\n%s", d.text->epilogue);
}

std::string roff_text(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '\\') r += "\\e";
    else if (c == '-') r += "\\-";
    else r += c;
  }
  if (!r.empty() && (r[0] == '.' || r[0] == '\'')) r = "\\&" + r;
  return r;
}

void print_man_options(const std::vector<CommandDoc>& docs, std::FILE* f) {
  for (const CommandDoc& d : docs) {
    std::fprintf(f, ".SS \"dexmill %s\"\n", d.text->name);
    for (const SectionDoc& s : d.sections) {
      if (s.see) {
        std::fprintf(f, ".PP\n%s%severy option of \\fBdexmill %s\\fR.\n", s.title ? roff_text(s.title).c_str() : "",
                     s.title ? ": " : "", s.see);
        continue;
      }
      if (s.title) std::fprintf(f, ".PP\n%s:\n", roff_text(s.title).c_str());
      for (const OptionDoc& o : s.options) {
        std::string head = o.alias ? roff_bold(o.alias) + ", " : "";
        head += roff_bold(o.name);
        if (o.value) head += " \\fI" + roff_text(o.value) + "\\fR";
        std::fprintf(f, ".TP\n%s\n%s\n", head.c_str(), roff_text(o.help).c_str());
      }
    }
  }
}

}  // namespace cli
}  // namespace dexmill
