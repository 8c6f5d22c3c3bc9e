#include "tools/run_path.h"

#include "core/motion/arc_chords.h"

namespace dexmill {
namespace cli {

uint32_t path_pieces(const CanonRecord& r) {
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) return 1;
  if (r.kind != CanonKind::kArc) return 0;
  ArcChords chords;
  chords.init(r, kBackplotSagittaNm);
  return chords.count();
}

void append_path(const CanonRecord& r, std::vector<PathSegment>* path) {
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) {
    path->push_back(PathSegment{r.start, r.end, r.kind == CanonKind::kFeed ? PathKind::kFeed : PathKind::kRapid});
    return;
  }
  if (r.kind != CanonKind::kArc) return;
  ArcChords chords;
  chords.init(r, kBackplotSagittaNm);
  PointNm from = r.start, to;
  while (chords.next(&to)) {
    path->push_back(PathSegment{from, to, PathKind::kFeed});
    from = to;
  }
}

}  // namespace cli
}  // namespace dexmill
