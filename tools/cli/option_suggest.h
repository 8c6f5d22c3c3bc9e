// "Did you mean --strict?": the option names close to a misspelled one.
#ifndef DEXMILL_TOOLS_CLI_OPTION_SUGGEST_H
#define DEXMILL_TOOLS_CLI_OPTION_SUGGEST_H

#include <cstddef>
#include <string>
#include <vector>

namespace dexmill {
namespace cli {

// The edits that turn a into b: a character inserted, deleted or
// replaced, or two neighbours swapped ("stirct" -> "strict" is one).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The names closest to `typed`, "--a" or "--a or --b", when they are close:
// at most 1 edit for a name of up to 4 letters (not counting its dashes),
// 2 up to 8, 3 beyond, and fewer than `typed` has letters; names of one
// letter ("-q") are never offered. Empty when none is that close.
std::string suggest_option(const std::string& typed, const std::vector<std::string>& names);

}  // namespace cli
}  // namespace dexmill

#endif
