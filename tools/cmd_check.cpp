// `dexmill check` (issue 4): not yet built.
#include "tools/cli.h"

namespace dexmill {
namespace cli {
int cmd_check(int, char**) { return fail(kExitUsage, "'check' is not built yet"); }
}  // namespace cli
}  // namespace dexmill
