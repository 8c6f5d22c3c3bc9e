// The engine tests' harness; see sim_util.h.
#include "tests/sim_util.h"

#include <cstdio>
#include <cstring>

#include "core/gcode/messages.h"
#include "core/math/decimal.h"
#include "core/tool/spec.h"
#include "platform/input/gcode_file.h"
#include "platform/report/report_json.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tools/cli/cli.h"
#include "tools/run/run_stock.h"

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

std::string seventy_rapids() {
  std::string text = "G21 G90\nM3 S1000\nG0 X-5 Y2 Z5\nG0 Z-1\n";
  for (int k = 0; k < 70; ++k) {
    char line[64];
    std::snprintf(line, sizeof line, "G0 X%d Y%.1f\n", k % 2 ? -5 : 45, 2 + 0.5 * k);
    text += line;
  }
  text += "G0 Z5\nM2\n";
  return text;
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

SimState Engine::run(LineInput* in, const SimBudget& b, bool sync_each_step) { return run_lines(sim, in, b, sync_each_step); }

SimState run_lines(Simulation* sim, LineInput* in, const SimBudget& b, bool sync_each_step) {
  sim->read_from(in);
  while (sim->step(b) == SimState::kReady)
    if (sync_each_step) sim->sync();
  sim->finish();
  return sim->state();
}

Run::Run() { o.job.tool = sim_test::tool("flat:6"); }

Run& Run::stock(const char* mm) {
  const StockBox b = stock_box(mm);
  const int64_t v[6] = {b.lo.x_nm, b.lo.y_nm, b.lo.z_nm, b.hi.x_nm, b.hi.y_nm, b.hi.z_nm};
  for (int k = 0; k < 6; ++k) o.job.stock_nm[k] = v[k];
  o.job.have_stock = true;
  return *this;
}
Run& Run::stock_stl(const std::string& path) {
  o.job.stock_stl = path;
  return *this;
}
Run& Run::pitch(const char* mm) {
  o.job.pitch_nm = nm(mm);
  return *this;
}
Run& Run::grid(int32_t nx, int32_t ny) {
  o.job.grid_nx = nx;
  o.job.grid_ny = ny;
  return *this;
}
Run& Run::tool(const char* spec) {
  o.job.tool = sim_test::tool(spec);
  o.job.tool_text = spec;
  o.job.tool_given = true;
  return *this;
}
Run& Run::tools(const std::string& path) {
  o.job.read.tools_file = path;
  return *this;
}
Run& Run::inch() {
  o.job.read.inch = true;
  return *this;
}
Run& Run::material(const std::string& what) {
  o.job.material = what;
  return *this;
}
Run& Run::design(const std::string& what) {
  // As the option reads it: a mesh, a height image, else a built-in part.
  auto ends = [&what](const char* e) {
    const size_t n = std::strlen(e);
    return what.size() >= n && what.compare(what.size() - n, n, e) == 0;
  };
  o.job.design_pgm = ends(".pgm");
  o.job.builtin = ends(".stl") || ends(".pgm") ? nullptr : builtin_design_find(what.c_str());
  CHECK(ends(".stl") || ends(".pgm") || o.job.builtin);
  o.job.design = o.job.builtin ? "(built-in part " + what + ")" : what;
  return *this;
}
Run& Run::design_z(const char* low_mm, const char* high_mm) {
  o.job.design_z_nm[0] = nm(low_mm);
  o.job.design_z_nm[1] = nm(high_mm);
  o.job.have_design_z = true;
  return *this;
}
Run& Run::tolerance_box(const char* x0, const char* y0, const char* x1, const char* y1, const char* tol) {
  o.job.tolerance_boxes.push_back(ToleranceBox{nm(x0), nm(y0), nm(x1), nm(y1), nm(tol)});
  return *this;
}
Run& Run::check_all() {
  cli::SafetyChoice& c = o.job.checks;
  c.rapid = c.spindle = c.below = c.shank = c.holder = c.plunge = true;
  return *this;
}
Run& Run::table(const char* z_mm) {
  o.job.checks.has_table = true;
  o.job.checks.table_nm = nm(z_mm);
  return *this;
}
Run& Run::fixture(const char* mm) {
  const StockBox b = stock_box(mm);
  o.job.checks.fixtures.push_back(BoxNm{b.lo, b.hi});
  return *this;
}
Run& Run::provenance() {
  o.view.color = cli::ViewOptions::Color::kTool;  // what turns it on in `dexmill run`
  return *this;
}

bool Run::program(const std::string& path, const SimBudget& b, bool sync_each_step) {
  o.job.file = path;
  setup_.reset(new cli::RunSetup());
  setup_->print = false;
  if (!CHECK_EQ(cli::run_setup(&o, setup_.get()), int(cli::kExitOk))) return false;
  sim().set_observer(observer);
  sim().set_body_fast(body_fast);
  GcodeFile in;
  if (!CHECK(in.open(setup_->read_path.c_str()))) return false;
  run_lines(&sim(), &in, b, sync_each_step);
  return true;
}

bool same_events(const SafetyWatch& a, const SafetyWatch& b) {
  if (a.total != b.total || a.nevents != b.nevents || a.rapid_removed_lsb != b.rapid_removed_lsb) return false;
  for (size_t k = 0; k < a.nevents; ++k) {
    const SafetyEvent &x = a.events[k], &y = b.events[k];
    if (x.kind != y.kind || x.line != y.line || x.at.x_nm != y.at.x_nm || x.at.y_nm != y.at.y_nm ||
        x.at.z_nm != y.at.z_nm || x.removed_lsb != y.removed_lsb || x.depth_nm != y.depth_nm ||
        x.columns != y.columns || x.last_line != y.last_line)
      return false;
  }
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

std::string Run::message(const ProcessViolation& v) { return cli::process_violation_text(v, *setup_->material.comp); }

std::string Run::assessment() {
  const GougeWatch* w = sim().gouges();
  if (!CHECK(w != nullptr)) return "";
  cli::assess_design(*w, sim().grid(), &setup_->design);
  RunReport rep;
  rep.lsb_nm = sim().grid().lsb_nm;
  rep.pitch_nm = sim().grid().pitch_nm;
  rep.have_assessment = true;
  rep.assessment = setup_->design.report;
  return run_cli::assessment_of(report_json_text(rep));
}

}  // namespace sim_test
