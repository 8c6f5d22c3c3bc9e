// The command-line parser of the option tables; see option_parse.h.
#include "tools/cli/option_parse.h"

#include <cstring>
#include <string>

#include "tools/cli/cli.h"
#include "tools/cli/option_suggest.h"

namespace dexmill {
namespace cli {
namespace {

bool is_help(const char* a) { return !std::strcmp(a, "--help") || !std::strcmp(a, "-h"); }

// An argument that is an option: it begins with '-' and is not "-" alone.
bool is_option(const char* a) { return a[0] == '-' && a[1]; }

// The option an argument names: "--stock=1,2" and "--stock" name "--stock";
// the text after '=' (a long name only) is the value. -1 for no option.
int find_option(const ParseView& v, const char* a, std::string* name, const char** inline_value) {
  const char* eq = a[1] == '-' ? std::strchr(a, '=') : nullptr;
  *name = eq ? std::string(a, static_cast<std::size_t>(eq - a)) : std::string(a);
  *inline_value = eq ? eq + 1 : nullptr;
  for (std::size_t i = 0; i < v.options.size(); ++i) {
    const OptionDoc& d = *v.options[i];
    if (*name == d.name || (d.alias && *name == d.alias)) return static_cast<int>(i);
  }
  return -1;
}

int unknown_option(const ParseView& v, const std::string& name) {
  std::vector<std::string> names{"--help"};
  for (const OptionDoc* d : v.options) {
    names.push_back(d->name);
    if (d->alias) names.push_back(d->alias);
  }
  const std::string close = suggest_option(name, names);
  const std::string mean = close.empty() ? "" : "; did you mean " + close + "?";
  const std::string hint = v.text->hint ? std::string(" (try 'dexmill ") + v.text->name + " --help')" : "";
  return fail(kExitUsage, "%sunknown option '%s'%s%s", v.text->message_prefix, name.c_str(), mean.c_str(), hint.c_str());
}

// An option whose value is written "[VALUE]" takes the next argument only
// when it reads as one: a number list (`--scallop 0,0,10,10`), not an
// option or an operand (`--scallop part.dxstock`). Null: no value.
const char* optional_value(const OptionDoc& d, const char* next) {
  if (!next || !d.value || d.value[0] != '[') return nullptr;
  const char c = next[0] == '-' || next[0] == '+' ? next[1] : next[0];
  return (c >= '0' && c <= '9') || c == '.' ? next : nullptr;
}

// The first pass: is help asked for among the options?
bool help_asked(const ParseView& v, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--")) return false;
    if (!is_option(a)) continue;
    if (is_help(a)) return true;
    std::string name;
    const char* inline_value = nullptr;
    const int k = find_option(v, a, &name, &inline_value);
    if (k >= 0 && v.options[k]->value && !inline_value &&
        (v.options[k]->value[0] != '[' || optional_value(*v.options[k], i + 1 < argc ? argv[i + 1] : nullptr)))
      ++i;  // its value
  }
  return false;
}

}  // namespace

int parse_view(const ParseView& v, int argc, char** argv, bool* help) {
  *help = help_asked(v, argc, argv);
  if (*help) return kExitOk;
  bool options_done = false;
  int operands = 0;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!options_done && !std::strcmp(a, "--")) {
      options_done = true;
      continue;
    }
    if (options_done || !is_option(a)) {
      if (!v.operand) return fail(kExitUsage, "%sunexpected argument '%s'", v.text->message_prefix, a);
      if (const int code = v.operand(a, operands++)) return code;
      continue;
    }
    std::string name;
    const char* value = nullptr;
    const int k = find_option(v, a, &name, &value);
    if (k < 0) return unknown_option(v, name);
    const OptionDoc& d = *v.options[k];
    if (!d.value && value) return fail(kExitUsage, "%s takes no value", name.c_str());
    if (d.value && d.value[0] == '[' && !value) {
      value = optional_value(d, i + 1 < argc ? argv[i + 1] : nullptr);
      if (value) ++i;
    } else if (d.value && !value) {
      if (i + 1 >= argc) return fail(kExitUsage, "%s needs %s", name.c_str(), d.needs ? d.needs : "a value");
      value = argv[++i];
    }
    if (const int code = v.apply(static_cast<std::size_t>(k), value)) return code;
  }
  return kExitOk;
}

bool option_in_args(int argc, char** argv, const char* name) {
  for (int i = 1; i < argc && std::strcmp(argv[i], "--"); ++i)
    if (!std::strcmp(argv[i], name)) return true;
  return false;
}

int apply_named(const ParseView& v, const char* name, const char* value) {
  for (std::size_t i = 0; i < v.options.size(); ++i)
    if (!std::strcmp(v.options[i]->name, name)) return v.apply(i, value);
  return fail(kExitUsage, "internal: no option %s", name);
}

}  // namespace cli
}  // namespace dexmill
