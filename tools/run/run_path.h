// The toolpath of `dexmill run --path-overlay` (display/overlay/backplot.h): the
// program's moves as straight pieces, arcs as chords of sagitta at most
// kBackplotSagittaNm (a tenth of the finest pitch a frame shows them at is
// far more than enough: this is a picture, not a cut).
#ifndef DEXMILL_TOOLS_RUN_RUN_PATH_H
#define DEXMILL_TOOLS_RUN_RUN_PATH_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/canon/canon.h"
#include "display/overlay/backplot.h"

namespace dexmill {
namespace cli {

constexpr int64_t kBackplotSagittaNm = 10000;  // 0.01 mm

// Pieces a record adds to the path: 1 for a straight move, its chords for
// an arc, 0 for anything else. The cut pass counts with it how much of the
// path is done; the scan pass builds the path with append_path, which stops
// at max_pieces in all (the fuzz target's bound). Both with chords of
// sagitta_nm (the fuzz target's are coarser on coarse grids).
uint32_t path_pieces(const CanonRecord& r, int64_t sagitta_nm = kBackplotSagittaNm);
void append_path(const CanonRecord& r, std::vector<PathSegment>* path, int64_t sagitta_nm = kBackplotSagittaNm,
                 size_t max_pieces = SIZE_MAX);

}  // namespace cli
}  // namespace dexmill

#endif
