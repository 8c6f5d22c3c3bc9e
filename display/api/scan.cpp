// The embedding API's first pass (dexmill.h dm_scan_*): core/sim/scan.h's
// ProgramScan over text fed in pieces, and the stock and grid core/sim/scan_stock.h
// chooses from it, as `dexmill run` does.
#include <new>

#include "core/sim/carver.h"
#include "core/sim/chunk_input.h"
#include "core/sim/scan_stock.h"
#include "display/api/handles.h"

using namespace dexmill;
using namespace dexmill::api;

namespace {

constexpr uint32_t kScanTag = 0x64736331;  // "dsc1"

// The pass's messages: it stops at the first error; that one is kept.
class FirstError final : public GcodeMessages {
 public:
  void error(const GcodeDiag& d) override {
    if (errors_++ == 0) first = d;
  }
  void warning(const GcodeDiag&) override { ++warnings_; }
  GcodeDiag first{};
};

}  // namespace

// The handle's block: this, then the reader's buffer.
struct dm_scan {
  uint32_t tag;
  bool ended;
  int32_t state;  // the last step's DM_*
  NumberedTools library;
  SimJob job;
  FirstError messages;
  ProgramMemory memory;
  ChunkInput input;
  ProgramScan scan;
  ScanPass pass;

  dm_scan(const NumberedTools& lib, const SimJob& j, char* buf, size_t bytes)
      : tag(0),
        ended(false),
        state(DM_READY),
        library(lib),
        job(own_library(j)),
        input(buf, bytes),
        scan(job),
        pass(&scan, &input, &messages, &memory) {}

 private:
  // The job's library is the copy in here (scan_job_of pointed it at the caller's).
  SimJob own_library(SimJob j) const {
    if (j.library) {
      j.library = &library;
      j.offsets = &library;
      j.tools = library.tools;
    }
    return j;
  }
};

namespace {

bool live(const dm_scan* s) { return s && s->tag == kScanTag; }

// The job's SimJob (its library pointing into lib) and the reader's bytes.
dm_status scan_job(const dm_job& in, NumberedTools* lib, SimJob* j, size_t* bytes) {
  if (const dm_status s = scan_job_of(in, lib, j)) return s;
  Carver c(nullptr);
  (void)c.take<dm_scan>(1);
  (void)c.take<char>(j->input_buffer_bytes);
  *bytes = c.used();
  return DM_OK;
}

void box_of(const PointNm& lo, const PointNm& hi, dm_box* out) {
  const int64_t l[3] = {lo.x_nm, lo.y_nm, lo.z_nm}, h[3] = {hi.x_nm, hi.y_nm, hi.z_nm};
  for (int a = 0; a < 3; ++a) {
    out->lo_nm[a] = l[a];
    out->hi_nm[a] = h[a];
  }
}

bool box_empty(const dm_box& b) {
  for (int a = 0; a < 3; ++a)
    if (b.lo_nm[a] || b.hi_nm[a]) return false;
  return true;
}

int32_t units_of(const ProgramScan& s) {
  if (s.inch_moves && s.mm_moves) return DM_UNITS_MIXED;
  if (s.inch_moves) return DM_UNITS_INCH;
  if (s.mm_moves) return DM_UNITS_MM;
  return DM_UNITS_NONE;
}

}  // namespace

