// Option tables: a subcommand's options as data, each one's name, the
// placeholder of its value, its help text and what it does, from which
// its parsing (tools/cli/option_parse.h), its `--help` and the man page's
// option list (tools/cli/option_help.h) are made, so that no list of names is
// kept in step by hand.
//
// A table is a list of sections. A section is either a list of options
// over one part of the subcommand's settings (`section`: the reading
// options, which path, check and run share, are one list that each of them
// includes), or another subcommand's whole table (`include`: parsed here,
// listed by that one's help, which this one's refers to).
#ifndef DEXMILL_TOOLS_CLI_OPTION_TABLE_H
#define DEXMILL_TOOLS_CLI_OPTION_TABLE_H

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace dexmill {
namespace cli {

// An option as the help, the man page and the parser see it.
struct OptionDoc {
  const char* name = nullptr;   // "--stock", or a short name with no long one ("-o")
  const char* value = nullptr;  // the value's placeholder ("MM"); null: a switch, which takes none
  const char* help = "";        // one paragraph; the help and the man page wrap it
  const char* alias = nullptr;  // a short name ("-q"), or null
  const char* needs = nullptr;  // what "NAME needs ..." says of a missing value; null: "a value"
};

// One entry of an option list over settings of type Part.
template <class Part>
struct Option {
  const char* name;
  const char* value;
  const char* help;
  // What the option does to the settings: kExitOk, or the usage error
  // printed and kExitUsage. `value` is null for a switch.
  int (*apply)(Part* part, const char* value);
  const char* alias = nullptr;
  const char* needs = nullptr;
};

template <class Part>
struct OptionList {
  const Option<Part>* options;
  std::size_t count;
};
template <class Part, std::size_t N>
OptionList<Part> option_list(const Option<Part> (&a)[N]) {
  return OptionList<Part>{a, N};
}

// The words of a subcommand's help around its option list.
struct CommandText {
  const char* name;            // "run"
  const char* usage;           // before the options: the synopsis and what the subcommand does
  const char* epilogue;        // after them (exit status ...), or null
  // An unknown option is "unknown option '--x'", "; did you mean --y?"
  // when one is close, then " (try 'dexmill NAME --help')". bench's
  // messages, older than its table, begin "bench: " and give no hint.
  const char* message_prefix = "";
  bool hint = true;
};

struct SectionDoc {
  const char* title = nullptr;  // null: untitled (the subcommand's own)
  const char* see = nullptr;    // an included subcommand's name: its help lists these, this one's refers to it
  std::vector<OptionDoc> options;
};

// What the help and the man page print of a subcommand.
struct CommandDoc {
  const CommandText* text = nullptr;
  std::vector<SectionDoc> sections;
};

template <class T>
struct OptionSection {
  SectionDoc doc;
  std::function<int(T* target, std::size_t k, const char* value)> apply;  // doc.options[k]'s
};

template <class T>
struct OptionTable {
  const CommandText* text = nullptr;
  std::vector<OptionSection<T>> sections;
  // An argument that is no option (index: 0 for the first of them), or
  // one after `--`: kExitOk, or the usage error printed and kExitUsage.
  int (*operand)(T* target, const char* arg, int index) = nullptr;
};

// A section of the options of `list`, which work on part(*target).
template <class T, class Part, class PartOf>
OptionSection<T> section(const char* title, OptionList<Part> list, PartOf part) {
  OptionSection<T> s;
  s.doc.title = title;
  for (std::size_t k = 0; k < list.count; ++k) {
    const Option<Part>& o = list.options[k];
    s.doc.options.push_back(OptionDoc{o.name, o.value, o.help, o.alias, o.needs});
  }
  s.apply = [list, part](T* t, std::size_t k, const char* v) { return list.options[k].apply(&part(*t), v); };
  return s;
}

// Option i of table t counted across its sections: (section, index in it).
template <class T>
std::pair<std::size_t, std::size_t> option_at(const OptionTable<T>& t, std::size_t i) {
  std::size_t s = 0;
  while (i >= t.sections[s].doc.options.size()) i -= t.sections[s++].doc.options.size();
  return {s, i};
}

// Another subcommand's whole table (which must outlive this one), working
// on part(*target); `title` heads the reference to its help.
template <class T, class Part, class PartOf>
OptionSection<T> include(const char* title, const OptionTable<Part>& table, PartOf part) {
  OptionSection<T> s;
  s.doc.title = title;
  s.doc.see = table.text->name;
  for (const OptionSection<Part>& in : table.sections)
    for (const OptionDoc& d : in.doc.options) s.doc.options.push_back(d);
  s.apply = [&table, part](T* t, std::size_t k, const char* v) {
    const std::pair<std::size_t, std::size_t> at = option_at(table, k);
    return table.sections[at.first].apply(&part(*t), at.second, v);
  };
  return s;
}

template <class T>
CommandDoc command_doc(const OptionTable<T>& t) {
  CommandDoc d;
  d.text = t.text;
  for (const OptionSection<T>& s : t.sections) d.sections.push_back(s.doc);
  return d;
}

}  // namespace cli
}  // namespace dexmill

#endif
