// LinuxCNC parameter files (.var); see machine_file.h.
#include "platform/format/machine_text.h"

namespace dexmill {
namespace {

using namespace machine_text;

struct VarState {
  PointNm g5x[kMachineCoordSystems] = {};
  PointNm g92{0, 0, 0};
  bool g92_on = false;
  uint8_t coord_system = 0;
};

// One `NUMBER VALUE` line; *last the number of the line before.
bool var_line(const char* name, uint32_t no, const Span& t, bool inch, int32_t* last, VarState* st, std::string* err) {
  std::size_t i = 0;
  int32_t num = 0;
  for (; i < t.n && digit(t.s[i]); ++i) {
    if (i >= 5) return *err = error_at(name, no, t.col, "a parameter number is 1 to 5601"), false;
    num = num * 10 + (t.s[i] - '0');
  }
  if (i == 0 || (i < t.n && !blank(t.s[i])))
    return *err = error_at(name, no, t.col, "expected NUMBER VALUE (a LinuxCNC parameter), not " + quoted(t)), false;
  const std::string what = "#" + std::to_string(num);
  if (num < 1 || num > kMaxParameter) return *err = error_at(name, no, t.col, "a parameter number is 1 to 5601"), false;
  if (num <= *last)
    return *err = error_at(name, no, t.col, what + " after #" + std::to_string(*last) +
                                                 ": LinuxCNC reads parameters in increasing order"), false;
  *last = num;
  const Span v = trim(t.from(i));
  Decimal d;
  if (!v.n) return *err = error_at(name, no, t.col + t.n, what + " needs a value"), false;
  if (!decimal_all(v, &d))
    return *err = error_at(name, no, v.col, what + "'s value is a number, not " + quoted(v)), false;
  if (num == 5220) {
    int64_t k = 0;
    if (!whole(v, 1, kMachineCoordSystems, &k))
      return *err = error_at(name, no, v.col, "#5220 is the coordinate system, 1 (G54) to 9 (G59.3), not " +
                                                  quoted(v)), false;
    st->coord_system = static_cast<uint8_t>(k - 1);
    return true;
  }
  if (num == 5210) {
    st->g92_on = !decimal_is_zero(d);
    return true;
  }
  PointNm* p = nullptr;
  int32_t c = 0;  // the axis
  if (num >= 5211 && num <= 5213) {
    p = &st->g92;
    c = num - 5211;
  } else if (num >= 5221 && (num - 5221) / 20 < kMachineCoordSystems && (num - 5221) % 20 < 3) {
    p = &st->g5x[(num - 5221) / 20];
    c = (num - 5221) % 20;
  }
  int64_t* at = !p ? nullptr : c == 0 ? &p->x_nm : c == 1 ? &p->y_nm : &p->z_nm;
  if (at) {
    *at = decimal_to_nm(d, inch);
    if (*at < -kLimitNm || *at > kLimitNm)
      return *err = error_at(name, no, v.col, what + " is a position in " + (inch ? "inch" : "mm") +
                                                  " within +-10 m, not " + quoted(v)), false;
  }
  return true;
}

}  // namespace

bool machine_var_parse(const char* name, const char* text, std::size_t n, bool inch, MachineSpec* spec,
                       std::string* err) {
  VarState st;
  int32_t last = 0;
  if (!each_line(name, text, n, err, [&](const Span& l, uint32_t no) {
        const Span t = trim(l);
        return !t.n || var_line(name, no, t, inch, &last, &st, err);
      }))
    return false;
  for (int k = 0; k < kMachineCoordSystems; ++k) spec->work_offset[k] = st.g5x[k];
  spec->g92 = st.g92_on ? st.g92 : PointNm{0, 0, 0};
  spec->coord_system = st.coord_system;
  spec->have_offsets = true;
  return true;
}

}  // namespace dexmill
