// The embedding API's built-in demo (dexmill.h dm_demo_program,
// dm_demo_text): core/cam/demo_program.h's text and job, as `dexmill run
// --demo pocket` has them.
#include "core/cam/demo_program.h"
#include "display/api/dexmill.h"

extern "C" {

size_t dm_demo_program(char* buf, size_t n) { return dexmill::demo_program_write(buf, buf ? n : 0); }

const char* dm_demo_text(int32_t which) {
  switch (which) {
    case DM_DEMO_STOCK: return dexmill::demo_stock();
    case DM_DEMO_TOOL_TABLE: return dexmill::demo_tool_table();
    case DM_DEMO_MATERIAL: return dexmill::demo_material();
    default: return nullptr;
  }
}

}  // extern "C"
