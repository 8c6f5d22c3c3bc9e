// The sheet's sections (see sheet_html.h): each a <section> of the page,
// every figure the report's text with its unit.
#include <string>
#include <vector>

#include "core/safety/safety.h"
#include "platform/report/report_json.h"
#include "platform/report/sheet_html.h"

namespace dexmill {
namespace sheet_detail {
namespace {

constexpr size_t kListed = 5;  // findings listed per kind; the rest counted

std::string u64(uint64_t v) { return std::to_string(v); }

std::string mm(int64_t nm, int decimals = 3) { return nm_to_mm_text(nm, decimals) + "&nbsp;mm"; }

std::string where(const RunReport& r, uint32_t line) {
  return "<span class=\"at\">" + html(r.file) + ":" + u64(line) + "</span>";
}

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  std::string o = "<tr>";
  for (const std::string& c : cells) o += std::string("<") + tag + ">" + c + "</" + tag + ">";
  return o + "</tr>\n";
}

// A maximum's name without "max_", its underscores as spaces.
std::string peak_name(const std::string& key) {
  std::string s = key.compare(0, 4, "max_") == 0 ? key.substr(4) : key;
  for (char& c : s)
    if (c == '_') c = ' ';
  return s;
}

// A report unit key as a unit: "w" W, "n" N, "n_m" N·m, "mm3_per_min" mm³/min.
std::string unit_text(const std::string& key) {
  static const char* const kUnits[][2] = {{"w", "W"}, {"n", "N"}, {"n_m", "N\xc2\xb7m"}, {"mm3_per_min", "mm\xc2\xb3/min"},
                                          {"deg", "\xc2\xb0"}};
  for (const auto& u : kUnits)
    if (key == u[0]) return u[1];
  return key;
}

// A finding's row: FILE:LINE, then what it is.
std::string finding(const RunReport& r, uint32_t line, const std::string& message) {
  return "<tr><td>" + where(r, line) + " " + html(message) + "</td></tr>\n";
}

std::string head(const char* title) { return std::string("<section><h2>") + title + "</h2>\n"; }

// A finding list: the first kListed rows, then how many more there are.
std::string finding_rows(const std::vector<std::string>& rows, uint64_t total) {
  std::string o;
  for (size_t k = 0; k < rows.size() && k < kListed; ++k) o += rows[k];
  const uint64_t shown = rows.size() < kListed ? rows.size() : kListed;
  if (total > shown) o += "<tr><td class=\"more\">and " + u64(total - shown) + " more</td></tr>\n";
  return o;
}

std::string figure(const SheetPicture& p, const char* what) {
  if (p.png.empty()) return "<figure class=\"view none\"><div class=\"nopic\">" + std::string(what) + "</div></figure>";
  return "<figure class=\"view\">" + img_png(p.png, p.caption, "view") + "<figcaption>" + html(p.caption) +
         "</figcaption></figure>";
}

}  // namespace

std::string part_section(const RunReport& r, const SheetImages& im) {
  std::string o = "<section class=\"part\"><div class=\"views\">";
  o += figure(im.iso, "no iso view");
  o += figure(im.top, "no top view");
  o += figure(im.error, r.have_assessment ? "no error view" : "no design given (--design): no error view");
  return o + "</div></section>\n";
}

std::string program_section(const RunReport& r) {
  std::string o = head("Program and setups");
  o += "<table class=\"programs\"><tr><th>#</th><th>program</th><th>setup</th><th>moves</th><th>time</th><th>removed</th></tr>\n";
  if (r.have_chain) {
    for (size_t k = 0; k < r.chain.size(); ++k) {
      const RunReport::ChainProgram& c = r.chain[k];
      o += row({u64(k + 1), html(c.file), html(c.setup), u64(c.moves), seconds_text(c.estimated_us, false),
                volume_mm3_text(c.removed_lsb_dexels, r.lsb_nm, r.pitch_nm) + "&nbsp;mm³"});
    }
  } else {
    o += row({"1", html(r.file), "none", u64(r.rapid + r.feed + r.arc), seconds_text(r.estimated_us, false),
              volume_mm3_text(r.removed_lsb_dexels, r.lsb_nm, r.pitch_nm) + "&nbsp;mm³"});
  }
  o += "</table>\n<p class=\"facts\">";
  auto span = [](const char* axis, int64_t lo, int64_t hi) {
    return std::string(axis) + nm_to_mm_text(lo, 3) + ".." + nm_to_mm_text(hi, 3);
  };
  if (r.have_stock)
    o += "stock " + span("X", r.stock_lo.x_nm, r.stock_hi.x_nm) + " " + span("Y", r.stock_lo.y_nm, r.stock_hi.y_nm) +
         " " + span("Z", r.stock_lo.z_nm, r.stock_hi.z_nm) + "&nbsp;mm (" + html(r.stock_source) + ") · ";
  o += "grid " + u64(static_cast<uint64_t>(r.nx)) + " × " + u64(static_cast<uint64_t>(r.ny)) + " at " + mm(r.pitch_nm, 4) +
       ", " + html(r.mode) + " · " + u64(r.lines) + " blocks run, " + r.units;
  if (r.have_materials) {
    o += " · material " + html(r.material_source) + ":";
    for (const ReportMaterial& m : r.materials) o += " " + html(m.name) + " " + html(m.removed_mm3) + "&nbsp;mm³";
  }
  if (r.have_machine) o += " · machine " + html(r.machine.file) + " (" + html(r.machine.kind) + ")";
  return o + "</p></section>\n";
}

std::string tools_section(const RunReport& r) {
  std::string o = head("Tools");
  o += "<table><tr><th>tool</th><th>spec</th><th>stick-out</th><th>lines</th><th>from</th></tr>\n";
  for (const ReportToolUse& u : r.tools_used) {
    const std::string lines = u.last_line ? u64(u.first_line) + "–" + u64(u.last_line) : std::string("no cut");
    o += row({u.number < 0 ? std::string("first") : "T" + std::to_string(u.number), "<code>" + html(u.spec) + "</code>",
              mm(u.stick_out_nm, 2), lines,
              html(u.source.empty() ? std::string("-") : u.source) + (u.line ? " (line " + u64(u.line) + ")" : "")});
  }
  if (r.tools_used.empty()) o += "<tr><td colspan=\"5\">" + html(r.default_tool) + " (the default tool)</td></tr>\n";
  return o + "</table></section>\n";
}

std::string time_section(const RunReport& r) {
  std::string o = head("Time estimate");
  o += "<p class=\"facts\"><b>total " + seconds_text(r.estimated_us) + "</b> · feed " + seconds_text(r.feed_us) +
       " · rapid " + seconds_text(r.rapid_us) + " · dwell " + seconds_text(r.dwell_us) + " · rapids at " +
       nm_to_mm_text(r.rapid_nm_per_min, 0) + "&nbsp;mm/min" +
       (r.accel_nm_per_s2 ? ", accel " + nm_to_mm_text(r.accel_nm_per_s2, 0) + "&nbsp;mm/s²" : std::string(", no acceleration")) +
       "</p>\n";
  if (r.stop_us || r.blended_us)  // the three estimates (core/canon/summary.h), when the run made them
    o += "<p class=\"facts\">no acceleration " + seconds_text(r.no_accel_us, false) + " · from rest at every move " +
         seconds_text(r.stop_us, false) + " · blended " + seconds_text(r.blended_us, false) +
         (r.path_tolerance_nm >= 0 ? " (path tolerance " + nm_to_mm_text(r.path_tolerance_nm, 3) + "&nbsp;mm)" : std::string()) +
         "</p>\n";
  if (r.time_by_tool.empty()) o += "<p class=\"note\">by tool: not estimated</p>\n";
  else o += time_bars_svg(r) + "<p class=\"note\">dark: feed, light: rapid</p>\n";
  return o + "</section>\n";
}

std::string assessment_section(const RunReport& r, const SheetImages& im) {
  std::string o = head("Against the design");
  if (!r.have_assessment) return o + "<p class=\"note\">no design given (--design): no error view, no assessment</p></section>\n";
  const ReportAssessment& a = r.assessment;
  const AssessmentTexts t = assessment_texts(r);
  o += "<div class=\"cols\"><div><table class=\"kv\">\n";
  o += row({"design", html(a.file) + " (" + html(a.kind) + ")"});
  o += row({"tolerance", nm_to_mm_text(a.tolerance_nm, 4) + "&nbsp;mm" +
                             (a.tolerance_boxes ? ", " + u64(a.tolerance_boxes) + " boxes" : std::string())});
  o += row({"within tolerance", t.within_percent.empty() ? "-" : t.within_percent + "&nbsp;% of the columns"});
  o += row({"rms of cut - design", t.rms_mm + "&nbsp;mm"});
  o += row({"deepest gouge", t.max_gouge_mm.empty() ? "none" : t.max_gouge_mm + "&nbsp;mm at X" +
                                 nm_to_mm_text(a.max_gouge_at.x_nm, 3) + " Y" + nm_to_mm_text(a.max_gouge_at.y_nm, 3)});
  o += row({"most material left", t.max_leftover_mm.empty() ? "none" : t.max_leftover_mm + "&nbsp;mm at X" +
                                      nm_to_mm_text(a.max_leftover_at.x_nm, 3) + " Y" +
                                      nm_to_mm_text(a.max_leftover_at.y_nm, 3)});
  o += row({"gouged", t.gouged_area_mm2 + "&nbsp;mm², " + t.gouged_volume_mm3 + "&nbsp;mm³"});
  o += row({"left", t.leftover_area_mm2 + "&nbsp;mm², " + t.leftover_volume_mm3 + "&nbsp;mm³"});
  o += row({"lines that gouged", u64(a.gouges_total)});
  o += "</table></div><div>" + histogram_svg(a.result) + "</div></div>\n";
  const std::vector<size_t> worst = sheet_worst_gouges(a);
  if (worst.empty()) return o + "</section>\n";
  o += "<h3>The worst gouges</h3><div class=\"crops\">\n";
  for (size_t k = 0; k < worst.size(); ++k) {
    const ReportGouge& g = a.gouges[worst[k]];
    o += "<figure class=\"crop\">";
    if (k < im.crops.size() && !im.crops[k].png.empty()) o += img_png(im.crops[k].png, im.crops[k].caption, "crop");
    o += "<figcaption>" + where(r, g.line) + "<br>" + mm(g.depth_nm, 4) + " deep<br>X" + nm_to_mm_text(g.at.x_nm, 3) +
         " Y" + nm_to_mm_text(g.at.y_nm, 3) + " Z" + nm_to_mm_text(g.at.z_nm, 3) + "&nbsp;mm</figcaption></figure>\n";
  }
  return o + "</div></section>\n";
}

std::string findings_section(const RunReport& r) {
  std::string o = head("Collisions, travel, rules, load");
  o += "<table class=\"findings\">\n";
  auto group = [&o](const char* title, bool ran, const char* how, const std::vector<std::string>& rows, uint64_t total) {
    o += "<tr><th>" + std::string(title) + ": " +
         (!ran ? std::string("not checked (") + how + ")" : total ? u64(total) : std::string("none")) + "</th></tr>\n";
    if (ran) o += finding_rows(rows, total);
  };
  std::vector<std::string> rows;
  for (const SafetyEvent& e : r.collisions) rows.push_back(finding(r, e.line, safety_event_text(e, r.lsb_nm, r.pitch_nm)));
  group("collisions", r.have_collisions, "--check", rows, r.collisions_total);
  rows.clear();
  for (const ReportMachine::Finding& f : r.machine.findings) rows.push_back(finding(r, f.line, f.message));
  group("travel", r.have_machine && r.machine.have_travel, "--machine", rows, r.machine.travel_total);
  rows.clear();
  for (const ReportViolation& v : r.material_violations)
    rows.push_back(finding(r, v.line, v.rule + ": " + v.message));
  group("process rules", r.have_materials, "--material", rows, r.material_violations_total);
  rows.clear();
  for (const ReportLoad::Finding& f : r.load.kept) rows.push_back(finding(r, f.line, f.message));  // the message names the rule
  group("load", r.have_load, "--check load", rows, r.load.total);
  rows.clear();
  for (const ReportDiag& d : r.errors) rows.push_back(finding(r, d.line, d.message));
  if (!r.errors.empty()) group("input errors", true, "", rows, r.errors.size());
  return o + "</table></section>\n";
}

std::string load_section(const RunReport& r, const SheetImages& im) {
  if (!r.have_engagement) return "";
  std::string o = head("Load peaks");
  const ReportEngageSet& p = r.engagement.program;
  o += "<p class=\"facts\">" + u64(p.moves) + " feed moves measured, " + u64(p.engaged) + " in material" +
       (p.no_spindle_speed ? ", " + u64(p.no_spindle_speed) + " with no spindle speed (not measured)" : std::string()) +
       "</p>\n<table class=\"peaks\"><tr>";
  for (const ReportEngageMax& m : p.maxima) o += "<th>" + html(peak_name(m.name)) + "</th>";
  o += "</tr><tr>";
  for (const ReportEngageMax& m : p.maxima) o += "<td>" + html(m.value) + "&nbsp;" + html(unit_text(m.unit)) + "</td>";
  o += "</tr><tr>";
  for (const ReportEngageMax& m : p.maxima) o += "<td>" + (m.line ? "line " + u64(m.line) : std::string("-")) + "</td>";
  o += "</tr></table>\n";
  if (!im.load_plot_svg.empty()) {
    std::string svg = im.load_plot_svg;  // inline: without the XML declaration
    if (svg.compare(0, 5, "<?xml") == 0) svg.erase(0, svg.find('\n') + 1);
    o += "<div class=\"plot\">" + svg + "</div>\n";
  }
  return o + "</section>\n";
}

}  // namespace sheet_detail
}  // namespace dexmill
