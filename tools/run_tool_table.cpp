#include "tools/run_tool_table.h"

#include <cstdio>

#include "tools/cli.h"

namespace dexmill {
namespace cli {

int load_tool_table(const std::string& path, bool inch, ToolTableFile* t) {
  const ToolTableFile::Load l = t->load(path.c_str(), inch);
  if (l == ToolTableFile::Load::kIoError) return fail(kExitIo, "%s", t->message().c_str());
  if (l == ToolTableFile::Load::kInputError) {
    std::fprintf(stderr, "%s\n", t->message().c_str());
    return kExitInput;
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
