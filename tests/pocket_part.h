// The design of tests/run/pocket.ngc's part as the project draws it, for
// the tests that assess that program against it (by the CLI and on the
// engine): the stock's top at Z0 with a 26 x 16 mm pocket 3 mm deep,
// square cornered (the 6 mm flat end leaves 3 mm radii: leftover), as ten
// facets of a top surface; and the STL files of facets, ASCII and binary.
#ifndef DEXMILL_TESTS_POCKET_PART_H
#define DEXMILL_TESTS_POCKET_PART_H

#include <string>
#include <vector>

namespace pocket_part {

struct Facet {
  float v[3][3];
};

std::vector<Facet> design();
std::string ascii_stl(const std::vector<Facet>& fs);
// Little-endian floats and count, as hosts write them.
std::string binary_stl(const std::vector<Facet>& fs);

}  // namespace pocket_part

#endif
