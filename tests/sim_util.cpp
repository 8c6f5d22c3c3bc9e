// The engine tests' harness; see sim_util.h.
#include "tests/sim_util.h"

#include <cstring>

#include "core/gcode/messages.h"
#include "core/math/decimal.h"
#include "core/tool/spec.h"
#include "platform/gcode_file.h"
#include "platform/report_json.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tools/cli.h"
#include "tools/run_stock.h"

namespace sim_test {

using namespace dexmill;

int64_t nm(const char* mm) {
  Decimal d;
  size_t pos = 0;
  const size_t n = std::strlen(mm);
  const bool ok = decimal_parse(mm, n, &pos, &d) == DecimalParse::kOk && pos == n;
  CHECK(ok);
  return ok ? decimal_to_nm(d, false) : 0;
}

StockBox stock_box(const char* mm) {
  int64_t v[6] = {};
  const char* at = mm;
  for (int k = 0; k < 6; ++k) {
    const char* end = std::strchr(at, ',');
    const std::string part = end ? std::string(at, end) : std::string(at);
    v[k] = nm(part.c_str());
    CHECK(k == 5 ? end == nullptr : end != nullptr);
    if (!end) break;
    at = end + 1;
  }
  return StockBox{PointNm{v[0], v[1], v[2]}, PointNm{v[3], v[4], v[5]}};
}

Tool tool(const char* spec) {
  Tool t;
  CHECK(tool_spec_parse(spec, std::strlen(spec), &t) == ToolSpecError::kOk);
  return t;
}

std::string run_file(const char* name) { return std::string(t::tests_dir()) + "/run/" + name; }

SimJob box_job(int64_t x0, int64_t y0, int64_t z0, int64_t x1, int64_t y1, int64_t pitch_nm, const char* spec) {
  SimJob j;
  const StockBox box{PointNm{x0, y0, z0}, PointNm{x1, y1, 0}};
  CHECK(plan_grid(box, 0, 0, pitch_nm, &j.plan) == PlanError::kOk);
  j.tool = tool(spec);
  j.input_buffer_bytes = LineReader::kStartBytes;
  return j;
}

Engine::Engine(const SimJob& j) {
  SimSetup why;
  const size_t n = sim_required_bytes(j, &why);
  CHECK(n > 0);
  mem.assign(n / 8 + 1, 0);
  sim = sim_create(j, mem.data(), mem.size() * 8, &why);
  CHECK(sim != nullptr);
}

SimState Engine::run(const std::string& text, size_t piece, const SimBudget& b) {
  size_t at = 0;
  SimState s = SimState::kReady;
  for (int guard = 0; guard < 10000000; ++guard) {
    s = sim->step(b);
    if (s == SimState::kNeedInput) {
      if (at >= text.size()) {
        sim->close_input();
      } else {
        const size_t n = std::min(piece, text.size() - at);
        sim->feed(text.data() + at, n);
        at += n;
      }
      continue;
    }
    if (s != SimState::kReady) break;
  }
  return s;
}

SimState Engine::run(LineInput* in, const SimBudget& b, bool sync_each_step) {
  sim->read_from(in);
  while (sim->step(b) == SimState::kReady)
    if (sync_each_step) sim->sync();
  sim->finish();
  return sim->state();
}

namespace {

// The first pass's diagnostics: counted, and the first error's line (where
// the cut stops, as `dexmill run` stops it).
struct ScanMessages final : GcodeMessages {
  uint32_t first_error_line = 0;
  void error(const GcodeDiag& d) override {
    if (!errors_++) first_error_line = d.line;
  }
  void warning(const GcodeDiag&) override { ++warnings_; }
};

}  // namespace

Run::Run() : o_(new cli::RunOptions()) { o_->tool = sim_test::tool("flat:6"); }

Run& Run::stock(const char* mm) {
  const StockBox b = stock_box(mm);
  const int64_t v[6] = {b.lo.x_nm, b.lo.y_nm, b.lo.z_nm, b.hi.x_nm, b.hi.y_nm, b.hi.z_nm};
  for (int k = 0; k < 6; ++k) o_->stock_nm[k] = v[k];
  o_->have_stock = true;
  return *this;
}
Run& Run::stock_stl(const std::string& path) {
  o_->stock_stl = path;
  return *this;
}
Run& Run::pitch(const char* mm) {
  o_->pitch_nm = nm(mm);
  return *this;
}
Run& Run::grid(int32_t nx, int32_t ny) {
  o_->grid_nx = nx;
  o_->grid_ny = ny;
  return *this;
}
Run& Run::tool(const char* spec) {
  o_->tool = sim_test::tool(spec);
  return *this;
}
Run& Run::tools(const std::string& path) {
  o_->read.tools_file = path;
  return *this;
}
Run& Run::inch() {
  o_->read.inch = true;
  return *this;
}
Run& Run::material(const std::string& what) {
  o_->material = what;
  return *this;
}
Run& Run::design(const std::string& what) {
  // As the option reads it: a mesh, a height image, else a built-in part.
  auto ends = [&what](const char* e) {
    const size_t n = std::strlen(e);
    return what.size() >= n && what.compare(what.size() - n, n, e) == 0;
  };
  o_->design_pgm = ends(".pgm");
  o_->builtin = ends(".stl") || ends(".pgm") ? nullptr : builtin_design_find(what.c_str());
  CHECK(ends(".stl") || ends(".pgm") || o_->builtin);
  o_->design = o_->builtin ? "(built-in part " + what + ")" : what;
  return *this;
}
Run& Run::design_z(const char* low_mm, const char* high_mm) {
  o_->design_z_nm[0] = nm(low_mm);
  o_->design_z_nm[1] = nm(high_mm);
  o_->have_design_z = true;
  return *this;
}
Run& Run::tolerance_box(const char* x0, const char* y0, const char* x1, const char* y1, const char* tol) {
  o_->tolerance_boxes.push_back(ToleranceBox{nm(x0), nm(y0), nm(x1), nm(y1), nm(tol)});
  return *this;
}

Run& Run::check_all() {
  job.checks.rapid = job.checks.spindle = job.checks.below = true;
  job.checks.shank = job.checks.holder = job.checks.plunge = true;
  return *this;
}
Run& Run::table(const char* z_mm) {
  job.checks.has_table = true;
  job.checks.table_nm = nm(z_mm);
  return *this;
}
Run& Run::fixture(const char* mm) {
  const StockBox b = stock_box(mm);
  o_->checks.fixtures.push_back(BoxNm{b.lo, b.hi});
  return *this;
}

bool Run::program(const std::string& path, const SimBudget& b, bool sync_each_step) {
  const cli::RunOptions& o = *o_;
  job.tool = o.tool;
  job.inch = o.read.inch;
  if (!o.read.tools_file.empty()) {
    table_.reset(new ToolTableFile());
    if (!CHECK(table_->load(o.read.tools_file.c_str(), o.read.inch) == ToolTableFile::Load::kOk)) return false;
    job.library = table_.get();
    job.offsets = table_.get();
  }
  // The first pass: the tools, the extents, the first bad block.
  scan_.reset(new ProgramScan(job));
  {
    GcodeFile file;
    if (!CHECK(file.open(path.c_str()))) return false;
    ScanMessages msgs;
    const std::unique_ptr<ProgramMemory> mem(new ProgramMemory());
    scan_->run(&file, &msgs, mem.get());
    scan_errors_ = msgs.errors() + (scan_->bad_tool_line ? 1 : 0);
    scan_warnings_ = msgs.warnings();
    job.stop_line = msgs.errors() ? msgs.first_error_line : scan_->bad_tool_line;
  }
  // The stock and its grid.
  StockBox box;
  if (!o.stock_stl.empty()) {
    if (!CHECK_EQ(cli::read_stock_stl(o.stock_stl, &blank_, &box), int(cli::kExitOk))) return false;
  } else if (o.have_stock) {
    box = StockBox{PointNm{o.stock_nm[0], o.stock_nm[1], o.stock_nm[2]}, PointNm{o.stock_nm[3], o.stock_nm[4], o.stock_nm[5]}};
  } else {
    box = default_stock(scan_->summary, scan_->max_radius_nm);
  }
  int64_t pitch_nm = o.pitch_nm;
  if (!pitch_nm && !o.grid_nx) pitch_nm = default_pitch_nm(box, scan_->smallest_diameter_nm());
  if (!CHECK(plan_grid(box, o.grid_nx, o.grid_ny, pitch_nm, &job.plan) == PlanError::kOk)) return false;
  // The tools the program loads, the observers its inputs ask for.
  tools_.assign(scan_->tools + 1, scan_->tools + scan_->ntools);
  job.tools = tools_.data();
  job.ntools = static_cast<int>(tools_.size());
  if (!o.design.empty()) {
    if (!CHECK_EQ(cli::load_design(o, job.plan, path, &design_), int(cli::kExitOk))) return false;
    job.design = &design_.grid;
    job.assess = design_.opt;
  }
  job.checks.fixtures = o.checks.fixtures.data();
  job.checks.nfixtures = static_cast<int>(o.checks.fixtures.size());
  sim_checks_for_tools(&job.checks, scan_->tools, scan_->ntools);
  if (!o.material.empty()) {
    const BoxNm stock{job.plan.stock.lo, job.plan.stock.hi};
    if (!CHECK_EQ(cli::material_start(&material_, o.material, stock), int(cli::kExitOk))) return false;
    job.material = material_.comp.get();
  }
  // The cut.
  engine_.reset(new Engine(job));
  if (!engine_->sim) return false;
  if (!blank_.empty() && !CHECK_EQ(cli::carve_stock(&sim().grid(), job.plan, blank_), int(cli::kExitOk))) return false;
  sim().set_observer(observer);
  sim().start();
  GcodeFile in;
  if (!CHECK(in.open(path.c_str()))) return false;
  engine_->run(&in, b, sync_each_step);
  return true;
}

bool Run::text(const char* name, const std::string& text, const SimBudget& b, bool sync_each_step) {
  // Apart from the files the CLI tests write to the same folder.
  return program(run_cli::write_tmp(("sim-" + std::string(name)).c_str(), text.c_str()), b, sync_each_step);
}

std::string Run::removed_mm3() {
  const DexelGrid<height_t>& g = sim().grid();
  return volume_mm3_text(sim().removed_lsb(), g.lsb_nm, g.pitch_nm);
}

std::vector<SafetyEvent> Run::events(SafetyKind k) {
  std::vector<SafetyEvent> out;
  const SafetyWatch* w = sim().safety();
  if (!CHECK(w != nullptr)) return out;
  for (size_t n = 0; n < w->nevents; ++n)
    if (w->events[n].kind == k) out.push_back(w->events[n]);
  return out;
}

std::string Run::message(const SafetyEvent& e) {
  const DexelGrid<height_t>& g = sim().grid();
  return safety_event_text(e, g.lsb_nm, g.pitch_nm);
}

std::vector<ProcessViolation> Run::violations(ProcessRule r) {
  std::vector<ProcessViolation> out;
  const ProcessWatch* w = sim().process();
  if (!CHECK(w != nullptr)) return out;
  for (size_t n = 0; n < w->nkept; ++n)
    if (w->kept[n].rule == r) out.push_back(w->kept[n]);
  return out;
}

std::string Run::message(const ProcessViolation& v) { return cli::process_violation_text(v, *material_.comp); }

std::string Run::assessment() {
  const GougeWatch* w = sim().gouges();
  if (!CHECK(w != nullptr)) return "";
  cli::assess_design(*w, sim().grid(), &design_);
  RunReport rep;
  rep.lsb_nm = sim().grid().lsb_nm;
  rep.pitch_nm = sim().grid().pitch_nm;
  rep.have_assessment = true;
  rep.assessment = design_.report;
  return run_cli::assessment_of(report_json_text(rep));
}

}  // namespace sim_test
