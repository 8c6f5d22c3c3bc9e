// dexmill: entry point; dispatches to the subcommands (tools/cli.h).
#include "tools/cli.h"

int main(int argc, char** argv) { return dexmill::cli::main(argc, argv); }
