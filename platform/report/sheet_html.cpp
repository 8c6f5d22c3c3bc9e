// The sheet's page and its style; see sheet_html.h. A4 portrait with 10 mm
// margins (190 mm of width), print colours kept, every section kept whole
// across a page break where it fits.
#include "platform/report/sheet_html.h"

#include <string>

#include "platform/report/verdict.h"

namespace dexmill {

namespace {

using namespace sheet_detail;

const char kStyle[] =
    "@page { size: A4; margin: 10mm; }\n"
    "* { box-sizing: border-box; }\n"
    "html { -webkit-print-color-adjust: exact; print-color-adjust: exact; }\n"
    "body { margin: 0 auto; width: 190mm; font: 8.5pt/1.3 'DejaVu Sans', 'Helvetica Neue', Arial, sans-serif;"
    " color: #222; background: #fff; }\n"
    "header { display: flex; justify-content: space-between; align-items: baseline; border-bottom: 1.5pt solid #222;"
    " padding-bottom: 1.5mm; }\n"
    "h1 { font-size: 13pt; margin: 0; }\n"
    "h1 .file { font-family: 'DejaVu Sans Mono', monospace; font-weight: normal; }\n"
    ".run { color: #666; font-size: 7.5pt; text-align: right; }\n"
    ".verdict { margin: 2mm 0; padding: 1.6mm 3mm; font-size: 12pt; font-weight: bold; border-radius: 1mm; }\n"
    ".verdict.pass { background: #e3f4e4; color: #1d6b2a; border: 1pt solid #4caf50; }\n"
    ".verdict.fail { background: #fbe5e1; color: #a3261a; border: 1pt solid #d9412b; }\n"
    "section { margin: 0 0 2.2mm; break-inside: avoid; }\n"
    "h2 { font-size: 9.5pt; margin: 0 0 1mm; padding-bottom: 0.4mm; border-bottom: 0.5pt solid #999;"
    " text-transform: uppercase; letter-spacing: 0.04em; color: #333; }\n"
    "h3 { font-size: 8.5pt; margin: 1.5mm 0 1mm; }\n"
    ".views { display: flex; gap: 2mm; }\n"
    "figure { margin: 0; }\n"
    ".view { flex: 1 1 0; text-align: center; }\n"
    "img.view { width: 100%; height: auto; border: 0.5pt solid #bbb; display: block; }\n"
    ".nopic { height: 46mm; border: 0.5pt dashed #bbb; display: flex; align-items: center; justify-content: center;"
    " color: #888; padding: 2mm; }\n"
    "figcaption { font-size: 7.5pt; color: #555; margin-top: 0.6mm; }\n"
    ".grid2 { display: flex; gap: 4mm; }\n"
    ".grid2 > div { flex: 1 1 0; min-width: 0; }\n"
    ".grid2 > div:first-child { flex-grow: 1.2; }\n"
    ".programs { font-size: 7.5pt; }\n"
    ".cols { display: flex; gap: 3mm; align-items: flex-start; }\n"
    ".cols > div:first-child { flex: 1 1 0; }\n"
    "table { border-collapse: collapse; width: 100%; }\n"
    "th, td { text-align: left; padding: 0.35mm 1.2mm 0.35mm 0; vertical-align: top; }\n"
    "th { font-weight: bold; color: #444; border-bottom: 0.5pt solid #ccc; }\n"
    "td { border-bottom: 0.3pt solid #eee; }\n"
    "code, .at { font-family: 'DejaVu Sans Mono', monospace; font-size: 7.5pt; }\n"
    ".at { word-break: break-all; color: #000; }\n"
    ".programs td:nth-child(2) { overflow-wrap: anywhere; }\n"
    ".programs td:nth-child(n+4) { white-space: nowrap; text-align: right; }\n"
    ".peaks td, .peaks th { font-size: 7.5pt; }\n"
    ".kv td:first-child { width: 30mm; color: #555; }\n"
    ".findings th { padding-top: 1mm; }\n"
    ".findings td { font-size: 7.5pt; }\n"
    ".more, .note { color: #666; font-style: italic; }\n"
    ".facts { margin: 0.8mm 0; }\n"
    "p { margin: 0.8mm 0; }\n"
    ".crops { display: flex; flex-wrap: wrap; gap: 2mm; }\n"
    ".crop { width: 29.5mm; font-size: 7pt; }\n"
    "img.crop { width: 29.5mm; height: 29.5mm; border: 0.5pt solid #bbb; display: block; }\n"
    "svg.chart { display: block; }\n"
    ".plot svg { width: 100%; height: auto; display: block; }\n"
    "footer { color: #777; font-size: 7pt; border-top: 0.5pt solid #ccc; padding-top: 1mm; }\n";

}  // namespace

std::string sheet_html_text(const RunReport& r, const SheetImages& im) {
  const Verdict v = report_verdict(r);
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  o += "<title>dexmill sheet: " + html(r.file) + "</title>\n<style>\n" + std::string(kStyle) + "</style>\n</head>\n<body>\n";
  o += "<header><h1>Verification sheet <span class=\"file\">" + html(r.file) + "</span></h1><div class=\"run\">dexmill run " +
       html(r.run_started) + "</div></header>\n";
  o += std::string("<div class=\"verdict ") + (v.pass() ? "pass" : "fail") + "\">" + html(verdict_text(v, r)) + "</div>\n";
  o += part_section(r, im);
  o += "<div class=\"grid2\"><div>" + program_section(r) + tools_section(r) + "</div><div>" + time_section(r) +
       findings_section(r) + "</div></div>\n";
  o += assessment_section(r, im);
  o += load_section(r, im);
  o += "<footer>Drawn from the run's report (the same figures as its --report JSON). Lengths in mm, times in s;"
       " cut - design &lt; 0 is a gouge.</footer>\n";
  return o + "</body>\n</html>\n";
}

}  // namespace dexmill
