#include "platform/report/report_json.h"

#include <cstdio>

#include "core/math/fixed.h"
#include "platform/os/output_file.h"
#include "platform/report/verdict.h"

namespace dexmill {
namespace {

// Length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong
// forms, no surrogates, at most U+10FFFF), or 0.
std::size_t utf8_sequence(const std::string& s, std::size_t i) {
  const unsigned char c = static_cast<unsigned char>(s[i]);
  std::size_t n;
  uint32_t cp;
  if (c >= 0xc2 && c <= 0xdf) { n = 2; cp = c & 0x1fu; }
  else if (c >= 0xe0 && c <= 0xef) { n = 3; cp = c & 0x0fu; }
  else if (c >= 0xf0 && c <= 0xf4) { n = 4; cp = c & 0x07u; }
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const unsigned char t = static_cast<unsigned char>(s[i + k]);
    if ((t & 0xc0) != 0x80) return 0;
    cp = (cp << 6) | (t & 0x3fu);
  }
  if ((n == 3 && (cp < 0x800 || (cp >= 0xd800 && cp <= 0xdfff))) || (n == 4 && (cp < 0x10000 || cp > 0x10ffff))) return 0;
  return n;
}

// A JSON string. JSON text is Unicode: a byte that is not part of
// well-formed UTF-8 (a file name in Latin-1) is written as the code point
// of the same number, \u00XX, so the report stays valid JSON.
std::string quoted(const std::string& s) {
  std::string o = "\"";
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    char b[8];
    if (c == '"' || c == '\\') { o += '\\'; o += static_cast<char>(c); }
    else if (c == '\n') o += "\\n";
    else if (c == '\t') o += "\\t";
    else if (c < 0x20 || c == 0x7f) { std::snprintf(b, sizeof b, "\\u%04x", c); o += b; }
    else if (c < 0x80) o += static_cast<char>(c);
    else if (const std::size_t n = utf8_sequence(s, i)) { o.append(s, i, n); i += n - 1; }
    else { std::snprintf(b, sizeof b, "\\u%04x", c); o += b; }
  }
  return o + "\"";
}

std::string u64(uint64_t v) { return std::to_string(v); }

// A non-negative integer count of 10^-d units as "I.FFF".
std::string fixed_text(uint64_t units, int decimals, bool negative) {
  uint64_t p = 1;
  for (int k = 0; k < decimals; ++k) p *= 10;
  std::string f = std::to_string(units % p);
  while (static_cast<int>(f.size()) < decimals) f = "0" + f;
  return std::string(negative && units ? "-" : "") + std::to_string(units / p) + (decimals ? "." + f : "");
}

std::string point_mm(const PointNm& p) {
  return "[" + nm_to_mm_text(p.x_nm, 4) + ", " + nm_to_mm_text(p.y_nm, 4) + ", " + nm_to_mm_text(p.z_nm, 4) + "]";
}


void diags(std::string* o, const char* key, const std::vector<ReportDiag>& v) {
  *o += "  " + quoted(key) + ": [";
  for (std::size_t k = 0; k < v.size(); ++k) {
    *o += k ? ",\n    " : "\n    ";
    *o += "{\"line\": " + u64(v[k].line) + ", \"column\": " + u64(v[k].column) + ", \"message\": " + quoted(v[k].message);
    if (v[k].count > 1) *o += ", \"count\": " + u64(v[k].count) + ", \"last_line\": " + u64(v[k].last_line);
    *o += "}";
  }
  *o += v.empty() ? "],\n" : "\n  ],\n";
}

// A 128-bit count of 10^-d units as "I.FFF" (d <= 18).
std::string fixed_text_u128(unsigned __int128 units, int decimals) {
  std::string digits;
  do {
    digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(units % 10)));
    units /= 10;
  } while (units);
  while (static_cast<int>(digits.size()) <= decimals) digits.insert(digits.begin(), '0');
  if (!decimals) return digits;
  return digits.substr(0, digits.size() - decimals) + "." + digits.substr(digits.size() - decimals);
}

