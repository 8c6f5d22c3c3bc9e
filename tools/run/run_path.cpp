#include "tools/run/run_path.h"

namespace dexmill {
namespace cli {

void append_path(const CanonRecord& r, std::vector<PathSegment>* path, int64_t sagitta_nm, size_t max_pieces) {
  if (path->size() >= max_pieces) return;
  const size_t room = max_pieces - path->size();
  const uint32_t want = path_pieces(r, sagitta_nm);
  if (want == 0) return;
  uint32_t n = static_cast<uint32_t>(path->size());
  const size_t cap = path->size() + (want < room ? want : room);
  path->resize(cap);
  (void)path_append(r, path->data(), &n, static_cast<uint32_t>(cap), sagitta_nm);
  path->resize(n);
}

}  // namespace cli
}  // namespace dexmill
