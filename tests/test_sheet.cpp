// The verification sheet (platform/report/sheet_html.h, `dexmill run
// --sheet`): the verdict's counts against a report with known findings,
// PASS with none, a sheet without a design that says so, file names with
// markup escaped, numbers with their units, base64 against RFC 4648's
// vectors, the worst gouges' order, no script and nothing from the
// network; end to end, a run's sheet and report agree. The browser's
// rendering is tools/scripts/sheet-test.sh's (make test-sheet).
#include <string>
#include <vector>

#include "platform/report/report_json.h"
#include "platform/report/sheet_html.h"
#include "platform/report/verdict.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;
using run_cli::has;
using run_cli::lacks;

namespace {

size_t count_of(const std::string& s, const std::string& part) {
  size_t n = 0;
  for (size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
  return n;
}

RunReport with_findings() {
  RunReport r;
  r.file = "part.ngc";
  r.have_assessment = true;
  r.assessment.gouges_total = 3;
  r.assessment.tolerance_nm = 50000;
  for (uint32_t line : {12u, 30u, 7u}) {
    ReportGouge g;
    g.line = line;
    g.depth_nm = line == 30 ? 400000 : 200000;
    r.assessment.gouges.push_back(g);
  }
  r.have_collisions = true;
  r.collisions_total = 1;
  r.have_machine = true;
  r.machine.have_travel = true;
  r.machine.travel_total = 2;
  r.have_materials = true;
  r.material_violations_total = 5;
  r.have_load = true;
  r.load.total = 1;
  return r;
}

// The static rules of the page: nothing fetched, nothing run.
bool self_contained(const std::string& page) {
  return lacks(page, "<script") && lacks(page, "src=\"http") && lacks(page, "url(http") && lacks(page, "@import") &&
         lacks(page, "<link") && lacks(page, "<iframe");
}

}  // namespace

TEST(sheet_verdict_counts_findings_by_kind) {
  const RunReport r = with_findings();
  const Verdict v = report_verdict(r);
  CHECK(!v.pass());
  CHECK_EQ(verdict_text(v, r), std::string("3 gouges \xc2\xb7 1 collision \xc2\xb7 2 travel findings \xc2\xb7 5 rule findings \xc2\xb7 1 load finding"));
  const std::string page = sheet_html_text(r, SheetImages());
  CHECK(has(page, "<div class=\"verdict fail\">3 gouges \xc2\xb7 1 collision"));
  CHECK(lacks(page, "PASS"));
  CHECK(has(report_json_text(r), "\"verdict\": {\"pass\": false, \"errors\": 0, \"gouges\": 3, \"collisions\": 1, "
                                 "\"travel\": 2, \"rules\": 5, \"load\": 1, \"stopped\": false}"));
  CHECK(self_contained(page));
  // A stop is a finding too.
  RunReport s;
  s.stopped_reason = "gouge";
  s.stopped_line = 9;
  CHECK_EQ(verdict_text(report_verdict(s), s), std::string("stopped (gouge) at line 9"));
}

TEST(sheet_without_findings_passes) {
  RunReport r;
  r.file = "clean.ngc";
  r.have_collisions = true;  // checked, none found
  const std::string page = sheet_html_text(r, SheetImages());
  CHECK(has(page, "<div class=\"verdict pass\">PASS</div>"));
  CHECK(has(page, "collisions: none"));
  CHECK(has(page, "travel: not checked (--machine)"));
  CHECK(has(report_json_text(r), "\"verdict\": {\"pass\": true,"));
}

TEST(sheet_without_design_says_so) {
  RunReport r;
  r.file = "p.ngc";
  const std::string page = sheet_html_text(r, SheetImages());
  CHECK(has(page, "no design given (--design): no error view, no assessment"));
  CHECK(lacks(page, "histogram of cut - design"));
  CHECK(lacks(page, "The worst gouges"));
  const std::string with = sheet_html_text(with_findings(), SheetImages());
  CHECK(has(with, "histogram of cut - design"));
  CHECK(has(with, "The worst gouges"));
  CHECK(lacks(with, "no design given"));
}

TEST(sheet_escapes_file_names) {
  RunReport r = with_findings();
  r.file = "a<b>&\"c'.ngc";
  const std::string page = sheet_html_text(r, SheetImages());
  CHECK(has(page, "a&lt;b&gt;&amp;&quot;c&apos;.ngc"));
  CHECK(has(page, "a&lt;b&gt;&amp;&quot;c&apos;.ngc:30"));  // a gouge's FILE:LINE
  CHECK(lacks(page, "a<b>"));
  CHECK_EQ(sheet_detail::html("x\x01y\xff"), std::string("x?y?"));
}

TEST(sheet_numbers_carry_units) {
  RunReport r;
  r.file = "p.ngc";
  r.estimated_us = 16779000;
  r.feed_us = 15885000;
  r.rapid_nm_per_min = 5000000000LL;
  ReportToolUse u{3, "flat:6", "table", 0, ""};
  u.stick_out_nm = 30000000;
  u.first_line = 5;
  u.last_line = 20;
  r.tools_used.push_back(u);
  std::string page = sheet_html_text(r, SheetImages());
  CHECK(has(page, "total 16.779\xc2\xa0s"));
  CHECK(has(page, "feed 15.885\xc2\xa0s"));
  CHECK(has(page, "5000&nbsp;mm/min"));
  CHECK(has(page, "<td>T3</td><td><code>flat:6</code></td><td>30.00&nbsp;mm</td><td>5\xe2\x80\x93" "20</td>"));
  CHECK(has(page, "by tool: not estimated"));
  CHECK(lacks(page, "blended"));  // no such estimates in this report
  r.no_accel_us = 16779000;
  r.stop_us = 30000000;
  r.blended_us = 20500000;
  r.path_tolerance_nm = 10000;
  CHECK(has(sheet_html_text(r, SheetImages()), "blended 20.500\xc2\xa0s (path tolerance 0.010&nbsp;mm)"));
  CHECK(has(report_json_text(r), "\"tool_use\": [{\"number\": 3, \"stick_out_mm\": 30.0000, \"first_line\": 5, \"last_line\": 20}]"));
  // With the estimate by tool: its bars, in seconds.
  r.time_by_tool.push_back(ReportToolTime{3, 12000000, 11000000, 1000000, 10});
  page = sheet_html_text(r, SheetImages());
  CHECK(lacks(page, "not estimated"));
  CHECK(has(page, "the time estimate by tool"));
  CHECK(has(page, ">12.000\xc2\xa0s</text>"));
  CHECK_EQ(sheet_detail::seconds_text(205000000), std::string("205.000\xc2\xa0s (3 min 25 s)"));
}

TEST(sheet_base64_rfc4648_vectors) {
  auto b64 = [](const char* s) { return sheet_detail::base64(std::vector<uint8_t>(s, s + std::char_traits<char>::length(s))); };
  CHECK_EQ(b64(""), std::string(""));
  CHECK_EQ(b64("f"), std::string("Zg=="));
  CHECK_EQ(b64("fo"), std::string("Zm8="));
  CHECK_EQ(b64("foo"), std::string("Zm9v"));
  CHECK_EQ(b64("foob"), std::string("Zm9vYg=="));
  CHECK_EQ(b64("fooba"), std::string("Zm9vYmE="));
  CHECK_EQ(b64("foobar"), std::string("Zm9vYmFy"));
  CHECK_EQ(sheet_detail::base64({0xff, 0xfe, 0x00}), std::string("//4A"));
}

TEST(sheet_worst_gouges_deepest_first) {
  ReportAssessment a;
  const int64_t depth[] = {100, 300, 300, 50, 900, 200, 10, 700};
  for (uint32_t k = 0; k < 8; ++k) {
    ReportGouge g;
    g.line = 10 + k;
    g.depth_nm = depth[k];
    a.gouges.push_back(g);
  }
  const std::vector<size_t> w = sheet_worst_gouges(a);
  CHECK_EQ(w.size(), kSheetWorstGouges);
  const size_t want[] = {4, 7, 1, 2, 5, 0};  // 900, 700, 300 (line 11), 300 (line 12), 200, 100
  for (size_t k = 0; k < w.size(); ++k) CHECK_EQ(w[k], want[k]);
}

TEST(sheet_pictures_are_data_uris) {
  SheetImages im;
  im.iso.png = {0x89, 'P', 'N', 'G'};
  im.iso.caption = "iso <view>";
  im.load_plot_svg = "<?xml version=\"1.0\"?>\n<svg><title>plot</title></svg>\n";
  RunReport r;
  r.have_engagement = true;
  const std::string page = sheet_html_text(r, im);
  CHECK(has(page, "src=\"data:image/png;base64,iVBORw==\""));
  CHECK(has(page, "alt=\"iso &lt;view&gt;\""));
  CHECK(has(page, "<div class=\"plot\"><svg><title>plot</title></svg>"));
  CHECK(lacks(page, "<?xml"));
  CHECK(self_contained(page));
}

TEST(sheet_run_end_to_end) {
  if (run_cli::skip()) return;
  const std::string d = run_cli::tmp_dir();
  // pocket.ngc against its design with the checks: the gouge at line 20 and
  // the spindle-stopped finding (tests/test_run_cli.cpp's).
  run_cli::Result r = run_cli::run("pocket.ngc -q --tool flat:6 --design pocket_design.stl --check all --sheet %/s.html "
                                   "--report %/s.json");
  CHECK_EQ(r.code, 0);
  const std::string page = run_cli::slurp(d + "/s.html"), rep = run_cli::slurp(d + "/s.json");
  CHECK(has(page, "<div class=\"verdict fail\">1 gouge \xc2\xb7 1 collision</div>"));
  CHECK(has(rep, "\"gouges\": 1, \"collisions\": 1,"));
  CHECK(has(rep, "{\"option\": \"--sheet\", \"file\": "));
  CHECK_EQ(count_of(page, "src=\"data:image/png;base64,"), 4u);  // iso, top, error, one crop
  CHECK(has(page, "pocket.ngc:20"));
  CHECK(self_contained(page));
  // Without a design: two pictures, no error view.
  r = run_cli::run("pocket.ngc -q --tool flat:6 --sheet %/n.html");
  CHECK_EQ(r.code, 0);
  const std::string bare = run_cli::slurp(d + "/n.html");
  CHECK_EQ(count_of(bare, "src=\"data:image/png;base64,"), 2u);
  CHECK(has(bare, "no design given (--design): no error view"));
  CHECK(has(bare, "<div class=\"verdict pass\">PASS</div>"));
  // A chain: each program and the setup before it.
  r = run_cli::run("pocket.ngc -q --tool flat:6 --setup flip-x pocket.ngc --sheet %/c.html");
  CHECK_EQ(r.code, 0);
  const std::string chain = run_cli::slurp(d + "/c.html");
  CHECK(has(chain, "<tr><td>1</td><td>pocket.ngc</td><td>none</td>"));
  CHECK(has(chain, "<tr><td>2</td><td>pocket.ngc</td><td>flip-x</td>"));
  // A name that is not .html, and a sheet that would overwrite the input.
  r = run_cli::run("pocket.ngc -q --sheet %/s.txt");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--sheet needs a FILE.html"));
  run_cli::write_tmp("prog.html", "G1 X1 F100\n");
  r = run_cli::run("%/prog.html -q --sheet %/prog.html");
  CHECK_EQ(r.code, 2);
  CHECK_EQ(run_cli::slurp(d + "/prog.html"), std::string("G1 X1 F100\n"));
}
