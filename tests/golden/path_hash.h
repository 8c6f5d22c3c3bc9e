// The golden sections' trace of an interpreter's records (path, flow,
// motion): each record's kind and line, with_state also its feed, spindle,
// coolant and tool length offset, then its end point or, for an arc, every
// chord point (1 um sagitta).
#ifndef DEXMILL_TESTS_GOLDEN_PATH_HASH_H
#define DEXMILL_TESTS_GOLDEN_PATH_HASH_H

#include <stdint.h>

#include "core/math/hash.h"
#include "core/canon/arc_chords.h"
#include "core/canon/canon.h"

namespace golden {

class PathHash : public dexmill::CanonSink {
 public:
  explicit PathHash(bool with_state = false) : with_state_(with_state) {}
  void emit(const dexmill::CanonRecord& r) override {
    ++records;
    h.uint_le(static_cast<uint8_t>(r.kind), 1);
    h.uint_le(r.line, 4);
    if (with_state_) {
      h.uint_le(static_cast<uint64_t>(r.feed_nm_per_min), 8);
      h.uint_le(static_cast<uint64_t>(r.spindle_rpm), 4);
      h.uint_le(r.coolant, 1);
      h.uint_le(static_cast<uint64_t>(r.tool_length_offset_nm), 8);
    }
    if (r.kind == dexmill::CanonKind::kArc) {
      dexmill::ArcChords c;
      c.init(r, 1000);
      dexmill::PointNm p;
      while (c.next(&p)) point(p);
    } else {
      point(r.end);
    }
  }
  void point(const dexmill::PointNm& p) {
    h.uint_le(static_cast<uint64_t>(p.x_nm), 8);
    h.uint_le(static_cast<uint64_t>(p.y_nm), 8);
    h.uint_le(static_cast<uint64_t>(p.z_nm), 8);
    ++points;
  }
  dexmill::Hash64 h;
  int64_t records = 0, points = 0;

 private:
  bool with_state_;
};

// Runs `program` with parameters and o-words (golden_mill.cpp), into sink;
// its o-word blocks run in *blocks when not null. Returns the errors.
int trace_with_flow(const char* program, PathHash* sink, int64_t* blocks);

}  // namespace golden

#endif
