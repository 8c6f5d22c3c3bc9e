// Material files (platform/format/material_file.h): a file with every statement
// read into the composition it says, a preset with an insert, and a corpus
// of bad files, each with the error it must give (FILE:LINE:COL).
#include <cstring>
#include <string>

#include "core/math/fixed.h"
#include "platform/format/material_file.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

const BoxNm kStock{PointNm{0, 0, -20 * kNmPerMm}, PointNm{100 * kNmPerMm, 60 * kNmPerMm, 0}};

bool parse(const char* text, StockComposition* c, std::string* err) {
  return material_file_parse("m.txt", text, std::strlen(text), kStock, c, err);
}

const char* name_at(const StockComposition& c, double x, double y, double z) {
  const uint8_t k = composition_material_at(c, static_cast<int64_t>(x * 1e6), static_cast<int64_t>(y * 1e6),
                                            static_cast<int64_t>(z * 1e6));
  return c.materials[k].name;
}

}  // namespace

TEST(material_file_reads_every_statement) {
  StockComposition c;
  std::string err;
  const char* text =
      "# a wood and aluminium sandwich with a bronze bushing\n"
      "material alu plain colour=200,204,210 max_feed=1200 spindle=8000..24000 density=2.7\n"
      "material beech wood coolant=no max_feed=3000 period=3.5 seed=7 density=0.72   # soaks up coolant\n"
      "material bush bronze max_feed=400 tolerance=0.01 density=8.8\n"
      "\n"
      "layer -20 -8 alu\n"
      "layer -8 0 beech\n"
      "cylinder 50,30,6,-20,0 bush\n"
      "box 0,0,-2,10,10,0 alu\n"
      "default alu\n";
  CHECK(parse(text, &c, &err));
  if (!err.empty()) std::printf("  %s\n", err.c_str());
  CHECK_EQ(c.material_count, 3);
  CHECK(!std::strcmp(name_at(c, 80, 50, -10), "alu"));
  CHECK(!std::strcmp(name_at(c, 80, 50, -3), "beech"));
  CHECK(!std::strcmp(name_at(c, 52, 31, -3), "bush"));   // the insert wins over the layer
  CHECK(!std::strcmp(name_at(c, 5, 5, -1), "alu"));      // the later box wins
  CHECK(!std::strcmp(name_at(c, 80, 50, 5), "alu"));     // the default
  const Material& beech = c.materials[1];
  CHECK(!beech.process.coolant_allowed);
  CHECK_EQ(beech.process.max_feed_nm_per_min, 3000 * kNmPerMm);
  CHECK_EQ(beech.texture.kind, TextureKind::kWood);
  CHECK_EQ(beech.texture.wood.ring_pitch_nm, 3500000);
  CHECK_EQ(beech.texture.wood.seed, 7u);
  CHECK_EQ(beech.process.density_mg_per_cm3, 720);
  CHECK_EQ(c.materials[0].process.spindle_min_rpm, 8000);
  CHECK_EQ(c.materials[0].process.spindle_max_rpm, 24000);
  CHECK(c.materials[0].texture.plain == (Rgb8{200, 204, 210}));
  CHECK_EQ(c.materials[2].process.tolerance_nm, 10000);
}

TEST(material_file_preset_and_insert) {
  StockComposition c;
  std::string err;
  CHECK(parse("preset marble\nmaterial plug bronze\ncylinder 20,20,5,-20,0 plug\n", &c, &err));
  CHECK(!std::strcmp(name_at(c, 20, 21, -5), "plug"));
  CHECK(std::strcmp(name_at(c, 60, 40, -5), "plug") != 0);
}