unsigned __int128 round_div(unsigned __int128 n, unsigned __int128 d) { return (n + d / 2) / d; }

// The chain of programs on this stock (core/stock/stock_file.h), this run last.
std::string chain_text(const RunReport& r) {
  std::string o = "  \"chain\": {\"programs\": [";
  for (size_t k = 0; k < r.chain.size(); ++k) {
    const RunReport::ChainProgram& p = r.chain[k];
    o += std::string(k ? "," : "") + "\n    {\"file\": " + quoted(p.file) + ", \"setup\": " + quoted(p.setup) +
         ", \"removed_mm3\": " + volume_mm3_text(p.removed_lsb_dexels, r.lsb_nm, r.pitch_nm) +
         ", \"estimated_time_s\": " + seconds_of_us(p.estimated_us) + ", \"moves\": " + u64(p.moves) +
         ", \"findings\": ";
    if (!p.have_findings) {
      o += "null}";
      continue;
    }
    o += "{\"total\": " + u64(p.findings_total) + ", \"kept\": [";
    for (size_t f = 0; f < p.findings.size(); ++f)
      o += std::string(f ? ",\n      " : "\n      ") + "{\"kind\": " + quoted(p.findings[f].kind) +
           ", \"line\": " + u64(p.findings[f].line) + ", \"message\": " + quoted(p.findings[f].message) + "}";
    o += "]}}";
  }
  if (!r.chain.empty()) o += "\n  ";
  o += "], \"removed_mm3\": " + volume_mm3_text(r.chain_removed_lsb_dexels, r.lsb_nm, r.pitch_nm) +
       ", \"estimated_time_s\": " + seconds_of_us(r.chain_us) + ", \"moves\": " + u64(r.chain_moves) + "},\n";
  return o;
}

}  // namespace

std::string seconds_of_us(int64_t us) { return fixed_text(static_cast<uint64_t>(div_round(max_of<int64_t>(us, 0), 1000)), 3, false); }

AssessmentTexts assessment_texts(const RunReport& rep) {
  const ReportAssessment& a = rep.assessment;
  const AssessResult& r = a.result;
  const unsigned __int128 lsb = static_cast<uint64_t>(rep.lsb_nm);
  const unsigned __int128 e_nm2 = ((static_cast<unsigned __int128>(r.e_lsb2.hi) << 64) | r.e_lsb2.lo) * lsb * lsb;
  const unsigned __int128 top_nm = static_cast<unsigned __int128>(r.sum_design_top_lsb) * lsb;
  const uint64_t n = r.design_columns;
  const int64_t rms_nm = n ? static_cast<int64_t>(isqrt_u128(U128{static_cast<uint64_t>(e_nm2 / n >> 64),
                                                                   static_cast<uint64_t>(e_nm2 / n)}))
                           : 0;
  auto area = [&](uint64_t columns) { return volume_mm3_text(columns, kNmPerMm, rep.pitch_nm); };
  auto volume = [&](uint64_t lsb_columns) { return volume_mm3_text(lsb_columns, rep.lsb_nm, rep.pitch_nm); };
  AssessmentTexts t;
  t.e_mm2 = fixed_text_u128(round_div(e_nm2, 1000000), 6);
  // E_rel in 1e-9 mm (pm): E nm^2 / sum nm = nm; x 1000 = pm.
  t.e_rel = top_nm ? fixed_text_u128(round_div(e_nm2 * 1000, top_nm), 9) : std::string("null");
  t.rms_mm = nm_to_mm_text(rms_nm, 4);
  if (r.max_gouge_lsb > 0) t.max_gouge_mm = nm_to_mm_text(r.max_gouge_lsb * rep.lsb_nm, 4);
  if (r.max_leftover_lsb > 0) t.max_leftover_mm = nm_to_mm_text(r.max_leftover_lsb * rep.lsb_nm, 4);
  t.gouged_area_mm2 = area(r.gouge_columns);
  t.gouged_volume_mm3 = volume(r.gouge_lsb);
  t.leftover_area_mm2 = area(r.leftover_columns);
  t.leftover_volume_mm3 = volume(r.leftover_lsb);
  if (n)
    t.within_percent =
        fixed_text(static_cast<uint64_t>(round_div(static_cast<unsigned __int128>(r.within_tol_columns) * 10000, n)), 2, false);
  t.outside_area_mm2 = area(r.outside_columns);
  t.outside_volume_mm3 = volume(r.outside_lsb);
  return t;
}

