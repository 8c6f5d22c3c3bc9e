// Safety checks; see safety.h.
#include "core/safety/safety.h"

#include "core/grid/removals.h"

#include "core/math/fixed.h"
#include "core/canon/arc_chords.h"

namespace dexmill {

const char* safety_kind_name(SafetyKind k) {
  switch (k) {
    case SafetyKind::kRapidIntoStock: return "rapid";
    case SafetyKind::kSpindleStopped: return "spindle_stopped";
    case SafetyKind::kBelowStock: return "below_stock";
    case SafetyKind::kIntoTable: return "table";
    case SafetyKind::kShank: return "shank";
    case SafetyKind::kHolder: return "holder";
    case SafetyKind::kFixture: return "fixture";
    case SafetyKind::kPlunge: return "plunge";
  }
  return "";
}

namespace {

// The event of (line, kind): one this call began or the last before them
// (a line's removals go on into the next record with its end cap), else a
// new one (counted; null when the list is full).
SafetyEvent* event_for(SafetyWatch* w, size_t first_of_call, uint32_t line, SafetyKind kind, bool* added) {
  for (size_t k = first_of_call > 0 ? first_of_call - 1 : 0; k < w->nevents; ++k)
    if (w->events[k].line == line && w->events[k].kind == kind) return &w->events[k];
  // Past the list: counted once a (line, kind), as a kept one is (a line's
  // columns come in one record, or two with its end cap).
  const size_t ki = static_cast<size_t>(kind);
  if (w->nevents >= kSafetyEventsMax && w->unkept_line[ki] == line) return nullptr;
  ++w->total;
  *added = true;
  if (w->nevents >= kSafetyEventsMax) {
    w->unkept_line[ki] = line;
    return nullptr;
  }
  SafetyEvent* e = &w->events[w->nevents++];
  *e = SafetyEvent{};
  e->line = line;
  e->kind = kind;
  return e;
}

// The lowest point of the tool tip along a motion record: an end, or for
// an arc whose plane is upright (G18, G19) the lowest of its chord points.
PointNm lowest_tip(const CanonRecord& r) {
  PointNm low = r.start.z_nm <= r.end.z_nm ? r.start : r.end;
  if (r.kind != CanonKind::kArc || r.arc.plane == Plane::kXY) return low;
  ArcChords chords;
  chords.init(r, kArcChordSagittaNm);
  PointNm p;
  while (chords.next(&p))
    if (p.z_nm < low.z_nm) low = p;
  return low;
}

void check_below(SafetyWatch* w, size_t first, const CanonRecord& r, SafetyKind kind, int64_t limit_nm, bool* added) {
  const PointNm low = lowest_tip(r);
  if (low.z_nm >= limit_nm) return;
  // A move that only rises from where the last one went down is the way
  // out, not a second offence.
  if (low.z_nm == r.start.z_nm && r.end.z_nm > r.start.z_nm && r.kind != CanonKind::kArc) return;
  SafetyEvent* e = event_for(w, first, r.line, kind, added);
  if (!e) return;
  if (limit_nm - low.z_nm > e->depth_nm) {
    e->depth_nm = limit_nm - low.z_nm;
    e->at = low;
  }
}

// Adds one column's overlap to event e (what it marks is the deepest).
void add_overlap(SafetyEvent* e, int64_t depth_nm, int64_t lsb_nm, PointNm at) {
  ++e->columns;
  e->removed_lsb += static_cast<uint64_t>(depth_nm / lsb_nm);
  if (e->columns == 1 || depth_nm > e->depth_nm) {
    e->depth_nm = depth_nm;
    e->at = at;
  }
}

// Pieces of a record the contact checks take at once: their per-column
// minimum is exact; a record with more (a long helix) is taken in batches,
// and a column near two batches counts in both.
constexpr int kBatchPieces = 16;  // about 2 KB of stack (a panel's is small)
struct Batch {
  int n = 0;
  BodyPiece piece[kBatchPieces];
  int64_t x_lo[kBatchPieces], x_hi[kBatchPieces], y_lo[kBatchPieces], y_hi[kBatchPieces];
  int64_t zmin = INT64_MAX;
  int64_t zlow = INT64_MAX;  // piece_lowest_tip_nm of them all
  int64_t bx0 = INT64_MAX, bx1 = INT64_MIN, by0 = INT64_MAX, by1 = INT64_MIN;  // all, widened by the reach
  int64_t reach = 0;
};

bool fill_batch(BodyPieces* pieces, int64_t reach, Batch* b) {
  *b = Batch{};
  b->reach = reach;
  BodyPiece p;
  while (b->n < kBatchPieces && pieces->next(&p)) {
    const int k = b->n++;
    b->piece[k] = p;
    b->x_lo[k] = min_of(p.a.x_nm, p.b.x_nm) - reach;
    b->x_hi[k] = max_of(p.a.x_nm, p.b.x_nm) + reach;
    b->y_lo[k] = min_of(p.a.y_nm, p.b.y_nm) - reach;
    b->y_hi[k] = max_of(p.a.y_nm, p.b.y_nm) + reach;
    b->zmin = min_of(b->zmin, min_of(p.a.z_nm, p.b.z_nm));
    b->zlow = min_of(b->zlow, piece_lowest_tip_nm(p));
    b->bx0 = min_of(b->bx0, b->x_lo[k]);
    b->bx1 = max_of(b->bx1, b->x_hi[k]);
    b->by0 = min_of(b->by0, b->y_lo[k]);
    b->by1 = max_of(b->by1, b->y_hi[k]);
  }
  return b->n > 0;
}

// The columns of g whose axes lie in [x0, x1] x [y0, y1], clipped.
template <class H>
GridRect columns_in(const DexelGrid<H>& g, int64_t x0, int64_t x1, int64_t y0, int64_t y1) {
  const int64_t i0 = div_ceil(x0 - g.x0_nm, g.pitch_nm), i1 = div_floor(x1 - g.x0_nm, g.pitch_nm) + 1;
  const int64_t j0 = div_ceil(y0 - g.y0_nm, g.pitch_nm), j1 = div_floor(y1 - g.y0_nm, g.pitch_nm) + 1;
  return GridRect{static_cast<int32_t>(clamp<int64_t>(i0, 0, g.nx)), static_cast<int32_t>(clamp<int64_t>(j0, 0, g.ny)),
                  static_cast<int32_t>(clamp<int64_t>(i1, 0, g.nx)), static_cast<int32_t>(clamp<int64_t>(j1, 0, g.ny))};
}

// Calls fn(batch, rect) for each batch of r's pieces whose reach (widened
// by `reach`) meets g's columns, rect those columns; fn returns false to stop.
template <class H, class Fn>
void each_batch(const DexelGrid<H>& g, const CanonRecord& r, int64_t reach, Fn fn) {
  BodyPieces pieces;
  pieces.init(r);
  Batch b;
  while (fill_batch(&pieces, reach, &b)) {
    const GridRect rect = columns_in(g, b.bx0, b.bx1, b.by0, b.by1);
    if (!rect.empty() && !fn(b, rect)) return;
  }
}

// The body's lowest point over the batch at a column, and its part.
int64_t body_lowest(const ToolBody& body, const Batch& b, int64_t x, int64_t y, BodyPart* part) {
  int64_t best = kBodyNever;
  for (int k = 0; k < b.n; ++k) {
    if (x < b.x_lo[k] || x > b.x_hi[k] || y < b.y_lo[k] || y > b.y_hi[k]) continue;
    for (int q = 0; q < body.nrings; ++q) {
      const int64_t z = ring_lowest_nm(body.ring[q], b.piece[k], x, y);
      if (z < best) {
        best = z;
        *part = body.ring[q].part;
      }
    }
  }
  return best;
}

// Per ring of the body over a batch: the columns in its reach (their axes
// within r1 of a piece's box) and the tops (LSB) at or under which it
// meets nothing (the batch's lowest tip plus its h0): a column outside
// every ring's reach, or under the floor of each whose reach holds it,
// has no overlap, so the fast look does not work it out.
struct RingFloors {
  int n = 0;
  GridRect rect[kBodyRingsMax];
  int64_t floor_lsb[kBodyRingsMax];
};

template <class H>
void ring_floors(const DexelGrid<H>& g, const ToolBody& body, const Batch& b, RingFloors* out) {
  out->n = body.nrings;
  for (int q = 0; q < body.nrings; ++q) {
    const int64_t cut = b.reach - body.ring[q].r1_nm;  // the batch box is widened by the widest ring
    out->rect[q] = columns_in(g, b.bx0 + cut, b.bx1 - cut, b.by0 + cut, b.by1 - cut);
    out->floor_lsb[q] = div_floor(b.zlow + body.ring[q].h0_nm - g.z0_nm, g.lsb_nm);
  }
}

// The floor (as RingFloors) over the columns [i0, i1) x [j0, j1): the
// lowest of the rings whose reach meets them (INT64_MAX: none).
int64_t floor_over(const RingFloors& f, int32_t i0, int32_t i1, int32_t j0, int32_t j1) {
  int64_t low = INT64_MAX;
  for (int q = 0; q < f.n; ++q) {
    const GridRect& c = f.rect[q];
    if (c.i0 < i1 && i0 < c.i1 && c.j0 < j1 && j0 < c.j1) low = min_of(low, f.floor_lsb[q]);
  }
  return low;
}

size_t tile_index(const SafetyWatch* w, int32_t ti, int32_t tj) {
  return static_cast<size_t>(tj) * static_cast<size_t>(w->tiles_x) + static_cast<size_t>(ti);
}
size_t block_index(const SafetyWatch* w, int32_t ti, int32_t tj) {
  return static_cast<size_t>(tj >> kSafetyBlockBits) * static_cast<size_t>(w->blocks_x) +
         static_cast<size_t>(ti >> kSafetyBlockBits);
}

// The block of tile (ti, tj) brought up to date with its tiles after a
// look changed them: the highest bound, and whether any is not its top.
void block_refresh(SafetyWatch* w, int32_t ti, int32_t tj) {
  const int32_t t0 = ti >> kSafetyBlockBits << kSafetyBlockBits, u0 = tj >> kSafetyBlockBits << kSafetyBlockBits;
  uint32_t hi = 0, stale = 0;
  for (int32_t u = u0; u < min_of(w->tiles_y, u0 + (1 << kSafetyBlockBits)); ++u)
    for (int32_t t = t0; t < min_of(w->tiles_x, t0 + (1 << kSafetyBlockBits)); ++t) {
      const size_t k = tile_index(w, t, u);
      hi = max_of(hi, w->tile_max[k]);
      stale |= w->tile_top[k] == kSafetyTileUnknown || w->tile_top[k] != w->tile_max[k] ? 1u : 0u;
    }
  const size_t b = block_index(w, ti, tj);
  w->block_max[b] = hi;
  w->block_stale[b] = stale;
}

// Calls fn(ti, tj) for the tiles over g's columns `rect`, row by row of
// tiles, but (blocks) not for a block's tiles in a row when skip(ti, tj)
// of its first one there says it holds nothing to do.
template <class Skip, class Fn>
void each_tile(const GridRect& rect, bool blocks, Skip skip, Fn fn) {
  const int32_t ti0 = rect.i0 >> kSafetyTileBits, ti1 = (rect.i1 - 1) >> kSafetyTileBits;
  const int32_t mask = (1 << kSafetyBlockBits) - 1;
  for (int32_t tj = rect.j0 >> kSafetyTileBits; tj <= (rect.j1 - 1) >> kSafetyTileBits; ++tj)
    for (int32_t ti = ti0; ti <= ti1;) {
      const int32_t end = blocks ? min_of(ti1, ti | mask) : ti1;
      if (!blocks || !skip(ti, tj))
        for (int32_t t = ti; t <= end; ++t) fn(t, tj);
      ti = end + 1;
    }
}

// The blocks a look went into, to bring up to date after it (block_refresh):
// a few, else all those over the look's columns.
class VisitedBlocks {
 public:
  void add(int32_t ti, int32_t tj) {
    const int32_t bi = ti >> kSafetyBlockBits, bj = tj >> kSafetyBlockBits;
    for (int k = 0; k < n_; ++k)
      if (bi_[k] == bi && bj_[k] == bj) return;
    if (n_ == kMax) {
      all_ = true;
      return;
    }
    bi_[n_] = bi;
    bj_[n_++] = bj;
  }
  void refresh(SafetyWatch* w, const GridRect& rect) const {
    if (!all_) {
      for (int k = 0; k < n_; ++k) block_refresh(w, bi_[k] << kSafetyBlockBits, bj_[k] << kSafetyBlockBits);
      return;
    }
    const int32_t s = kSafetyTileBits + kSafetyBlockBits;
    for (int32_t bj = rect.j0 >> s; bj <= (rect.j1 - 1) >> s; ++bj)
      for (int32_t bi = rect.i0 >> s; bi <= (rect.i1 - 1) >> s; ++bi)
        block_refresh(w, bi << kSafetyBlockBits, bj << kSafetyBlockBits);
  }

