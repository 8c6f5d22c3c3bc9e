// `dexmill path` (issue 4): not yet built.
#include "tools/cli.h"

namespace dexmill {
namespace cli {
int cmd_path(int, char**) { return fail(kExitUsage, "'path' is not built yet"); }
}  // namespace cli
}  // namespace dexmill