namespace {

std::string assessment_text(const RunReport& rep) {
  const ReportAssessment& a = rep.assessment;
  const AssessResult& r = a.result;
  const AssessmentTexts t = assessment_texts(rep);
  auto extreme = [&](const std::string& mm, const PointNm& at) {
    if (mm.empty()) return std::string("null");
    return "{\"mm\": " + mm + ", \"x_mm\": " + nm_to_mm_text(at.x_nm, 4) + ", \"y_mm\": " + nm_to_mm_text(at.y_nm, 4) + "}";
  };
  std::string o = "  \"assessment\": {\"design\": {\"file\": " + quoted(a.file) + ", \"kind\": " + quoted(a.kind) +
                  ", \"triangles\": " + u64(a.triangles) + ", \"columns\": " + u64(r.design_columns) + "},\n";
  o += "    \"tolerance_mm\": " + nm_to_mm_text(a.tolerance_nm, 4) + ", \"tolerance_boxes\": " + u64(a.tolerance_boxes) +
       ",\n";
  o += "    \"E_mm2\": " + t.e_mm2 + ", \"E_rel\": " + t.e_rel + ", \"rms_mm\": " + t.rms_mm + ",\n";
  o += "    \"max_gouge\": " + extreme(t.max_gouge_mm, a.max_gouge_at) + ", \"max_leftover\": " +
       extreme(t.max_leftover_mm, a.max_leftover_at) + ",\n";
  o += "    \"gouged\": {\"area_mm2\": " + t.gouged_area_mm2 + ", \"volume_mm3\": " + t.gouged_volume_mm3 +
       "}, \"leftover\": {\"area_mm2\": " + t.leftover_area_mm2 + ", \"volume_mm3\": " + t.leftover_volume_mm3 +
       "},\n";
  o += "    \"within_tolerance_percent\": " + (t.within_percent.empty() ? std::string("null") : t.within_percent) +
       ", \"outside_design\": {\"area_mm2\": " + t.outside_area_mm2 + ", \"volume_mm3\": " + t.outside_volume_mm3 +
       "},\n";
  o += "    \"histogram\": {\"edges_mm\": [";
  for (int k = 0; k < kAssessEdges; ++k) o += std::string(k ? ", " : "") + nm_to_mm_text(kAssessBinEdgesNm[k], 2);
  o += "], \"columns\": [";
  for (int k = 0; k < kAssessBins; ++k) o += std::string(k ? ", " : "") + u64(r.histogram[k]);
  o += "]},\n    \"gouges\": [";
  for (size_t k = 0; k < a.gouges.size(); ++k) {
    const ReportGouge& g = a.gouges[k];
    o += std::string(k ? ",\n      " : "\n      ") + "{\"line\": " + u64(g.line) + ", \"x_mm\": " + nm_to_mm_text(g.at.x_nm, 4) +
         ", \"y_mm\": " + nm_to_mm_text(g.at.y_nm, 4) + ", \"depth_mm\": " + nm_to_mm_text(g.depth_nm, 4) +
         ", \"design_z_mm\": " + nm_to_mm_text(g.at.z_nm, 4) + ", \"cut_z_mm\": " + nm_to_mm_text(g.at.z_nm - g.depth_nm, 4) +
         ", \"tool_mm\": " + point_mm(g.tool) + ", \"columns\": " + u64(g.columns) + "}";
  }
  o += std::string(a.gouges.empty() ? "" : "\n    ") + "], \"gouges_total\": " + u64(a.gouges_total) + "},\n";
  return o;
}

}  // namespace

