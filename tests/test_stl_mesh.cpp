// core/design/stl_mesh.h, the freestanding STL reader: its integer
// conversions give the nm the hosted reader's doubles gave (a float's
// value times 1e6 rounded, llround; a decimal as strtod reads it) on random
// and edge values, binary and ASCII alike; the faults and their places.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/design/stl_mesh.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct Got {
  std::vector<PointNm> v;
  int stop_after = -1;
};
bool take(void* ctx, const PointNm* v) {
  Got& g = *static_cast<Got*>(ctx);
  for (int k = 0; k < 3; ++k) g.v.push_back(v[k]);
  return g.stop_after < 0 || static_cast<int>(g.v.size() / 3) < g.stop_after;
}

StlScan scan(const std::string& text, Got* g, PointNm off = PointNm{0, 0, 0}) {
  StlScan s;
  stl_scan(reinterpret_cast<const uint8_t*>(text.data()), text.size(), off, take, g, &s);
  return s;
}

std::string ascii_facet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 1\n outer loop\n  vertex " + a + "\n  vertex " + b + "\n  vertex " + c +
         "\n endloop\nendfacet\n";
}

std::string binary(const std::vector<float>& xyz) {  // 9 a facet
  std::string b(80, ' ');
  const uint32_t n = static_cast<uint32_t>(xyz.size() / 9);
  b.append(reinterpret_cast<const char*>(&n), 4);
  for (uint32_t k = 0; k < n; ++k) {
    b.append(12, '\0');
    b.append(reinterpret_cast<const char*>(&xyz[9 * k]), 36);
    b.append(2, '\0');
  }
  return b;
}

// What the hosted reader made of a coordinate: llround(mm * 1e6), or false.
bool hosted_nm(double mm, int64_t* nm) {
  if (!std::isfinite(mm) || std::fabs(mm) > 10000.0) return false;
  *nm = static_cast<int64_t>(std::llround(mm * 1e6));
  return true;
}

}  // namespace

TEST(stl_mesh_binary_floats_are_the_hosted_nm) {
  std::mt19937 rng(42);
  int checked = 0, beyond = 0;
  for (int round = 0; round < 2000; ++round) {
    std::vector<float> xyz(9);
    for (float& f : xyz) {
      uint32_t bits = rng();
      if (round % 3 != 0) {  // two in three within the range: exponents of 2^-30 .. 2^14
        bits = (bits & 0x807fffff) | ((97 + rng() % 44) << 23);
      }
      std::memcpy(&f, &bits, 4);
      if (!std::isfinite(f)) f = 1.5f;
    }
    const float special[] = {0.0f, -0.0f, 10000.0f, -10000.0f, 0.0000005f, 1e-45f, 0.1f, 33.000004f};
    if (round < 8) xyz[0] = special[round];
    Got g;
    const std::string b = binary(xyz);
    StlScan s;
    stl_scan(reinterpret_cast<const uint8_t*>(b.data()), b.size(), PointNm{5, -7, 11}, take, &g, &s);
    bool all = true;
    int64_t want[9];
    for (int k = 0; k < 9; ++k) all = hosted_nm(xyz[k], &want[k]) && all;
    CHECK(s.binary);
    if (!all) {
      CHECK(s.fault == StlFault::kBeyond);
      ++beyond;
      continue;
    }
    CHECK(s.fault == StlFault::kNone);
    CHECK_EQ(g.v.size(), 3u);
    if (g.v.size() != 3) continue;
    for (int k = 0; k < 3; ++k) {
      CHECK_EQ(g.v[k].x_nm, want[3 * k] + 5);
      CHECK_EQ(g.v[k].y_nm, want[3 * k + 1] - 7);
      CHECK_EQ(g.v[k].z_nm, want[3 * k + 2] + 11);
    }
    ++checked;
  }
  std::printf("  %d facets as the hosted reader read them, %d beyond 10 m\n", checked, beyond);
  CHECK_GT(checked, 1000);
  CHECK_GT(beyond, 100);
}

