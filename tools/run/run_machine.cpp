// `--machine FILE`; see run_machine.h.
#include "tools/run/run_machine.h"

#include <cstdio>

#include "core/math/fixed.h"
#include "platform/input/warning_fold.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {
namespace {

const char kAxis[3] = {'X', 'Y', 'Z'};

std::string mm_text(int64_t nm) { return nm_to_mm_text(nm, 3); }

std::string finding_text(const TravelFinding& f, MachineKind kind) {
  const char* what = kind == MachineKind::kGrbl ? (f.above ? "0 (grbl's home)" : "-$13x travel")
                                                 : (f.above ? "MAX_LIMIT" : "MIN_LIMIT");
  char b[200];
  std::snprintf(b, sizeof b, "%c %s mm %s the machine's %s (machine %c %s, limit %s)", kAxis[f.axis],
                mm_text(f.excess_nm).c_str(), f.above ? "past" : "below", what, kAxis[f.axis], mm_text(f.at_nm).c_str(),
                mm_text(f.limit_nm).c_str());
  return b;
}

// The slowest of the axes' values that are given (0: none is).
int64_t slowest(const MachineSpec& s, bool accel) {
  int64_t v = 0;
  for (const MachineAxis& a : s.axis) {
    const int64_t x = accel ? a.max_accel_nm_per_s2 : a.max_velocity_nm_per_min;
    if (x > 0) v = v ? min_of(v, x) : x;
  }
  return v;
}

}  // namespace

int run_machine_load(RunOptions* o, RunMachine* m) {
  JobOptions& j = o->job;
  if (j.machine_file.empty()) return kExitOk;
  std::string err;
  const MachineLoad l = machine_file_load(j.machine_file, &m->file, &err);
  if (l != MachineLoad::kOk) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return l == MachineLoad::kIoError ? kExitIo : kExitInput;
  }
  const MachineSpec& s = m->file.spec;
  auto said = [m](const std::string& what, bool from_machine) {
    m->said.push_back(what + (from_machine ? " (the machine's)" : " (the option's, over the machine's)"));
  };
  if (!m->file.tool_table.empty()) {
    const bool use = j.read.tools_file.empty();
    if (use) j.read.tools_file = m->file.tool_table;
    said("tool table " + m->file.tool_table, use);
  }
  if (!m->file.subroutine_path.empty()) {
    const bool use = j.read.subroutine_path.empty();
    if (use)
      for (std::size_t at = 0; at <= m->file.subroutine_path.size();) {
        const std::size_t end = std::min(m->file.subroutine_path.find(':', at), m->file.subroutine_path.size());
        if (end > at) j.read.subroutine_path.push_back(m->file.subroutine_path.substr(at, end - at));
        at = end + 1;
      }
    said("subroutine path " + m->file.subroutine_path, use);
  }
  // grbl reads an F on a G20/G21 line in that line's units; LinuxCNC in
  // the units before it (core/interp/interp_modes.cpp).
  if (s.kind == MachineKind::kGrbl) j.read.feed_in_line_units = true;
  if (s.kind == MachineKind::kLinuxcnc) {  // the units a program starts in (grbl's $13 only reports)
    const bool use = !j.read.units_given;
    if (use) j.read.inch = s.inch, j.read.units_given = true;
    said(std::string("units ") + (s.inch ? "inch" : "mm"), use);
  }
  for (int a = 0; a < 3; ++a) {  // the blended estimate's, axis by axis
    if (!j.have_rapid) j.axes.velocity_nm_per_s[a] = s.axis[a].max_velocity_nm_per_min / 60;
    if (!j.have_accel) j.axes.accel_nm_per_s2[a] = s.axis[a].max_accel_nm_per_s2;
  }
  if (const int64_t v = slowest(s, false)) {
    if (!j.have_rapid) j.rapid_nm_per_min = v;
    said("rapid " + nm_to_mm_text(v, 0) + " mm/min (the slowest axis)", !j.have_rapid);
  }
  if (const int64_t a = slowest(s, true)) {
    if (!j.have_accel) j.accel_nm_per_s2 = a;
    said("acceleration " + nm_to_mm_text(a, 0) + " mm/s2 (the slowest axis)", !j.have_accel);
  }
  if (s.have_offsets) {
    const bool use = !j.have_work_offsets;
    if (use) {
      j.have_work_offsets = true;
      for (int c = 0; c < kMachineCoordSystems; ++c) j.work_offsets[c] = s.work_offset[c];
    }
    said("work offsets G54..G59.3", use);
    if (use) {  // and with them what else the controller holds at the start
      j.start_coord_system = s.coord_system;
      j.start_g92 = s.g92;
      j.start_tlo_nm = s.tlo_nm;
      static const char* const kSystem[kMachineCoordSystems] = {"G54", "G55", "G56", "G57", "G58", "G59",
                                                                "G59.1", "G59.2", "G59.3"};
      if (s.coord_system != 0) said(std::string(kSystem[s.coord_system % kMachineCoordSystems]) + " in force", true);
      if (!(s.g92 == PointNm{0, 0, 0})) said("a G92 offset", true);
      if (s.tlo_nm != 0) said("a G43.1 tool length offset of " + mm_text(s.tlo_nm) + " mm", true);
    }
  }
  return kExitOk;
}

void travel_print(const TravelWatch& w, const std::string& file) {
  {
    WarningFold fold;  // a pass beyond a limit is one line with its count, not one a move
    for (int32_t k = 0; k < w.nkept; ++k) fold.add(file, w.kept[k].line, 1, "travel: " + finding_text(w.kept[k], w.kind));
  }
  if (w.total > static_cast<uint64_t>(w.nkept))
    std::fprintf(stderr, "%s: warning: %llu more travel findings not listed\n", file.c_str(),
                 static_cast<unsigned long long>(w.total - static_cast<uint64_t>(w.nkept)));
}

void machine_to_report(const RunMachine& m, const std::string& path, const TravelWatch* w, RunReport* rep) {
  ReportMachine& r = rep->machine;
  rep->have_machine = true;
  r.file = path;
  r.kind = m.file.spec.kind == MachineKind::kGrbl ? "grbl" : "linuxcnc";
  for (int a = 0; a < 3; ++a) {
    const MachineAxis& ax = m.file.spec.axis[a];
    r.limited[a] = ax.limited;
    r.min_mm[a] = ax.limited ? mm_text(ax.min_nm) : "";
    r.max_mm[a] = ax.limited ? mm_text(ax.max_nm) : "";
  }
  r.said = m.said;
  r.have_travel = w != nullptr;
  if (!w) return;
  r.travel_total = w->total;
  r.findings.clear();
  for (int32_t k = 0; k < w->nkept; ++k) {
    const TravelFinding& f = w->kept[k];
    r.findings.push_back(ReportMachine::Finding{f.line, std::string(1, kAxis[f.axis]), f.above ? "max" : "min",
                                                mm_text(f.excess_nm), finding_text(f, w->kind)});
  }
}

}  // namespace cli
}  // namespace dexmill