std::string nm_to_mm_text(int64_t nm, int decimals) {
  int64_t scale = 1;
  for (int k = decimals; k < 6; ++k) scale *= 10;
  const int64_t v = div_round(nm, scale);
  return fixed_text(abs_u64(v), decimals, v < 0);
}

std::string volume_mm3_text(uint64_t removed_lsb, int64_t lsb_nm, int64_t pitch_nm) {
  // nm^3 = removed * lsb * pitch^2, in 128 bits; mm^3 x 1000 = nm^3 / 1e15.
  const U128 a = mul_wide_u64(removed_lsb, static_cast<uint64_t>(lsb_nm));
  const uint64_t p2 = static_cast<uint64_t>(pitch_nm) * static_cast<uint64_t>(pitch_nm);
  // (a.hi * 2^64 + a.lo) * p2, as 192 bits: three 64-bit limbs.
  const U128 lo = mul_wide_u64(a.lo, p2), hi = mul_wide_u64(a.hi, p2);
  uint64_t limb[3] = {lo.lo, lo.hi + hi.lo, hi.hi + (lo.hi + hi.lo < lo.hi ? 1 : 0)};
  // Add 1e15 / 2 and divide by 1e15 (mm^3 x 1000, rounded), a byte at a
  // time so that remainder x 256 stays below 2^58.
  const uint64_t d = 1000000000000000ULL;
  const uint64_t s0 = limb[0] + d / 2;
  if (s0 < limb[0] && ++limb[1] == 0) ++limb[2];
  limb[0] = s0;
  uint64_t rem = 0, quotient = 0;
  for (int k = 23; k >= 0; --k) {
    const uint64_t cur = rem * 256 + ((limb[k / 8] >> (8 * (k % 8))) & 0xff);
    quotient = quotient * 256 + cur / d;  // fits: any grid a run holds is far below 2^64 / 1000 mm^3
    rem = cur % d;
  }
  return fixed_text(quotient, 3, false);
}

namespace {
// A stretch of contact that goes on past its line, no deeper.
std::string on_to(const SafetyEvent& e) {
  return e.last_line > e.line ? ", and on (no deeper) to line " + std::to_string(e.last_line) : std::string();
}
}  // namespace

std::string safety_event_text(const SafetyEvent& e, int64_t lsb_nm, int64_t pitch_nm) {
  const std::string at = "X" + nm_to_mm_text(e.at.x_nm, 3) + " Y" + nm_to_mm_text(e.at.y_nm, 3) + " Z" + nm_to_mm_text(e.at.z_nm, 3);
  const std::string removed = volume_mm3_text(e.removed_lsb, lsb_nm, pitch_nm) + " mm3 removed, " +
                              nm_to_mm_text(e.depth_nm, 3) + " mm deep at " + at;
  switch (e.kind) {
    case SafetyKind::kRapidIntoStock: return "rapid into material: " + removed;
    case SafetyKind::kSpindleStopped:
      return "cutting with the spindle stopped (no M3/M4) from here to line " + std::to_string(e.last_line) + ": " + removed;
    case SafetyKind::kBelowStock: return "the tool goes " + nm_to_mm_text(e.depth_nm, 3) + " mm below the stock's bottom at " + at;
    case SafetyKind::kIntoTable: return "the tool goes " + nm_to_mm_text(e.depth_nm, 3) + " mm into the table at " + at;
    case SafetyKind::kShank:
      return "the shank touches material: " + nm_to_mm_text(e.depth_nm, 3) + " mm above the flutes at " + at + ", " +
             volume_mm3_text(e.removed_lsb, lsb_nm, pitch_nm) + " mm3 in all" + on_to(e);
    case SafetyKind::kHolder:
      return "the holder touches material: " + nm_to_mm_text(e.depth_nm, 3) + " mm deep at " + at + ", " +
             volume_mm3_text(e.removed_lsb, lsb_nm, pitch_nm) + " mm3 in all" + on_to(e);
    case SafetyKind::kFixture:
      return "the tool enters a fixture: " + nm_to_mm_text(e.depth_nm, 3) + " mm deep at " + at + ", " +
             volume_mm3_text(e.removed_lsb, lsb_nm, pitch_nm) + " mm3 in all";
    case SafetyKind::kPlunge:
      return "a tool that is not centre cutting plunges " + nm_to_mm_text(e.depth_nm, 3) +
             " mm straight down into material at " + at;
  }
  return "";
}

