// The backplot's pieces of a record; see path_pieces.h.
#include "display/api/path_pieces.h"

#include "core/canon/arc_chords.h"

namespace dexmill {

uint32_t path_pieces(const CanonRecord& r, int64_t sagitta_nm) {
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) return 1;
  if (r.kind != CanonKind::kArc) return 0;
  ArcChords chords;
  chords.init(r, sagitta_nm);
  return chords.count();
}

uint32_t path_append(const CanonRecord& r, PathSegment* segs, uint32_t* n, uint32_t cap, int64_t sagitta_nm) {
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) {
    if (*n >= cap) return 1;
    segs[(*n)++] = PathSegment{r.start, r.end, r.kind == CanonKind::kFeed ? PathKind::kFeed : PathKind::kRapid};
    return 0;
  }
  if (r.kind != CanonKind::kArc) return 0;
  ArcChords chords;
  chords.init(r, sagitta_nm);
  const uint32_t all = chords.count();
  PointNm from = r.start, to;
  uint32_t put = 0;
  while (*n < cap && chords.next(&to)) {
    segs[(*n)++] = PathSegment{from, to, PathKind::kFeed};
    from = to;
    ++put;
  }
  return all - put;
}

}  // namespace dexmill
