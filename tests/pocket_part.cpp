// The pocket's design and its STL files; see pocket_part.h.
#include "tests/pocket_part.h"

#include <cstdint>
#include <cstdio>

namespace pocket_part {

std::vector<Facet> design() {
  const float z0 = 0, zp = -3, P[4] = {2, 2, 28, 18}, O[4] = {-10, -10, 45, 35};
  std::vector<Facet> f;
  auto quad = [&](float ax, float ay, float bx, float by, float z) {
    f.push_back(Facet{{{ax, ay, z}, {bx, ay, z}, {bx, by, z}}});
    f.push_back(Facet{{{ax, ay, z}, {bx, by, z}, {ax, by, z}}});
  };
  quad(P[0], P[1], P[2], P[3], zp);
  quad(O[0], O[1], O[2], P[1], z0);
  quad(O[0], P[3], O[2], O[3], z0);
  quad(O[0], P[1], P[0], P[3], z0);
  quad(P[2], P[1], O[2], P[3], z0);
  return f;
}

std::string ascii_stl(const std::vector<Facet>& fs) {
  std::string o = "solid pocket\n";
  char b[200];
  for (const Facet& f : fs) {
    o += "  facet normal 0 0 1\n    outer loop\n";
    for (const auto& v : f.v) {
      std::snprintf(b, sizeof b, "      vertex %g %g %g\n", v[0], v[1], v[2]);
      o += b;
    }
    o += "    endloop\n  endfacet\n";
  }
  return o + "endsolid pocket\n";
}

std::string binary_stl(const std::vector<Facet>& fs) {
  std::string o(80, ' ');
  o.replace(0, 5, "solid");  // many binary files start so; the size decides
  const uint32_t n = static_cast<uint32_t>(fs.size());
  o.append(reinterpret_cast<const char*>(&n), 4);
  for (const Facet& f : fs) {
    const float normal[3] = {0, 0, 1};
    o.append(reinterpret_cast<const char*>(normal), 12);
    o.append(reinterpret_cast<const char*>(f.v), 36);
    o.append(2, '\0');
  }
  return o;
}

}  // namespace pocket_part
