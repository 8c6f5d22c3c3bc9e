// The toolpath of `dexmill run --path-overlay` in a growing list: the
// pieces are display/api/path_pieces.h's (the embedding API's views
// build theirs with the same code).
#ifndef DEXMILL_TOOLS_RUN_RUN_PATH_H
#define DEXMILL_TOOLS_RUN_RUN_PATH_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/canon/canon.h"
#include "display/api/path_pieces.h"

namespace dexmill {
namespace cli {

// The cut pass counts how much of the path is done with path_pieces; the
// scan pass builds the path with append_path, which stops at max_pieces in
// all (the fuzz target's bound). Both with chords of sagitta_nm (the fuzz
// target's are coarser on coarse grids).
void append_path(const CanonRecord& r, std::vector<PathSegment>* path, int64_t sagitta_nm = kBackplotSagittaNm,
                 size_t max_pieces = SIZE_MAX);

}  // namespace cli
}  // namespace dexmill

#endif