TEST(stl_mesh_ascii_decimals_are_the_hosted_nm) {
  std::mt19937 rng(7);
  const char* fixed[] = {"0",       "-0",        "1",        "+2.5",        "1.000000e+01", "-3.3e-1", "1E3",
                         "0.0000004", "0.0000006", "9999.999999", "10000",    "-10000",       ".5",      "5.",
                         "1.2345678901234567890123e2", "000012.5000", "1e0",  "2.5e-7",       "1e-400"};
  int checked = 0;
  for (int round = 0; round < 3000; ++round) {
    char w[64];
    if (round < static_cast<int>(sizeof fixed / sizeof fixed[0])) {
      std::snprintf(w, sizeof w, "%s", fixed[round]);
    } else {
      const double v = (static_cast<double>(rng()) / 4294967296.0 - 0.5) * 2e4 * std::pow(10.0, -static_cast<int>(rng() % 8));
      const char* forms[] = {"%.6f", "%.3f", "%e", "%.9e", "%g", "%.2f"};
      std::snprintf(w, sizeof w, forms[rng() % 6], v);
    }
    const double mm = std::strtod(w, nullptr);
    int64_t want = 0;
    const bool ok = hosted_nm(mm, &want) && std::strcmp(w, "1e-400") != 0;
    Got g;
    const std::string t = "solid t\n" + ascii_facet(std::string(w) + " 0 0", "1 0 0", "0 1 0") + "endsolid t\n";
    const StlScan s = scan(t, &g);
    if (!ok) {
      CHECK(s.fault != StlFault::kNone);
      continue;
    }
    CHECK(s.fault == StlFault::kNone);
    if (g.v.empty()) continue;
    if (g.v[0].x_nm != want) std::printf("  %s: %lld, the hosted %lld\n", w, static_cast<long long>(g.v[0].x_nm),
                                         static_cast<long long>(want));
    CHECK_EQ(g.v[0].x_nm, want);
    ++checked;
  }
  std::printf("  %d decimals as strtod and llround read them\n", checked);
  CHECK_GT(checked, 2900);
}

TEST(stl_mesh_faults_and_where) {
  Got g;
  CHECK(scan("", &g).fault == StlFault::kNotStl);
  CHECK(scan(std::string("solid\0x", 7), &g).fault == StlFault::kNotStl);
  CHECK(scan("  solidx a\n", &g).fault == StlFault::kNoSolid);
  CHECK(scan("solid a\nendsolid a\n", &g).fault == StlFault::kNoTriangles);
  StlScan s = scan("solid a\n" + ascii_facet("0 0 0", "1 0 0", "0 1 0"), &g);
  CHECK(s.fault == StlFault::kNoEndsolid);
  CHECK_EQ(s.triangles, 1u);
  s = scan("solid a\n facet normal 0 0 1\n  outer loop\n   vertx 0 0 0\n", &g);
  CHECK(s.fault == StlFault::kExpected);
  CHECK_EQ(std::string(s.expected), "vertex");
  CHECK_EQ(std::string(s.found), "vertx");
  CHECK_EQ(s.line, 4u);
  s = scan("solid a\n" + ascii_facet("0 0 0", "1 x1 0", "0 1 0"), &g);
  CHECK(s.fault == StlFault::kNotNumber);
  CHECK_EQ(s.line, 5u);  // the second vertex's
  CHECK(scan("solid a\n" + ascii_facet("0 0 0", "1 inf 0", "0 1 0"), &g).fault == StlFault::kBeyond);
  CHECK(scan("solid a\n" + ascii_facet("0 0 0", "10000.001 0 0", "0 1 0"), &g).fault == StlFault::kBeyond);
  CHECK(scan("solid a\n" + ascii_facet("0 0 0", "1 1e999 0", "0 1 0"), &g).fault == StlFault::kNotNumber);
  CHECK(scan("solid a\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n", &g).fault == StlFault::kEndsInFacet);
  Got two;
  two.stop_after = 1;
  s = scan("solid a\n" + ascii_facet("0 0 0", "1 0 0", "0 1 0") + ascii_facet("0 0 0", "1 0 0", "0 1 0"), &two);
  CHECK(s.fault == StlFault::kStopped);
  CHECK_EQ(s.triangles, 1u);
  std::vector<float> nan_facet(9, 1.0f);
  nan_facet[4] = std::nanf("");
  const std::string b = binary(nan_facet);
  stl_scan(reinterpret_cast<const uint8_t*>(b.data()), b.size(), PointNm{0, 0, 0}, take, &g, &s);
  CHECK(s.fault == StlFault::kNotNumber);
  CHECK(s.binary);
}
