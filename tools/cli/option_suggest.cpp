// Suggestions for misspelled options; see option_suggest.h.
#include "tools/cli/option_suggest.h"

#include <algorithm>

namespace dexmill {
namespace cli {
namespace {

std::size_t letters(const std::string& name) {
  std::size_t k = 0;
  while (k < name.size() && name[k] == '-') ++k;
  return name.size() - k;
}

}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
  // Rows i-2, i-1 and i of the table d[i][j] = distance of a[0, i), b[0, j).
  const std::size_t m = b.size();
  std::vector<std::size_t> back2(m + 1), back(m + 1), row(m + 1);
  for (std::size_t j = 0; j <= m; ++j) back[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t replace = back[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({back[j] + 1, row[j - 1] + 1, replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], back2[j - 2] + 1);
    }
    back2.swap(back);
    back.swap(row);
  }
  return back[m];
}

std::string suggest_option(const std::string& typed, const std::vector<std::string>& names) {
  std::size_t best = static_cast<std::size_t>(-1);
  std::vector<std::string> closest;
  for (const std::string& n : names) {
    const std::size_t len = letters(n);
    if (len < 2 || n == typed) continue;
    const std::size_t d = edit_distance(typed, n);
    const std::size_t allowed = len <= 4 ? 1 : len <= 8 ? 2 : 3;
    if (d > allowed || d >= letters(typed) || d > best) continue;
    if (d < best) closest.clear();
    best = d;
    if (std::find(closest.begin(), closest.end(), n) == closest.end()) closest.push_back(n);
  }
  std::string s;
  for (std::size_t k = 0; k < closest.size(); ++k)
    s += (k == 0 ? "" : k + 1 == closest.size() ? " or " : ", ") + closest[k];
  return s;
}

}  // namespace cli
}  // namespace dexmill
