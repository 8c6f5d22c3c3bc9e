// The toolpath of the backplot (display/overlay/backplot.h) from the
// program's records: straight pieces, arcs as chords of sagitta at most
// kBackplotSagittaNm (a tenth of the finest pitch a frame shows them at is
// far more than enough: this is a picture, not a cut). `dexmill run
// --path-overlay` (tools/run/run_path.h) and the embedding API's views
// (dm_view_set_path) build their paths with it; here beside the API, the
// layer of display/ that reads records (tests/check_layers.sh). Integer
// only, no heap.
#ifndef DEXMILL_DISPLAY_API_PATH_PIECES_H
#define DEXMILL_DISPLAY_API_PATH_PIECES_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "display/overlay/backplot.h"

namespace dexmill {

constexpr int64_t kBackplotSagittaNm = 10000;  // 0.01 mm

// Pieces a record adds to the path: 1 for a straight move, its chords for
// an arc, 0 for anything else.
uint32_t path_pieces(const CanonRecord& r, int64_t sagitta_nm = kBackplotSagittaNm);

// r's pieces into segs[*n, cap) (*n advanced); the pieces that did not fit.
uint32_t path_append(const CanonRecord& r, PathSegment* segs, uint32_t* n, uint32_t cap,
                     int64_t sagitta_nm = kBackplotSagittaNm);

}  // namespace dexmill

#endif