 private:
  static constexpr int kMax = 32;
  int n_ = 0;
  bool all_ = false;
  int32_t bi_[kMax], bj_[kMax];
};

// The highest top of tile (ti, tj) of g, read again only when a record
// changed it since (tile_top: kSafetyTileUnknown), else null memory: read.
template <class H>
uint32_t tile_high(const SafetyWatch* w, const DexelGrid<H>& g, int32_t ti, int32_t tj) {
  uint32_t* known = w && w->tile_top ? &w->tile_top[static_cast<size_t>(tj) * static_cast<size_t>(w->tiles_x) + static_cast<size_t>(ti)]
                                : nullptr;
  if (known && *known != kSafetyTileUnknown) return *known;
  const int32_t ts = 1 << kSafetyTileBits;
  uint32_t hi = 0;
  for (int32_t j = tj * ts; j < min_of(g.ny, tj * ts + ts); ++j) {
    const H* top = g.top + g.index(0, j);
    for (int32_t i = ti * ts; i < min_of(g.nx, ti * ts + ts); ++i) hi = max_of<uint32_t>(hi, top[i]);
  }
  if (known) *known = hi;
  return hi;
}

// The body's rings of record r against the material of g (tops after the
// cut): every column where a ring comes below a top is an overlap, of the
// shank or the holder (or, for the fixture grid, of kind `as`). Tiles
// (tile_max, or null) skip what lies wholly under the body; the fast look
// (w->body_fast) skips as well what lies under each ring where it reaches
// (RingFloors), which reads the same columns' overlaps in the same order.
template <class H>
bool body_contacts(SafetyWatch* w, size_t first, const DexelGrid<H>& g, uint32_t* tile_max, const CanonRecord& r,
                   const SafetyMove& m, bool fixture, bool* added) {
  bool found = false;
  const ToolBody& body = *m.body;
  // Wholly over the highest top (a sound program's usual case): nothing to
  // do, before any piece is made.
  if (div_floor(lowest_tip(r).z_nm + body.lowest_nm - g.z0_nm, g.lsb_nm) >= g.top_bound_lsb) return false;
  const auto column = [&](const Batch& b, int32_t i, int32_t j, int64_t top) {
    const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm;
    BodyPart part = BodyPart::kHolder;
    const int64_t low = body_lowest(body, b, x, y, &part);
    if (low == kBodyNever) return;
    const int64_t depth = g.z0_nm + top * g.lsb_nm - low;
    if (depth <= 0) return;
    const SafetyKind kind = fixture ? SafetyKind::kFixture : part == BodyPart::kShank ? SafetyKind::kShank : SafetyKind::kHolder;
    if ((kind == SafetyKind::kShank && !w->check_shank) || (kind == SafetyKind::kHolder && !w->check_holder)) return;
    found = true;
    SafetyEvent* e = event_for(w, first, r.line, kind, added);
    if (e) add_overlap(e, depth, g.lsb_nm, PointNm{x, y, low});
  };
  const bool blocks = w->body_fast && tile_max && w->block_max;
  each_batch(g, r, body.reach_nm, [&](const Batch& b, const GridRect& rect) {
    // Tops at or under this (LSB) are under the body everywhere.
    const int64_t floor_lsb = div_floor(b.zmin + body.lowest_nm - g.z0_nm, g.lsb_nm);
    if (floor_lsb >= g.top_bound_lsb) return true;
    RingFloors rings;
    if (w->body_fast) ring_floors(g, body, b, &rings);
    const int32_t ts = 1 << kSafetyTileBits;
    VisitedBlocks visited;
    // A block is passed over when every tile bound in it is under the body,
    // or when no tile in it has to be tightened (each bound is its top) and
    // its highest is under every ring reaching its columns.
    const auto skip = [&](int32_t ti, int32_t tj) {
      const size_t k = block_index(w, ti, tj);
      if (static_cast<int64_t>(w->block_max[k]) <= floor_lsb) return true;
      if (!w->block_stale[k]) {
        const int32_t bs = ts << kSafetyBlockBits, bi = (ti >> kSafetyBlockBits) * bs, bj = (tj >> kSafetyBlockBits) * bs;
        const int64_t under = max_of(floor_lsb, floor_over(rings, max_of(rect.i0, bi), min_of(rect.i1, bi + bs),
                                                           max_of(rect.j0, bj), min_of(rect.j1, bj + bs)));
        if (static_cast<int64_t>(w->block_max[k]) <= under) return true;
      }
      visited.add(ti, tj);
      return false;
    };
    each_tile(rect, blocks, skip, [&](int32_t ti, int32_t tj) {
      const int32_t i0 = max_of(rect.i0, ti * ts), i1 = min_of(rect.i1, ti * ts + ts);
      const int32_t j0 = max_of(rect.j0, tj * ts), j1 = min_of(rect.j1, tj * ts + ts);
      int64_t hi = INT64_MAX;
      if (tile_max) {
        uint32_t& bound = tile_max[tile_index(w, ti, tj)];
        if (static_cast<int64_t>(bound) <= floor_lsb) return;
        // Tighten the bound over the whole tile (the reference reads it).
        bound = w->body_fast ? tile_high(w, g, ti, tj) : tile_high<H>(nullptr, g, ti, tj);
        hi = bound;
        if (hi <= floor_lsb) return;
      }
      if (!w->body_fast) {
        for (int32_t j = j0; j < j1; ++j)
          for (int32_t i = i0; i < i1; ++i) {
            const size_t at = g.index(i, j);
            const int64_t top = g.top[at];
            if (top <= floor_lsb || (top == 0 && g.bottom[at] == 0)) continue;
            column(b, i, j, top);
          }
        return;
      }
      if (hi <= floor_over(rings, i0, i1, j0, j1)) return;
      for (int32_t j = j0; j < j1; ++j) {
        const H* tops = g.top + g.index(0, j);
        const H* bottoms = g.bottom + g.index(0, j);
        for (int32_t i = i0; i < i1; ++i) {
          const int64_t top = tops[i];
          if (top <= floor_lsb || (top == 0 && bottoms[i] == 0)) continue;
          if (top <= floor_over(rings, i, i + 1, j, j + 1)) continue;
          column(b, i, j, top);
        }
      }
    });
    if (blocks) visited.refresh(w, rect);
    return true;
  });
  return found;
}

// True when the body over record r, its tip no lower than low_nm, is over
// the bound of every tile in its reach: it touches nothing.
template <class H>
bool body_clear(const SafetyWatch* w, const DexelGrid<H>& g, const CanonRecord& r, const ToolBody& body, int64_t low_nm) {
  const int64_t floor_lsb = div_floor(low_nm + body.lowest_nm - g.z0_nm, g.lsb_nm);
  if (floor_lsb >= g.top_bound_lsb) return true;
  if (!w->tile_max) return false;
  bool clear = true;
  const bool blocks = w->body_fast && w->block_max;
  each_batch(g, r, body.reach_nm, [&](const Batch&, const GridRect& rect) {
    each_tile(
        rect, blocks,
        [&](int32_t ti, int32_t tj) { return !clear || static_cast<int64_t>(w->block_max[block_index(w, ti, tj)]) <= floor_lsb; },
        [&](int32_t ti, int32_t tj) {
          if (static_cast<int64_t>(w->tile_max[tile_index(w, ti, tj)]) > floor_lsb) clear = false;
        });
    return clear;
  });
  return clear;
}

// Shank and holder contacts come in stretches: a tool too short for a deep
// cut rubs on move after move. A stretch is looked at in full on its first
// move and wherever the tool goes deeper than it has in the stretch (each
// such line is a finding, the depth grows there); the moves between
// lengthen the last finding (its last_line). It ends at a move whose body
// is clear of every top in reach (the tile bounds, which only a look
// tightens), or one that goes deeper and touches nothing. So a program that
// rubs all along costs a full look at each new depth, not one a move.
template <class H>
void body_stretch(SafetyWatch* w, size_t first, const DexelGrid<H>& g, const CanonRecord& r, const SafetyMove& m,
                  bool* added) {
  const int64_t low = lowest_tip(r).z_nm;
  if (w->body_stretch_open) {
    if (body_clear(w, g, r, *m.body, low)) {
      w->body_stretch_open = false;
      return;
    }
    if (low >= w->body_stretch_low_nm) {  // no deeper: the stretch goes on
      for (size_t k = 0; k < w->nevents; ++k)
        if (w->events[k].line == w->body_stretch_line &&
            (w->events[k].kind == SafetyKind::kShank || w->events[k].kind == SafetyKind::kHolder))
          w->events[k].last_line = max_of(w->events[k].last_line, r.line);
      return;
    }
  }
  w->body_stretch_open = body_contacts(w, first, g, w->tile_max, r, m, false, added);
  w->body_stretch_low_nm = low;
  w->body_stretch_line = r.line;
}

// The fixture grid's column at (x, y): from the lowest bottom to the highest
// top of the boxes over it, rounded outwards (a box is never thinner in the
// grid than it is); none: a hole.
void fixture_column(const DexelGrid<uint32_t>& f, const BoxNm* boxes, int n, int64_t x, int64_t y, uint32_t* top,
                    uint32_t* bottom) {
  int64_t lo = INT64_MAX, hi = INT64_MIN;
  for (int k = 0; k < n; ++k) {
    const BoxNm& b = boxes[k];
    if (x < b.lo.x_nm || x > b.hi.x_nm || y < b.lo.y_nm || y > b.hi.y_nm) continue;
    lo = min_of(lo, b.lo.z_nm);
    hi = max_of(hi, b.hi.z_nm);
  }
  if (hi == INT64_MIN) {
    *top = *bottom = 0;
    return;
  }
  *bottom = static_cast<uint32_t>(clamp<int64_t>(div_floor(lo - f.z0_nm, f.lsb_nm), 0, f.top_bound_lsb));
  *top = static_cast<uint32_t>(clamp<int64_t>(div_ceil(hi - f.z0_nm, f.lsb_nm), 0, f.top_bound_lsb));
}

// The fixture check: the cutter swept into the fixture grid exactly as
// into the stock (what it would cut there is an overlap, then put back),
// and the body's rings against it.
void fixture_contacts(SafetyWatch* w, size_t first, const CanonRecord& r, const SafetyMove& m, bool* added) {
  DexelGrid<uint32_t>& f = *w->fixtures;
  const int64_t reach = max_of(m.body->reach_nm, m.body->cutter_r_nm);
  const int64_t x0 = min_of(r.start.x_nm, r.end.x_nm), x1 = max_of(r.start.x_nm, r.end.x_nm);
  const int64_t y0 = min_of(r.start.y_nm, r.end.y_nm), y1 = max_of(r.start.y_nm, r.end.y_nm);
  const int64_t fx1 = f.x0_nm + (f.nx - 1) * f.pitch_nm, fy1 = f.y0_nm + (f.ny - 1) * f.pitch_nm;
  const bool arc = r.kind == CanonKind::kArc;
  if (!arc && (x1 + reach < f.x0_nm || x0 - reach > fx1 || y1 + reach < f.y0_nm || y0 - reach > fy1)) return;
  if (min_of(r.start.z_nm, r.end.z_nm) >= f.z0_nm + f.top_bound_lsb * f.lsb_nm && !arc) return;
  if (w->fixture_tool_ok) {
    f.dirty = GridRect::none();
    CutStats st;
    if (arc) sweep_arc(&f, w->fixture_tool, r, &st, true);
    else sweep_line(&f, w->fixture_tool, r.start, r.end, &st, true);
    const GridRect d = f.dirty;
    uint32_t* top = f.top;
    uint32_t* bottom = f.bottom;
    for (int32_t j = max_of(d.j0, int32_t{0}); j < min_of(d.j1, f.ny); ++j) {
      for (int32_t i = max_of(d.i0, int32_t{0}); i < min_of(d.i1, f.nx); ++i) {
        const size_t at = f.index(i, j);
        const uint32_t was_top = top[at], was_bottom = bottom[at];
        const int64_t x = f.x0_nm + i * f.pitch_nm, y = f.y0_nm + j * f.pitch_nm;
        uint32_t t1 = 0, b1 = 0;  // the column as the boxes make it
        fixture_column(f, w->fixture_boxes, w->nfixture_boxes, x, y, &t1, &b1);
        if (was_top == t1 && was_bottom == b1) continue;
        // How much of the box the tool took: from the top down, all of it
        // (a hole: through), or from the bottom up (the shaft's top in it).
        const int64_t depth = (was_top == 0 && was_bottom == 0 ? static_cast<int64_t>(t1) - b1
                               : was_top < t1                  ? static_cast<int64_t>(t1) - was_top
                                                               : static_cast<int64_t>(was_bottom) - b1) *
                              f.lsb_nm;
        top[at] = t1;
        bottom[at] = b1;
        if (depth <= 0) continue;
        SafetyEvent* e = event_for(w, first, r.line, SafetyKind::kFixture, added);
        if (e) add_overlap(e, depth, f.lsb_nm, PointNm{x, y, f.z0_nm + was_top * f.lsb_nm});
      }
    }
    f.dirty = GridRect::none();
  }
  if (m.body->nrings > 0) (void)body_contacts(w, first, f, nullptr, r, m, true, added);
}

// The tip's z where the cutter first covers (x, y) along r, or kBodyNever:
// r's pieces made once (the first column that asks) for every column of
// the record, or, past kCoverPieces of them (an arc's chords), walked
// again for each (a few: a line is one piece up to 67 mm, and the stack
// small, as Batch's).
class FirstCover {
 public:
  explicit FirstCover(const CanonRecord& r) : r_(r) {}
  int64_t z(int64_t radius, int64_t x, int64_t y) {
    if (r_.kind != CanonKind::kArc && r_.start.z_nm == r_.end.z_nm) return r_.start.z_nm;
    if (!made_) make();
    for (int k = 0; k < n_; ++k) {
      const int64_t z = piece_first_cover_z(piece_[k], radius, x, y);
      if (z != kBodyNever) return z;
    }
    if (!more_) return kBodyNever;
    BodyPieces pieces;
    pieces.init(r_);
    BodyPiece p;
    while (pieces.next(&p)) {
      const int64_t z = piece_first_cover_z(p, radius, x, y);
      if (z != kBodyNever) return z;
    }
    return kBodyNever;
  }