namespace {

std::string collisions_text(const RunReport& r) {
  std::string o = "  \"collisions\": {\"total\": " + u64(r.collisions_total) + ", \"rapid_removed_mm3\": " +
                  volume_mm3_text(r.rapid_removed_lsb, r.lsb_nm, r.pitch_nm) + ", \"list\": [";
  for (std::size_t k = 0; k < r.collisions.size(); ++k) {
    const SafetyEvent& e = r.collisions[k];
    o += std::string(k ? ",\n      " : "\n      ") + "{\"kind\": " + quoted(safety_kind_name(e.kind)) +
         ", \"line\": " + u64(e.line) + ", \"x_mm\": " + nm_to_mm_text(e.at.x_nm, 4) + ", \"y_mm\": " +
         nm_to_mm_text(e.at.y_nm, 4) + ", \"z_mm\": " + nm_to_mm_text(e.at.z_nm, 4) + ", \"depth_mm\": " +
         nm_to_mm_text(e.depth_nm, 4) + ", \"volume_mm3\": " + volume_mm3_text(e.removed_lsb, r.lsb_nm, r.pitch_nm) +
         ", \"last_line\": " + u64(max_of(e.last_line, e.line)) +
         ", \"message\": " + quoted(safety_event_text(e, r.lsb_nm, r.pitch_nm)) + "}";
  }
  return o + (r.collisions.empty() ? "]},\n" : "\n    ]},\n");
}

std::string materials_text(const RunReport& r) {
  std::string o = "  \"materials\": {\"source\": " + quoted(r.material_source) + ", \"list\": [";
  for (std::size_t k = 0; k < r.materials.size(); ++k) {
    const ReportMaterial& m = r.materials[k];
    char b[160];
    std::snprintf(b, sizeof b, ", \"mass_g\": %.3f, \"cut_time_s\": %.3f, \"violations\": ", m.mass_g, m.cut_time_s);
    o += std::string(k ? ",\n      " : "\n      ") + "{\"name\": " + quoted(m.name) + ", \"removed_mm3\": " + m.removed_mm3 + b +
         u64(m.violations) + "}";
  }
  o += std::string(r.materials.empty() ? "]" : "\n    ]") + ",\n    \"violations_total\": " + u64(r.material_violations_total) +
       ", \"violations\": [";
  for (std::size_t k = 0; k < r.material_violations.size(); ++k) {
    const ReportViolation& v = r.material_violations[k];
    o += std::string(k ? ",\n      " : "\n      ") + "{\"rule\": " + quoted(v.rule) + ", \"line\": " + u64(v.line) +
         ", \"material\": " + quoted(v.material) + ", \"message\": " + quoted(v.message) + "}";
  }
  return o + (r.material_violations.empty() ? "]},\n" : "\n    ]},\n");
}

// {"moves": N, "engaged": M, "no_spindle_speed": K, "max_angle": {"deg": 180.00, "line": 5, "at": "FILE:5"}, ...
std::string engage_set_text(const ReportEngageSet& e, const std::string& file) {
  std::string o = "\"moves\": " + u64(e.moves) + ", \"engaged\": " + u64(e.engaged);
  o += ", \"no_spindle_speed\": " + u64(e.no_spindle_speed);
  for (const ReportEngageMax& m : e.maxima)
    o += ", " + quoted(m.name) + ": {" + quoted(m.unit) + ": " + m.value + ", \"line\": " + u64(m.line) +
         ", \"at\": " + (m.line ? quoted(file + ":" + std::to_string(m.line)) : std::string("null")) + "}";
  return o;
}

std::string engagement_text(const RunReport& r) {
  const ReportEngagement& e = r.engagement;
  std::string o = "  \"engagement\": {" + engage_set_text(e.program, r.file) + ",\n    \"tools\": [";
  for (std::size_t k = 0; k < e.tools.size(); ++k)
    o += std::string(k ? ",\n      " : "\n      ") + "{\"tool\": " + std::to_string(e.tools[k].first) + ", " +
         engage_set_text(e.tools[k].second, r.file) + "}";
  return o + (e.tools.empty() ? "]},\n" : "\n    ]},\n");
}

std::string load_text(const RunReport& r) {
  const ReportLoad& l = r.load;
  std::string o = "  \"load\": {\"spindle_power_w\": " +
                  (l.spindle_power_mw ? nm_to_mm_text(l.spindle_power_mw * 1000, 3) : std::string("null")) +
                  ", \"total\": " + u64(l.total) + ", \"findings\": [";
  for (std::size_t k = 0; k < l.kept.size(); ++k)
    o += std::string(k ? ",\n      " : "\n      ") + "{\"rule\": " + quoted(l.kept[k].rule) + ", \"line\": " +
         u64(l.kept[k].line) + ", \"message\": " + quoted(l.kept[k].message) + "}";
  return o + (l.kept.empty() ? "]},\n" : "\n    ]},\n");
}

// "machine": {"file": ..., "kind": ..., "travel_mm": {"x": [MIN, MAX] or null, ...},
// "defaults": [...]}, then "travel": {"total": N, "findings": [...]} with --check travel.
std::string machine_text(const RunReport& r) {
  const ReportMachine& m = r.machine;
  std::string o = "  \"machine\": {\"file\": " + quoted(m.file) + ", \"kind\": " + quoted(m.kind) + ", \"travel_mm\": {";
  for (int a = 0; a < 3; ++a)
    o += std::string(a ? ", " : "") + "\"" + "xyz"[a] + "\": " +
         (m.limited[a] ? "[" + m.min_mm[a] + ", " + m.max_mm[a] + "]" : std::string("null"));
  o += "}, \"defaults\": [";
  for (std::size_t k = 0; k < m.said.size(); ++k) o += (k ? ", " : "") + quoted(m.said[k]);
  o += "]},\n";
  if (!m.have_travel) return o;
  o += "  \"travel\": {\"total\": " + u64(m.travel_total) + ", \"findings\": [";
  for (std::size_t k = 0; k < m.findings.size(); ++k) {
    const ReportMachine::Finding& f = m.findings[k];
    o += std::string(k ? ",\n      " : "\n      ") + "{\"line\": " + u64(f.line) + ", \"at\": " +
         quoted(r.file + ":" + std::to_string(f.line)) + ", \"axis\": " + quoted(f.axis) + ", \"side\": " +
         quoted(f.side) + ", \"by_mm\": " + f.by_mm + ", \"message\": " + quoted(f.message) + "}";
  }
  return o + (m.findings.empty() ? "]},\n" : "\n    ]},\n");
}

// What the sheet (--sheet, platform/report/sheet_html.h) shows that the keys
// above do not hold: each tool's stick-out and lines, and the verdict.
std::string sheet_keys_text(const RunReport& r) {
  std::string o = "  \"tool_use\": [";
  for (std::size_t k = 0; k < r.tools_used.size(); ++k) {
    const ReportToolUse& u = r.tools_used[k];
    const bool cut = u.last_line != 0;
    o += std::string(k ? ", " : "") + "{\"number\": " + (u.number < 0 ? std::string("null") : std::to_string(u.number)) +
         ", \"stick_out_mm\": " + nm_to_mm_text(u.stick_out_nm, 4) +
         ", \"first_line\": " + (cut ? u64(u.first_line) : std::string("null")) +
         ", \"last_line\": " + (cut ? u64(u.last_line) : std::string("null")) + "}";
  }
  const Verdict v = report_verdict(r);
  o += "],\n  \"verdict\": {\"pass\": " + std::string(v.pass() ? "true" : "false") + ", \"errors\": " + u64(v.errors) +
       ", \"gouges\": " + u64(v.gouges) + ", \"collisions\": " + u64(v.collisions) + ", \"travel\": " +
       u64(v.travel) + ", \"rules\": " + u64(v.rules) + ", \"load\": " + u64(v.load) + ", \"stopped\": " +
       (v.stopped ? "true" : "false") + "},\n";
  return o;
}

}  // namespace

