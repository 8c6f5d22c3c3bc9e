// tools/run/setup_text.h: setups as text.
#include "tools/run/setup_text.h"

#include "tools/cam/feed_word.h"
#include "tools/cli/option_values.h"

namespace dexmill {
namespace cli {

bool setup_parse(const std::string& given, StockSetup* out, std::string* why) {
  StockSetup s;
  std::string text(given);
  for (char& ch : text)
    if (ch == '+' || ch == '\t') ch = ' ';
  size_t at = 0;
  bool any = false;
  while (at < text.size()) {
    const size_t space = text.find(' ', at);
    const size_t end = space == std::string::npos ? text.size() : space;
    const std::string word = text.substr(at, end - at);
    at = end + 1;
    if (word.empty()) continue;
    any = true;
    if (word == "flip-x") s.flip_x = !s.flip_x;
    else if (word == "flip-y") s.flip_y = !s.flip_y;
    else if (word == "rotate-90") s.quarter_turns += 1;
    else if (word == "rotate-180") s.quarter_turns += 2;
    else if (word == "rotate-270") s.quarter_turns += 3;
    else if (word.compare(0, 7, "offset=") == 0) {
      int64_t d[3];
      if (!parse_mm_list(word.c_str() + 7, 3, d)) return *why = "offset= needs X,Y,Z in mm, not '" + word.substr(7) + "'", false;
      s.offset_nm = PointNm{s.offset_nm.x_nm + d[0], s.offset_nm.y_nm + d[1], s.offset_nm.z_nm + d[2]};
    } else {
      *why = "a setup is flip-x, flip-y, rotate-90, rotate-180, rotate-270 and offset=X,Y,Z (joined by '+'), not '" +
             word + "'";
      return false;
    }
  }
  if (!any) return *why = "a setup needs one of flip-x, flip-y, rotate-90|180|270, offset=X,Y,Z", false;
  s.quarter_turns %= 4;
  *out = s;
  return true;
}

std::string setup_text(const StockSetup& s) {
  std::string o;
  auto add = [&o](const std::string& w) { o += (o.empty() ? "" : "+") + w; };
  if (s.flip_x) add("flip-x");
  if (s.flip_y) add("flip-y");
  const int q = ((s.quarter_turns % 4) + 4) % 4;
  if (q) add("rotate-" + std::to_string(90 * q));
  const PointNm& d = s.offset_nm;
  if (d.x_nm || d.y_nm || d.z_nm)
    add("offset=" + decimal_text(Decimal{d.x_nm, 6}) + "," + decimal_text(Decimal{d.y_nm, 6}) + "," +
        decimal_text(Decimal{d.z_nm, 6}));
  return o.empty() ? "none" : o;
}

std::string recorded_setup_text(const int8_t turn[9], const int64_t offset_nm[3]) {
  StockSetup s;
  return stock_setup_of_record(turn, offset_nm, &s) ? setup_text(s) : std::string("?");
}

}  // namespace cli
}  // namespace dexmill
