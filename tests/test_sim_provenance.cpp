// Which tool last cut each column (core/sim/provenance.h, what `--color
// tool` draws) on the engine (tests/sim_util.h): two slots by T1 and T2
// from a tool table carry their tools' classes, uncut stock none, and the
// classes do not depend on when the cut is shown (frames flush the Mill's
// deferred end caps). The colours in the image stay with the CLI's test
// (test_run_colours.cpp).
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;

namespace {

const char* kTwoTools =
    "G21 G90\nT1 M6\nM3 S10000\nG0 X-5 Y10 Z5\nG1 Z-3 F300\nG1 X45 F1000\nG0 Z5\n"
    "T2 M6\nM3 S10000\nG0 X-5 Y30\nG1 Z-3 F300\nG1 X45 F1000\nG0 Z5\nG0 X-40 Y-40\nM2\n";

// The class of the column whose axis is nearest (x, y) mm.
uint8_t class_at(Run& r, int64_t x_mm, int64_t y_mm) {
  const ToolProvenance<height_t>* p = r.sim().provenance();
  const GridGeometry& g = r.plan().geo;
  const int32_t i = static_cast<int32_t>((x_mm * kNmPerMm - g.x0_nm + g.pitch_nm / 2) / g.pitch_nm);
  const int32_t j = static_cast<int32_t>((y_mm * kNmPerMm - g.y0_nm + g.pitch_nm / 2) / g.pitch_nm);
  return p->cls[r.sim().grid().index(i, j)];
}

bool cut(Run* r, const std::string& table, const SimBudget& b, bool sync_each_step) {
  r->stock("0,0,-10,40,40,0").pitch("0.25").tools(table);
  r->provenance();
  return r->text("two_tools.ngc", kTwoTools, b, sync_each_step);
}

}  // namespace

TEST(sim_provenance_gives_each_tool_its_class) {
  const std::string table = run_cli::write_tmp("sim-two_tools.tbl", "T1 P1 D6 ;flat:6\nT2 P2 D6 ;ball:6\n");
  Run r;
  CHECK(cut(&r, table, SimBudget(), false));
  CHECK(r.sim().state() == SimState::kDone);
  const ToolProvenance<height_t>* p = r.sim().provenance();
  CHECK(p != nullptr);
  if (!p) return;
  CHECK_EQ(p->ntools, 2);
  CHECK_EQ(p->tool[0], 1);
  CHECK_EQ(p->tool[1], 2);
  CHECK_EQ(class_at(r, 20, 10), provenance_class_of(0, p->slots));  // T1's slot
  CHECK_EQ(class_at(r, 20, 30), provenance_class_of(1, p->slots));  // T2's
  CHECK(provenance_class_of(0, p->slots) != provenance_class_of(1, p->slots));
  CHECK_EQ(class_at(r, 20, 20), 0);  // between them, uncut
  // The cut shown after every move: the same grid, the same classes.
  Run framed;
  SimBudget one;
  one.moves = 1;
  CHECK(cut(&framed, table, one, true));
  CHECK_EQ(framed.grid_hash(), r.grid_hash());
  const ToolProvenance<height_t>* q = framed.sim().provenance();
  const size_t n = static_cast<size_t>(r.plan().geo.nx) * static_cast<size_t>(r.plan().geo.ny);
  CHECK(q != nullptr && std::vector<uint8_t>(q->cls, q->cls + n) == std::vector<uint8_t>(p->cls, p->cls + n));
}