 private:
  void make() {
    made_ = true;
    BodyPieces pieces;
    pieces.init(r_);
    BodyPiece p;
    while (n_ < kCoverPieces && pieces.next(&p)) piece_[n_++] = p;
    more_ = n_ == kCoverPieces && pieces.next(&p);
    if (more_) n_ = 0;  // walked in full per column, in order
  }

  static constexpr int kCoverPieces = 4;
  const CanonRecord& r_;
  bool made_ = false, more_ = false;
  int n_ = 0;
  BodyPiece piece_[kCoverPieces];
};

}  // namespace

bool safety_is_plunge(const CanonRecord& r) {
  return (r.kind == CanonKind::kFeed || r.kind == CanonKind::kTraverse) && r.start.x_nm == r.end.x_nm &&
         r.start.y_nm == r.end.y_nm && r.end.z_nm < r.start.z_nm;
}

void safety_watch_set_tool(SafetyWatch* w, const ToolProfile& p) {
  w->fixture_tool_ok = w->fixtures && ok(sweep_tool_prepare(p, w->fixtures->lsb_nm, &w->fixture_tool));
}

template <class H>
bool fixture_grid_size(const DexelGrid<H>& g, const BoxNm* boxes, int n, DexelGrid<uint32_t>* out) {
  if (n <= 0) return false;
  BoxNm u = boxes[0];
  for (int k = 1; k < n; ++k) {
    u.lo.x_nm = min_of(u.lo.x_nm, boxes[k].lo.x_nm);
    u.lo.y_nm = min_of(u.lo.y_nm, boxes[k].lo.y_nm);
    u.lo.z_nm = min_of(u.lo.z_nm, boxes[k].lo.z_nm);
    u.hi.x_nm = max_of(u.hi.x_nm, boxes[k].hi.x_nm);
    u.hi.y_nm = max_of(u.hi.y_nm, boxes[k].hi.y_nm);
    u.hi.z_nm = max_of(u.hi.z_nm, boxes[k].hi.z_nm);
  }
  // On the stock grid's lattice: the columns whose axes are in the boxes.
  const int64_t i0 = div_ceil(u.lo.x_nm - g.x0_nm, g.pitch_nm), i1 = div_floor(u.hi.x_nm - g.x0_nm, g.pitch_nm);
  const int64_t j0 = div_ceil(u.lo.y_nm - g.y0_nm, g.pitch_nm), j1 = div_floor(u.hi.y_nm - g.y0_nm, g.pitch_nm);
  if (i1 < i0 || j1 < j0 || i1 - i0 >= 65535 || j1 - j0 >= 65535) return false;
  DexelGrid<uint32_t> f;
  f.nx = static_cast<int32_t>(max_of<int64_t>(i1 - i0 + 1, 2));
  f.ny = static_cast<int32_t>(max_of<int64_t>(j1 - j0 + 1, 2));
  f.x0_nm = g.x0_nm + i0 * g.pitch_nm;
  f.y0_nm = g.y0_nm + j0 * g.pitch_nm;
  f.pitch_nm = g.pitch_nm;
  f.lsb_nm = g.lsb_nm;
  // Heights from a whole number of LSB under the lowest box, as the stock's.
  f.z0_nm = g.z0_nm + div_floor(u.lo.z_nm - g.z0_nm, g.lsb_nm) * g.lsb_nm;
  const int64_t span = div_ceil(u.hi.z_nm - f.z0_nm, g.lsb_nm);
  if (span <= 0 || span >= (int64_t{1} << 32) - 1) return false;
  f.top_bound_lsb = span;
  f.bottoms_zero = false;
  *out = f;
  return true;
}

void fixture_grid_fill(DexelGrid<uint32_t>* f, const BoxNm* boxes, int n) {
  for (int32_t j = 0; j < f->ny; ++j)
    for (int32_t i = 0; i < f->nx; ++i) {
      const size_t at = f->index(i, j);
      fixture_column(*f, boxes, n, f->x0_nm + i * f->pitch_nm, f->y0_nm + j * f->pitch_nm, &f->top[at], &f->bottom[at]);
    }
}

template <class H>
Status safety_watch_init(SafetyWatch* w, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words,
                         uint32_t* tiles, size_t tile_words) {
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  if (!shadow || shadow_words < n) return Status::kBufferTooSmall;
  for (size_t k = 0; k < n; ++k) shadow[k] = g.top[k];
  w->shadow = shadow;
  w->tile_max = tiles && tile_words >= safety_tile_words(g) ? tiles : nullptr;
  w->tiles_x = (g.nx >> kSafetyTileBits) + 1;
  w->tiles_y = (g.ny >> kSafetyTileBits) + 1;
  w->blocks_x = (w->tiles_x >> kSafetyBlockBits) + 1;
  w->blocks_y = (w->tiles_y >> kSafetyBlockBits) + 1;
  const size_t ntiles = static_cast<size_t>(w->tiles_x) * static_cast<size_t>(w->tiles_y);
  const size_t nblocks = static_cast<size_t>(w->blocks_x) * static_cast<size_t>(w->blocks_y);
  w->tile_top = w->tile_max ? w->tile_max + ntiles : nullptr;
  w->block_max = w->tile_max ? w->tile_top + ntiles : nullptr;
  w->block_stale = w->tile_max ? w->block_max + nblocks : nullptr;
  if (w->tile_max) {  // every tile bounded by the highest top, none read yet
    for (size_t k = 0; k < ntiles; ++k) {
      w->tile_max[k] = static_cast<uint32_t>(g.top_bound_lsb);
      w->tile_top[k] = kSafetyTileUnknown;
    }
    for (size_t k = 0; k < nblocks; ++k) {
      w->block_max[k] = static_cast<uint32_t>(g.top_bound_lsb);
      w->block_stale[k] = 1;
    }
  }
  w->nevents = 0;
  w->total = 0;
  w->rapid_removed_lsb = 0;
  w->spindle_stretch = kSafetyEventsMax;
  w->spindle_stretch_open = false;
  w->spindle_on_line = 0;
  for (uint32_t& l : w->unkept_line) l = 0;
  w->body_stretch_open = false;
  return Status::kOk;
}

template <class H>
bool safety_watch_record(SafetyWatch* w, const DexelGrid<H>& g, GridRect changed, const CanonRecord& r,
                         const SafetyMove& m, const SafetyOrigin* prev) {
  const size_t first = w->nevents;
  const uint64_t total_before = w->total;
  bool added = false;
  const int32_t i0 = max_of(changed.i0, int32_t{0}), i1 = min_of(changed.i1, g.nx);
  const int32_t j0 = max_of(changed.j0, int32_t{0}), j1 = min_of(changed.j1, g.ny);
  if (w->tile_top && i0 < i1 && j0 < j1)  // the tiles the record cut: their highest tops to read again
    for (int32_t tj = j0 >> kSafetyTileBits; tj <= (j1 - 1) >> kSafetyTileBits; ++tj)
      for (int32_t ti = i0 >> kSafetyTileBits; ti <= (i1 - 1) >> kSafetyTileBits; ++ti)
      {
        w->tile_top[static_cast<size_t>(tj) * static_cast<size_t>(w->tiles_x) + static_cast<size_t>(ti)] = kSafetyTileUnknown;
        w->block_stale[block_index(w, ti, tj)] = 1;
      }
  const bool move = r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
  if (move && m.spindle_on && w->spindle_stretch_open && !w->spindle_on_line) w->spindle_on_line = r.line;
  if (move && w->check_below) check_below(w, first, r, SafetyKind::kBelowStock, w->bottom_nm, &added);
  if (move && w->check_table) check_below(w, first, r, SafetyKind::kIntoTable, w->table_nm, &added);
  // Straight up is the way out of whatever the move before went into.
  const bool rising = r.kind != CanonKind::kArc && r.start.x_nm == r.end.x_nm && r.start.y_nm == r.end.y_nm &&
                      r.end.z_nm > r.start.z_nm;
  if (move && m.body && m.start_known && !rising) {
    if (w->fixtures) fixture_contacts(w, first, r, m, &added);
    if ((w->check_holder || w->check_shank) && m.body->nrings > 0) body_stretch(w, first, g, r, m, &added);
  }
  // The shank: tops before the record at or under this (LSB) were removed
  // by flutes wherever the tool stood.
  const auto flute_of = [](const SafetyMove& x) { return x.body ? x.body->flute_nm : 0; };
  int64_t shank_floor_lsb = INT64_MAX;
  if (w->check_shank && flute_of(m) > 0 && move) {
    const int64_t low = lowest_tip(r).z_nm + flute_of(m);
    shank_floor_lsb = div_floor(low - g.z0_nm, g.lsb_nm);
    if (shank_floor_lsb >= g.top_bound_lsb) shank_floor_lsb = INT64_MAX;  // over every top: nothing to compare
  }
  const auto plunging = [w](const SafetyMove& x) {
    return w->check_plunge && x.plunge && x.body && !x.body->centre_cutting && x.start_known;
  };
  // Most moves are feeds with the spindle on after a move like them: what
  // they remove is no finding whoever it is charged to, so the shadow just
  // follows the grid (a widening copy the compiler vectorizes).
  const auto quiet = [w, &plunging](const SafetyMove& x) {
    return !x.rapid && (x.spindle_on || !w->check_spindle) && x.start_known && !plunging(x);
  };
  bool fast = quiet(m) && (!prev || quiet(prev->move));
  if (fast && shank_floor_lsb != INT64_MAX) {  // no top before it above the flutes
    uint32_t hi = 0;
    for (int32_t j = j0; j < j1; ++j) {
      const uint32_t* was = w->shadow + g.index(0, j);
      for (int32_t i = i0; i < i1; ++i) hi = max_of(hi, was[i]);
    }
    fast = static_cast<int64_t>(hi) <= shank_floor_lsb;
  }
  if (fast) {
    for (int32_t j = j0; j < j1; ++j) {
      const size_t row = g.index(0, j);
      const H* top = g.top + row;
      uint32_t* was = w->shadow + row;
      for (int32_t i = i0; i < i1; ++i) was[i] = top[i];
    }
    return added;
  }
  FirstCover cover(r);
  each_removal(w->shadow, g, changed, [&](int32_t i, int32_t j, uint32_t was, uint32_t now) {
    const uint64_t removed = was - now;
    const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm, z = g.z0_nm + now * g.lsb_nm;
    const bool before = prev && prev->tool && profile_explains_cut(*prev->tool, prev->end, x, y, z, g.lsb_nm);
    const SafetyMove& by = before ? prev->move : m;
    if (by.rapid) w->rapid_removed_lsb += removed;
    if (!by.start_known) return;
    // Above the flutes where the tool first stood over the column. A
    // deferred end cap's (before) the shank disc found at its own record
    // as material left (body_contacts): not twice.
    if (!before && static_cast<int64_t>(was) > shank_floor_lsb && flute_of(by) > 0) {
      const int64_t zf = cover.z(by.body->cutter_r_nm, x, y);
      if (zf != kBodyNever) {
        const int64_t limit = zf + by.body->flute_nm, was_nm = z + static_cast<int64_t>(removed) * g.lsb_nm;
        const int64_t depth = was_nm - max_of(limit, z);
        if (depth > 0) {
          SafetyEvent* e = event_for(w, first, by.line, SafetyKind::kShank, &added);
          if (e) add_overlap(e, depth, g.lsb_nm, PointNm{x, y, limit});
        }
      }
    }
    if (plunging(by) && static_cast<int64_t>(removed) * g.lsb_nm > kPlungeDepthNm) {
      // At the axis: within a quarter of the radius, or the column nearest it.
      const int64_t zone = max_of(by.body->cutter_r_nm / 4, g.pitch_nm * 71 / 100);
      const int64_t ax = x - by.end.x_nm, ay = y - by.end.y_nm;
      if (ax >= -zone && ax <= zone && ay >= -zone && ay <= zone && ax * ax + ay * ay <= zone * zone) {
        SafetyEvent* e = event_for(w, first, by.line, SafetyKind::kPlunge, &added);
        if (e) add_overlap(e, static_cast<int64_t>(removed) * g.lsb_nm, g.lsb_nm, PointNm{by.end.x_nm, by.end.y_nm, z});
      }
    }
    SafetyEvent* e;
    if (by.rapid && w->check_rapid) {
      e = event_for(w, first, by.line, SafetyKind::kRapidIntoStock, &added);
    } else if (!by.spindle_on && w->check_spindle) {
      // One event a stretch: the open one, else a new one on this line.
      if (!w->spindle_stretch_open || (w->spindle_on_line && by.line >= w->spindle_on_line)) {  // M3/M4 ended the last
        w->spindle_stretch_open = true;
        w->spindle_on_line = 0;
        ++w->total;
        added = true;
        w->spindle_stretch = w->nevents;
        e = nullptr;
        if (w->nevents < kSafetyEventsMax) {
          e = &w->events[w->nevents++];
          *e = SafetyEvent{};
          e->kind = SafetyKind::kSpindleStopped;
          e->line = by.line;
        }
      } else {
        e = w->spindle_stretch < w->nevents ? &w->events[w->spindle_stretch] : nullptr;
      }
      if (e) e->last_line = max_of(e->last_line, by.line);
    } else {
      return;
    }
    if (!e) return;
    ++e->columns;
    e->removed_lsb += removed;
    const int64_t depth_nm = static_cast<int64_t>(removed) * g.lsb_nm;
    if (e->columns == 1 || depth_nm > e->depth_nm) {  // the deepest cut column marks the event
      e->depth_nm = depth_nm;
      e->at = PointNm{x, y, z};
    }
  });
  return added || w->total != total_before;
}

#define DEXMILL_SAFETY_INSTANTIATE(H)                                                                            \
  template Status safety_watch_init<H>(SafetyWatch*, const DexelGrid<H>&, uint32_t*, size_t, uint32_t*, size_t); \
  template bool fixture_grid_size<H>(const DexelGrid<H>&, const BoxNm*, int, DexelGrid<uint32_t>*);             \
  template bool safety_watch_record<H>(SafetyWatch*, const DexelGrid<H>&, GridRect, const CanonRecord&,          \
                                       const SafetyMove&, const SafetyOrigin*);
DEXMILL_SAFETY_INSTANTIATE(uint8_t)
DEXMILL_SAFETY_INSTANTIATE(uint16_t)
DEXMILL_SAFETY_INSTANTIATE(uint32_t)

}  // namespace dexmill
