// dexmill: entry point; dispatches to the subcommands of ../shared/CLI.md.
#include "tools/cli.h"

int main(int argc, char** argv) { return dexmill::cli::main(argc, argv); }
