// `dexmill bench` (issue 3): not yet built.
#include "tools/cli.h"

namespace dexmill {
namespace cli {
int cmd_bench(int, char**) { return fail(kExitUsage, "'bench' is not built yet"); }
}  // namespace cli
}  // namespace dexmill
