#include "tools/run/run_path.h"

#include "core/canon/arc_chords.h"

namespace dexmill {
namespace cli {

uint32_t path_pieces(const CanonRecord& r, int64_t sagitta_nm) {
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) return 1;
  if (r.kind != CanonKind::kArc) return 0;
  ArcChords chords;
  chords.init(r, sagitta_nm);
  return chords.count();
}

void append_path(const CanonRecord& r, std::vector<PathSegment>* path, int64_t sagitta_nm, size_t max_pieces) {
  if (path->size() >= max_pieces) return;
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) {
    path->push_back(PathSegment{r.start, r.end, r.kind == CanonKind::kFeed ? PathKind::kFeed : PathKind::kRapid});
    return;
  }
  if (r.kind != CanonKind::kArc) return;
  ArcChords chords;
  chords.init(r, sagitta_nm);
  PointNm from = r.start, to;
  while (path->size() < max_pieces && chords.next(&to)) {
    path->push_back(PathSegment{from, to, PathKind::kFeed});
    from = to;
  }
}

}  // namespace cli
}  // namespace dexmill
