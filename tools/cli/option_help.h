// What the option tables print: a subcommand's `--help`, and the option
// lists of the man page in roff (`dexmill --man-options`, which the man
// page's build splices into tools/man/dexmill.1).
#ifndef DEXMILL_TOOLS_CLI_OPTION_HELP_H
#define DEXMILL_TOOLS_CLI_OPTION_HELP_H

#include <cstdio>
#include <string>
#include <vector>

#include "tools/cli/option_table.h"

namespace dexmill {
namespace cli {

// "-q, --quiet" or "--stock X0,Y0,Z0,X1,Y1,Z1": how the help shows an option.
std::string option_label(const OptionDoc& d);

// The usage text, every section (an option a line or more: the label, the
// help wrapped beside it; an included table as a reference to its
// subcommand's help), then the epilogue.
void print_help(const CommandDoc& d, std::FILE* f);

// man(7): `.SS "dexmill NAME"` for each subcommand, a `.TP` for each of its
// options, a paragraph for each section's title and each included table.
void print_man_options(const std::vector<CommandDoc>& docs, std::FILE* f);

// Text for roff: backslashes and dashes escaped, a line kept from being
// read as a request.
std::string roff_text(const std::string& s);

}  // namespace cli
}  // namespace dexmill

#endif
