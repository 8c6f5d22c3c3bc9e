// Parsing a command line by an option table (tools/cli/option_table.h), in
// the GNU way: `--name VALUE` or `--name=VALUE` for an option with a value
// (the value may begin with '-'), a switch alone, `--` ending the options
// (every argument after it is an operand, a file even if it begins with
// '-'; `-` is one too, standard input), and for a misspelled option the
// names it is close to (tools/cli/option_suggest.h).
#ifndef DEXMILL_TOOLS_CLI_OPTION_PARSE_H
#define DEXMILL_TOOLS_CLI_OPTION_PARSE_H

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "tools/cli/option_table.h"

namespace dexmill {
namespace cli {

// A table as the parser walks it: its options in order, what to call for
// the i-th of them and for an operand.
struct ParseView {
  const CommandText* text = nullptr;
  std::vector<const OptionDoc*> options;
  std::function<int(std::size_t i, const char* value)> apply;
  std::function<int(const char* arg, int index)> operand;  // empty: the table takes none
};

// Parses argv[1..argc) (argv[0] is the subcommand's name). `--help` or
// `-h` among the options (values and what follows `--` are not options)
// sets *help and does nothing else; else the options are applied in the
// order given. Returns kExitOk, or prints the usage error and returns its
// exit code.
int parse_view(const ParseView& v, int argc, char** argv, bool* help);

// True when argv[1..argc) names the option `name` before any `--`.
bool option_in_args(int argc, char** argv, const char* name);

template <class T>
ParseView parse_view_of(const OptionTable<T>& t, T* target) {
  ParseView v;
  v.text = t.text;
  for (const OptionSection<T>& s : t.sections)
    for (const OptionDoc& d : s.doc.options) v.options.push_back(&d);
  v.apply = [&t, target](std::size_t i, const char* value) {
    const std::pair<std::size_t, std::size_t> at = option_at(t, i);
    return t.sections[at.first].apply(target, at.second, value);
  };
  if (t.operand) v.operand = [&t, target](const char* arg, int index) { return t.operand(target, arg, index); };
  return v;
}

// argv by table t into *target; see parse_view.
template <class T>
int parse_options(const OptionTable<T>& t, int argc, char** argv, T* target, bool* help) {
  return parse_view(parse_view_of(t, target), argc, argv, help);
}

// Applies option `name` of table t with `value`, as if it had been given:
// its result, or kExitUsage when t has no such option.
int apply_named(const ParseView& v, const char* name, const char* value);
template <class T>
int apply_option(const OptionTable<T>& t, const char* name, const char* value, T* target) {
  return apply_named(parse_view_of(t, target), name, value);
}

}  // namespace cli
}  // namespace dexmill

#endif
