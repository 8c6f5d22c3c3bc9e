#include "platform/report/report_summary.h"

#include <cinttypes>
#include <cstdio>

#include "platform/report/report_json.h"  // the numbers as text

namespace dexmill {

namespace {

std::string hms(int64_t us) {
  const int64_t s = (us + 500000) / 1000000;
  char b[64];
  std::snprintf(b, sizeof b, "%" PRId64 ":%02" PRId64 ":%02" PRId64, s / 3600, s / 60 % 60, s % 60);
  return b;
}

std::string range(int64_t lo_nm, int64_t hi_nm) { return nm_to_mm_text(lo_nm, 3) + ".." + nm_to_mm_text(hi_nm, 3); }

}  // namespace

std::string report_summary_text(const RunReport& r) {
  char b[512];
  std::string o;
  // Blocks run, not the file's lines: a loop's or a subroutine's lines count
  // each time they run (a 780-line file can run 63704 blocks).
  std::snprintf(b, sizeof b, "%s: %u blocks run, %s; %" PRIu64 " rapids, %" PRIu64 " feeds, %" PRIu64 " arcs, %" PRIu64
                " tool changes\n", r.file.c_str(), r.lines, r.units, r.rapid, r.feed, r.arc, r.tool_change);
  o += b;
  if (r.have_stock) {
    o += "stock    X" + range(r.stock_lo.x_nm, r.stock_hi.x_nm) + " Y" + range(r.stock_lo.y_nm, r.stock_hi.y_nm) + " Z" +
         range(r.stock_lo.z_nm, r.stock_hi.z_nm) + " mm (" +
         (r.stock_source == "program" ? "from the program's moves; --stock to set it" : "from " + r.stock_source) +
         ")\n";
    std::snprintf(b, sizeof b, "grid     %d x %d dexels, pitch %s mm\n", r.nx, r.ny, nm_to_mm_text(r.pitch_nm, 4).c_str());
    o += b;
    o += "removed  " + volume_mm3_text(r.removed_lsb_dexels, r.lsb_nm, r.pitch_nm) + " mm^3\n";
    if (r.have_chain && r.chain.size() > 1) {
      o += "chain    " + std::to_string(r.chain.size()) + " programs on this stock: removed " +
           volume_mm3_text(r.chain_removed_lsb_dexels, r.lsb_nm, r.pitch_nm) + " mm^3, time " + hms(r.chain_us) + "\n";
      for (size_t k = 0; k < r.chain.size(); ++k) {  // each setup's share
        const RunReport::ChainProgram& p = r.chain[k];
        const std::string setup = p.setup != "none" ? "setup " + p.setup : k ? "setup unchanged" : "first setup";
        std::snprintf(b, sizeof b, "  %2zu     %s, %s: removed %s mm^3, time %s", k + 1, p.file.c_str(),
                      setup.c_str(), volume_mm3_text(p.removed_lsb_dexels, r.lsb_nm, r.pitch_nm).c_str(),
                      hms(p.estimated_us).c_str());
        o += b;
        if (p.have_findings) o += ", " + std::to_string(p.findings_total) + " finding(s)";
        o += "\n";
      }
    }
  }
  // What the estimate is: without an acceleration a lower bound (no
  // machine reaches F at once); with one, the blended estimate
  // (core/canon/motion_plan.h) between its two bounds.
  if (r.blended) {
    o += "time     " + hms(r.estimated_us) + " blended at corners (G64" +
         (r.path_tolerance_nm >= 0 ? " P up to " + nm_to_mm_text(r.path_tolerance_nm, 4) + " mm" : std::string()) +
         "), each axis within its velocity and acceleration" + (r.have_machine ? " (the machine's)" : "") + "\n";
    o += "         bounds: " + hms(r.no_accel_us) + " without acceleration, " + hms(r.stop_us) +
         " stopping at every move (rapids at " + nm_to_mm_text(r.rapid_nm_per_min, 0) + " mm/min, acceleration " +
         nm_to_mm_text(r.accel_nm_per_s2, r.accel_nm_per_s2 % 1000000 ? 3 : 0) + " mm/s^2)\n";
  } else {
    o += "time     " + hms(r.estimated_us) + " at programmed feeds, rapids at " + nm_to_mm_text(r.rapid_nm_per_min, 0) +
         " mm/min, no acceleration (a lower bound; --accel MM/S2 or --machine FILE for a machine's)\n";
  }
  if (r.have_machine) {  // the machine, what it gave and what the options kept
    const ReportMachine& m = r.machine;
    o += "machine  " + m.file + " (" + (m.kind == "grbl" ? "grbl" : "LinuxCNC") + "): travel";
    for (int a = 0; a < 3; ++a)
      o += std::string(" ") + "XYZ"[a] + (m.limited[a] ? m.min_mm[a] + ".." + m.max_mm[a] : std::string(" unlimited"));
    o += "\n";
    for (const std::string& d : m.said) o += "         " + d + "\n";
    if (m.have_travel) {
      std::snprintf(b, sizeof b, "travel   %" PRIu64 " move(s) past a soft limit%s\n", m.travel_total,
                    m.travel_total ? " (on standard error)" : "");
      o += b;
    }
  }
  if (r.have_assessment) {
    const ReportAssessment& a = r.assessment;
    std::snprintf(b, sizeof b, "design   %" PRIu64 " gouge(s)\n", static_cast<uint64_t>(a.gouges_total));
    o += b;
  }
  if (r.have_collisions) {
    std::snprintf(b, sizeof b, "safety   %" PRIu64 " finding(s)%s\n", r.collisions_total,
                  r.collisions_total ? " (on standard error)" : "");
    o += b;
  }
  if (r.have_materials) {  // the process rules' warnings are counted apart from the G-code's
    std::snprintf(b, sizeof b, "process  %" PRIu64 " rule violation(s)%s\n", r.material_violations_total,
                  r.material_violations_total ? " (on standard error)" : "");
    o += b;
  }
  if (!r.stopped_reason.empty()) {
    std::snprintf(b, sizeof b, "stopped  at the first %s, line %u\n", r.stopped_reason.c_str(), r.stopped_line);
    o += b;
  }
  // Every warning counted (as warnings_total and `dexmill check` count
  // them: a gate on the count must not pass because repeats were folded),
  // and how many distinct ones that is when the report kept them all.
  uint64_t kept = 0;
  for (const ReportDiag& w : r.warnings) kept += w.count;
  const std::string distinct = kept == r.warnings_total && r.warnings.size() < kept
                                   ? std::to_string(r.warnings.size()) + " distinct, "
                                   : std::string();
  std::snprintf(b, sizeof b, "warnings %" PRIu64 "%s\n", r.warnings_total,
                r.warnings_total ? (" (" + distinct + "on standard error)").c_str() : "");
  o += b;
  o += "Add --image out.png for a picture, --report out.json for all of it (dexmill run --help).\n";
  return o;
}

}  // namespace dexmill
