#include "tools/run/run_material.h"

#include <sys/stat.h>

#include <cstdio>

#include "core/material/material_preset.h"
#include "platform/format/material_file.h"
#include "platform/input/warning_fold.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

namespace {

std::string mm_per_min(int64_t nm_per_min) {
  char b[48];
  std::snprintf(b, sizeof b, "%lld", static_cast<long long>((nm_per_min + kNmPerMm / 2) / kNmPerMm));
  return b;
}

}  // namespace

int material_start(RunMaterial* m, const std::string& what, const BoxNm& stock) {
  m->comp.reset(new StockComposition());
  if (material_preset(what.c_str(), stock, m->comp.get())) {
    m->source = "preset " + what;
  } else {
    struct stat st;
    if (stat(what.c_str(), &st) != 0) {
      std::string names;
      for (int32_t k = 0; k < material_preset_count(); ++k) names += std::string(k ? ", " : "") + material_preset_name(k);
      return fail(kExitUsage, "--material '%s' is neither a preset (%s) nor a file", what.c_str(), names.c_str());
    }
    std::string err;
    const MaterialLoad load = material_file_load(what, stock, m->comp.get(), &err);
    if (load != MaterialLoad::kOk) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return load == MaterialLoad::kIoError ? kExitIo : kExitInput;
    }
    m->source = what;
  }
  return kExitOk;
}

std::string process_violation_text(const ProcessViolation& v, const StockComposition& c) {
  const Material& mat = c.materials[v.material];
  const MaterialProcess& p = mat.process;
  const std::string name = mat.name;
  switch (v.rule) {
    case ProcessRule::kFeed:
      return "feed " + mm_per_min(v.value) + " mm/min over " + name + "'s limit " + mm_per_min(p.max_feed_nm_per_min) +
             " mm/min";
    case ProcessRule::kSpindle:
      return "spindle " + std::to_string(v.value) + " rpm outside " + name + "'s range " +
             std::to_string(p.spindle_min_rpm) + ".." + std::to_string(p.spindle_max_rpm) + " rpm";
    case ProcessRule::kCoolant:
      return std::string("coolant on (") + ((v.value & 2) ? "M8" : "M7") + ") while cutting " + name + ", which forbids it";
  }
  return "";
}

void material_print(const RunMaterial& m, const ProcessWatch& w, const std::string& file) {
  {
    WarningFold fold;  // one spindle speed out of range is one line, not one per line cut
    for (size_t k = 0; k < w.nkept; ++k) fold.add(file, w.kept[k].line, 1, process_violation_text(w.kept[k], *m.comp));
  }
  if (w.total > w.nkept)
    std::fprintf(stderr, "%s: warning: %llu more process rule violations not listed\n", file.c_str(),
                 static_cast<unsigned long long>(w.total - w.nkept));
}

void material_to_report(const RunMaterial& m, const ProcessWatch& w, const DexelGrid<height_t>& g, RunReport* rep) {
  rep->have_materials = true;
  rep->material_source = m.source;
  rep->material_violations_total = w.total;
  for (int32_t k = 0; k < m.comp->material_count; ++k) {
    const Material& mat = m.comp->materials[k];
    const MaterialTally& t = w.tally[k];
    ReportMaterial r;
    r.name = mat.name;
    r.removed_mm3 = volume_mm3_text(t.removed_nm_columns, 1, g.pitch_nm);
    // mm^3 x mg/cm^3 / 1000 mm^3 per cm^3 / 1000 mg per g.
    r.mass_g = static_cast<double>(t.removed_nm_columns) * 1e-6 * (static_cast<double>(g.pitch_nm) * 1e-6) *
               (static_cast<double>(g.pitch_nm) * 1e-6) * mat.process.density_mg_per_cm3 * 1e-6;
    r.cut_time_s = static_cast<double>(t.cut_time_us) * 1e-6;
    r.violations = t.violations;
    rep->materials.push_back(r);
  }
  for (size_t k = 0; k < w.nkept; ++k) {
    const ProcessViolation& v = w.kept[k];
    rep->material_violations.push_back(ReportViolation{process_rule_name(v.rule), v.line, m.comp->materials[v.material].name,
                                                       process_violation_text(v, *m.comp)});
  }
}

}  // namespace cli
}  // namespace dexmill