std::string report_json_text(const RunReport& r) {
  std::string o = "{\n";
  o += "  \"dexmill_report\": 1,\n";
  o += "  \"program\": {\"file\": " + quoted(r.file) + ", \"lines\": " + u64(r.lines) + ", \"units\": " +
       quoted(r.units) + ",\n";
  o += "    \"moves\": {\"rapid\": " + u64(r.rapid) + ", \"feed\": " + u64(r.feed) + ", \"arc\": " + u64(r.arc) +
       ", \"dwell\": " + u64(r.dwell) + ", \"tool_change\": " + u64(r.tool_change) + "}},\n";
  o += "  \"status\": " + quoted(r.errors.empty() ? "ok" : "error") + ",\n";
  o += "  \"stopped\": " +
       (r.stopped_reason.empty() ? std::string("null")
                                 : "{\"reason\": " + quoted(r.stopped_reason) + ", \"line\": " + u64(r.stopped_line) + "}") +
       ",\n";
  diags(&o, "errors", r.errors);
  diags(&o, "warnings", r.warnings);
  o += "  \"warnings_total\": " + u64(r.warnings_total) + ",\n";
  o += "  \"messages\": [";
  for (std::size_t k = 0; k < r.messages.size(); ++k)
    o += std::string(k ? ",\n    " : "\n    ") + "{\"line\": " + u64(r.messages[k].line) + ", \"kind\": " +
         quoted(r.messages[k].kind) + ", \"text\": " + quoted(r.messages[k].text) + "}";
  o += r.messages.empty() ? "],\n" : "\n  ],\n";
  if (r.have_stock)
    o += "  \"stock\": {\"min_mm\": " + point_mm(r.stock_lo) + ", \"max_mm\": " + point_mm(r.stock_hi) +
         ", \"source\": " + quoted(r.stock_source) + "},\n";
  else
    o += "  \"stock\": null,\n";
  if (r.nx)
    o += "  \"grid\": {\"nx\": " + u64(static_cast<uint64_t>(r.nx)) + ", \"ny\": " + u64(static_cast<uint64_t>(r.ny)) +
         ", \"pitch_mm\": " + nm_to_mm_text(r.pitch_nm, 6) + ", \"lsb_mm\": " + nm_to_mm_text(r.lsb_nm, 6) +
         ", \"height_bits\": " + std::to_string(r.height_bits) + "},\n";
  else
    o += "  \"grid\": null,\n";
  o += "  \"mode\": " + quoted(r.mode) + ",\n";
  o += "  \"tool\": {\"default\": " + quoted(r.default_tool) + ", \"table\": " +
       (r.tool_table.empty() ? std::string("null") : quoted(r.tool_table)) + ", \"table_units\": " +
       (r.tool_table_units.empty() ? std::string("null") : quoted(r.tool_table_units)) + ", \"used\": [";
  for (std::size_t k = 0; k < r.tools_used.size(); ++k) {
    const ReportToolUse& u = r.tools_used[k];
    const bool comment = u.line != 0;
    o += std::string(k ? ", " : "") + "{\"number\": " + (u.number < 0 ? std::string("null") : std::to_string(u.number)) +
         ", \"spec\": " + quoted(u.spec) + ", \"source\": " + (u.source.empty() ? std::string("null") : quoted(u.source)) +
         ", \"line\": " + (comment ? std::to_string(u.line) : std::string("null")) +
         ", \"form\": " + (comment ? quoted(u.form) : std::string("null")) + "}";
  }
  o += "]},\n";
  o += "  \"removed_mm3\": " + (r.nx ? volume_mm3_text(r.removed_lsb_dexels, r.lsb_nm, r.pitch_nm) : std::string("0.000")) + ",\n";
  o += "  \"estimated_time_s\": " + seconds_of_us(r.estimated_us) + ",\n";
  if (r.have_chain) o += chain_text(r);
  o += "  \"time_model\": {\"rapid_mm_per_min\": " + nm_to_mm_text(r.rapid_nm_per_min, 0) + ", \"accel_mm_per_s2\": " +
       (r.accel_nm_per_s2 ? nm_to_mm_text(r.accel_nm_per_s2, 3) : std::string("null")) + ", \"feed_s\": " +
       seconds_of_us(r.feed_us) + ", \"rapid_s\": " + seconds_of_us(r.rapid_us) + ", \"dwell_s\": " +
       seconds_of_us(r.dwell_us) + ", \"no_accel_s\": " + seconds_of_us(r.no_accel_us) + ", \"stop_s\": " +
       seconds_of_us(r.stop_us) + ", \"blended_s\": " + (r.blended ? seconds_of_us(r.blended_us) : std::string("null")) +
       ", \"path_tolerance_mm\": " + (r.path_tolerance_nm >= 0 ? nm_to_mm_text(r.path_tolerance_nm, 4) : std::string("null")) +
       "},\n";
  o += "  \"time_by_tool\": [";
  for (std::size_t k = 0; k < r.time_by_tool.size(); ++k) {
    const ReportToolTime& t = r.time_by_tool[k];
    o += std::string(k ? ", " : "") + "{\"tool\": " + (t.tool < 0 ? std::string("null") : std::to_string(t.tool)) +
         ", \"estimated_s\": " + seconds_of_us(t.estimated_us) + ", \"feed_s\": " + seconds_of_us(t.feed_us) +
         ", \"rapid_s\": " + seconds_of_us(t.rapid_us) + ", \"moves\": " + u64(t.moves) + "}";
  }
  o += "],\n";
  if (r.have_bounds)
    o += "  \"bounds_mm\": {\"min\": " + point_mm(r.bounds_lo) + ", \"max\": " + point_mm(r.bounds_hi) + "},\n";
  else
    o += "  \"bounds_mm\": null,\n";
  o += "  \"cut\": {\"instances\": " + u64(r.instances) + ", \"dexel_updates\": " + u64(r.dexel_updates) + "},\n";
  o += r.have_assessment ? assessment_text(r) : std::string("  \"assessment\": null,\n");
  o += r.have_collisions ? collisions_text(r) : std::string("  \"collisions\": null,\n");
  o += r.have_materials ? materials_text(r) : std::string("  \"materials\": null,\n");
  if (r.have_engagement) o += engagement_text(r);
  if (r.have_load) o += load_text(r);
  if (r.have_machine) o += machine_text(r);
  o += sheet_keys_text(r);
  o += "  \"timing\": {";
  for (std::size_t k = 0; k < r.timing.size(); ++k) {
    char b[64];
    std::snprintf(b, sizeof b, "%.3f", r.timing[k].second);
    o += std::string(k ? ", " : "") + quoted(r.timing[k].first + "_s") + ": " + b;
  }
  o += "},\n";
  o += "  \"run\": {\"started\": " + quoted(r.run_started) + ", \"pid\": " + std::to_string(r.run_pid) + ", \"outputs\": [";
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    const ReportOutput& out = r.outputs[k];
    o += std::string(k ? ",\n    " : "\n    ") + "{\"option\": " + quoted(out.option) +
         (out.bytes < 0 ? ", \"folder\": " + quoted(out.path) + ", \"files\": " + std::to_string(out.files)
                        : ", \"file\": " + quoted(out.path) + ", \"bytes\": " + std::to_string(out.bytes)) + "}";
  }
  o += r.outputs.empty() ? "]}\n}\n" : "\n  ]}\n}\n";
  return o;
}

bool write_report_json(const char* path, const RunReport& r, char* err, std::size_t errn) {
  const std::string text = report_json_text(r);
  return write_output(path, text.data(), text.size(), err, errn);
}

}  // namespace dexmill
