// The four built-in design parts, one file each (builtin_panel.cpp,
// builtin_smiley.cpp, builtin_freeform.cpp, builtin_tsuba.cpp), listed by
// builtin.cpp in the order of the paper's §3.
#ifndef DEXMILL_CORE_DESIGN_BUILTIN_PARTS_H
#define DEXMILL_CORE_DESIGN_BUILTIN_PARTS_H

#include "core/design/builtin.h"

namespace dexmill {

extern const BuiltinDesign kBuiltinPanel;
extern const BuiltinDesign kBuiltinSmiley;
extern const BuiltinDesign kBuiltinFreeform;
extern const BuiltinDesign kBuiltinTsuba;

}  // namespace dexmill

#endif