extern "C" {

dm_status dm_scan_bytes(const dm_job* job, size_t* bytes) {
  if (!job || !bytes) return DM_E_ARGUMENT;
  *bytes = 0;
  NumberedTools lib;
  SimJob j;
  return scan_job(*job, &lib, &j, bytes);
}

dm_status dm_scan_create(const dm_job* job, void* mem, size_t bytes, dm_scan** out) {
  if (!job || !out) return DM_E_ARGUMENT;
  *out = nullptr;
  NumberedTools lib;
  SimJob j;
  size_t need = 0;
  if (const dm_status s = scan_job(*job, &lib, &j, &need)) return s;
  if (!mem || (reinterpret_cast<uintptr_t>(mem) & 7) != 0 || bytes < need) return DM_E_MEMORY;
  Carver c(static_cast<char*>(mem));
  (void)c.take<dm_scan>(1);
  char* buf = c.take<char>(j.input_buffer_bytes);
  dm_scan* s = new (mem) dm_scan(lib, j, buf, j.input_buffer_bytes);
  s->tag = kScanTag;
  *out = s;
  return DM_OK;
}

dm_status dm_scan_feed(dm_scan* scan, const char* text, size_t n) {
  if (!live(scan) || (!text && n)) return DM_E_ARGUMENT;
  if (scan->ended) return DM_E_STATE;
  if (!scan->input.taken()) return DM_E_BUSY;
  scan->input.feed(text, n);
  return DM_OK;
}

int32_t dm_scan_input_taken(const dm_scan* scan) { return live(scan) && scan->input.taken() ? 1 : 0; }

dm_status dm_scan_end_input(dm_scan* scan) {
  if (!live(scan)) return DM_E_ARGUMENT;
  scan->ended = true;
  scan->input.close();
  return DM_OK;
}

dm_status dm_scan_step(dm_scan* scan, const dm_budget* budget, int32_t* state) {
  if (!live(scan) || !state) return DM_E_ARGUMENT;
  if (scan->state == DM_READY || scan->state == DM_NEED_INPUT) {
    const ScanPass::State s = scan->pass.step(budget ? budget->lines : 0);
    int32_t next = DM_DONE;
    if (s == ScanPass::State::kReading) next = DM_READY;
    else if (s == ScanPass::State::kWaiting) next = DM_NEED_INPUT;
    else if (scan->scan.io_error) next = DM_IO_ERROR;
    scan->state = next;
  }
  *state = scan->state;
  return DM_OK;
}

dm_status dm_scan_get_result(const dm_scan* scan, dm_scan_result* out) {
  if (!live(scan) || !out) return DM_E_ARGUMENT;
  if (scan->state != DM_DONE) return DM_E_STATE;
  const ProgramScan& s = scan->scan;
  dm_scan_result r{};
  StockBox stock;
  r.stock_from = static_cast<int32_t>(scan_default_stock(s, &stock));
  box_of(stock.lo, stock.hi, &r.stock);
  r.units = units_of(s);
  r.pitch_nm = scan_default_pitch_nm(s, stock);
  const BoxAccum& ext = s.summary.motion_box();
  r.has_extents = ext.valid ? 1 : 0;
  if (ext.valid) box_of(ext.lo, ext.hi, &r.extents);
  r.ntools = s.ntools;
  r.rapids = s.summary.count(CanonKind::kTraverse);
  r.feeds = s.summary.count(CanonKind::kFeed);
  r.arcs = s.summary.count(CanonKind::kArc);
  r.dwells = s.summary.count(CanonKind::kDwell);
  r.tool_changes = s.summary.count(CanonKind::kToolChange);
  r.lines = s.lines;
  r.errors = scan->messages.errors();
  if (r.errors) {
    r.error_line = scan->messages.first.line;
    r.error_col = scan->messages.first.col;
    r.error_code = static_cast<int32_t>(scan->messages.first.code);
  }
  r.bad_tool_line = s.bad_tool_line;
  r.bad_tool = s.bad_tool;
  r.workpiece_bad_line = s.workpiece_bad ? s.workpiece_bad_line : 0;
  r.estimated_us = s.summary.blended_time_us();
  r.table_units = s.table_inch ? DM_UNITS_INCH : DM_UNITS_MM;
  GridPlan plan;
  const bool planned = plan_grid(stock, 0, 0, r.pitch_nm, &plan) == PlanError::kOk;
  if (planned) {
    r.grid_nx = plan.geo.nx;
    r.grid_ny = plan.geo.ny;
  }
  *out = r;
  return planned ? DM_OK : DM_E_GRID;
}

dm_status dm_scan_tool_get(const dm_scan* scan, int32_t k, dm_scan_tool* out) {
  if (!live(scan) || !out) return DM_E_ARGUMENT;
  if (scan->state != DM_DONE) return DM_E_STATE;
  const ProgramScan& s = scan->scan;
  if (k < 0 || k >= s.ntools) return DM_E_INDEX;
  const Tool& t = s.tools[k];
  *out = dm_scan_tool{s.numbers[k], static_cast<int32_t>(t.kind), t.diameter_nm, s.first_lines[k], s.last_lines[k]};
  return DM_OK;
}

dm_status dm_scan_apply(const dm_scan* scan, dm_job* job) {
  if (!job) return DM_E_ARGUMENT;
  dm_scan_result r;
  if (!live(scan)) return DM_E_ARGUMENT;
  if (scan->state != DM_DONE) return DM_E_STATE;
  const bool no_stock = box_empty(job->stock), no_grid = !job->pitch_nm && !job->grid_nx && !job->grid_ny;
  if (no_stock) {
    const dm_status s = dm_scan_get_result(scan, &r);
    if (s != DM_OK && s != DM_E_GRID) return s;
    job->stock = r.stock;
  }
  if (!no_grid) return DM_OK;
  const StockBox stock{PointNm{job->stock.lo_nm[0], job->stock.lo_nm[1], job->stock.lo_nm[2]},
                       PointNm{job->stock.hi_nm[0], job->stock.hi_nm[1], job->stock.hi_nm[2]}};
  job->pitch_nm = scan_default_pitch_nm(scan->scan, stock);
  return DM_OK;
}

void dm_scan_destroy(dm_scan* scan) {
  if (!live(scan)) return;
  scan->tag = 0;  // what the pass holds needs no ending (core/ has no heap): the memory is the caller's again
}

}  // extern "C"