TEST(material_file_bad_files) {
  struct Case {
    const char* text;
    const char* error;
  };
  const Case cases[] = {
      {"", "m.txt:1:1: error: the file names no material"},
      {"# only a comment\n", "m.txt:1:1: error: the file names no material"},
      {"materiel a plain\n", "m.txt:1:1: error: unknown statement 'materiel'"},
      {"material a\n", "m.txt:1:10: error: expected material NAME TEXTURE"},
      {"material a velvet\n", "m.txt:1:12: error: unknown texture 'velvet'"},
      {"material averyveryverylongname plain\n", "m.txt:1:10: error: a material's name has 1 to 16 characters"},
      {"material a plain\nmaterial a plain\n", "m.txt:2:10: error: material 'a' is already defined"},
      {"material a plain colour=1,2\n", "m.txt:1:18: error: a colour is R,G,B"},
      {"material a plain colour=1,2,300\n", "m.txt:1:18: error: a colour is R,G,B"},
      {"material a plain vein=1,2,3\n", "m.txt:1:18: error: a plain material has no veins"},
      {"material a plain max_feed=-5\n", "m.txt:1:18: error: max_feed is a feed in mm/min above 0"},
      {"material a plain max_feed=fast\n", "m.txt:1:18: error: max_feed is a feed"},
      {"material a plain spindle=9000\n", "m.txt:1:18: error: spindle is MIN..MAX"},
      {"material a plain spindle=9000..100\n", "m.txt:1:18: error: spindle is MIN..MAX"},
      {"material a plain coolant=maybe\n", "m.txt:1:18: error: coolant is yes or no"},
      {"material a plain density=0\n", "m.txt:1:18: error: density is g/cm3"},
      {"material a plain period=3\n", "m.txt:1:18: error: only marble and wood have a period"},
      {"material a plain hardness=3\n", "m.txt:1:18: error: unknown key 'hardness'"},
      {"material a plain 3\n", "m.txt:1:18: error: expected KEY=VALUE"},
      {"material a plain\nlayer 0 -5 a\n", "m.txt:2:9: error: a layer's Z1 must be above its Z0"},
      {"material a plain\nlayer 0 x a\n", "m.txt:2:9: error: Z1 is a height in mm"},
      {"material a plain\nlayer -5 0 b\n", "m.txt:2:12: error: no material named 'b'"},
      {"material a plain\nlayer -5 0\n", "m.txt:2:10: error: expected layer Z0 Z1 NAME"},
      {"material a plain\nbox 0,0,0,1,1 a\n", "m.txt:2:5: error: '0,0,0,1,1' is not 6 numbers in mm"},
      {"material a plain\nbox 0,0,0,1,1,1,1 a\n", "m.txt:2:5: error: '0,0,0,1,1,1,1' is not 6 numbers in mm"},
      {"material a plain\nbox 5,0,0,1,1,1 a\n", "m.txt:2:5: error: a box needs X0<X1"},
      {"material a plain\ncylinder 0,0,0,-5,0 a\n", "m.txt:2:10: error: a cylinder's radius must be above 0"},
      {"material a plain\ncylinder 0,0,2,0,-5 a\n", "m.txt:2:10: error: a cylinder's Z1 must be above its Z0"},
      {"material a plain\nbox 0,0,0,99999999,1,1 a\n", "m.txt:2:5: error: '0,0,0,99999999,1,1' is not 6 numbers"},
      {"material a plain\ndefault b\n", "m.txt:2:9: error: no material named 'b'"},
      {"material a plain\npreset marble\n", "m.txt:2:1: error: a preset must come before any material"},
      {"preset granit\n", "m.txt:1:8: error: no preset named 'granit'"},
      {"material a plain\nlayer -5 0 a extra\n", "m.txt:2:14: error: expected layer Z0 Z1 NAME"},
      {"material a plain\x00\n", "m.txt:1:1: error: a NUL byte"},
  };
  int k = 0;
  for (const Case& cs : cases) {
    StockComposition c;
    composition_clear(&c);
    std::string err;
    const std::size_t n = cs.text[0] || k != 0 ? std::strlen(cs.text) + (std::strstr(cs.error, "NUL") ? 2 : 0) : 0;
    const bool okay = material_file_parse("m.txt", cs.text, n, kStock, &c, &err);
    CHECK(!okay);
    if (err.find(cs.error) != 0) std::printf("  case %d: got '%s', want '%s'\n", k, err.c_str(), cs.error);
    CHECK(err.find(cs.error) == 0);
    CHECK_EQ(c.material_count, 0);  // nothing of a bad file is used
    ++k;
  }
}

// Too many of a kind: the capacities the header names.
TEST(material_file_capacities) {
  std::string text;
  for (int k = 0; k <= kCompositionMaxMaterials; ++k) text += "material m" + std::to_string(k) + " plain\n";
  StockComposition c;
  std::string err;
  CHECK(!material_file_parse("m.txt", text.data(), text.size(), kStock, &c, &err));
  CHECK(err.find("m.txt:" + std::to_string(kCompositionMaxMaterials + 1) + ":10: error: too many materials") == 0);
}
