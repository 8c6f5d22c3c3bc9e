// The built-in demo's program as the CLI holds it: core/cam/demo_program.h's
// text in a string (`dexmill run --demo pocket`, `make run`).
#ifndef DEXMILL_TOOLS_RUN_DEMO_PROGRAM_H
#define DEXMILL_TOOLS_RUN_DEMO_PROGRAM_H

#include <string>

#include "core/cam/demo_program.h"

namespace dexmill {
namespace cli {

// The program text (about 7000 lines).
inline std::string demo_program() {
  std::string text(demo_program_write(nullptr, 0), '\0');
  (void)demo_program_write(&text[0], text.size() + 1);  // C++11: the NUL after the last byte is the string's
  return text;
}

}  // namespace cli
}  // namespace dexmill

#endif
