// grbl settings dumps; see machine_file.h.
#include <utility>

#include "platform/format/machine_text.h"

namespace dexmill {
namespace machine_text {
namespace {

class GrblParser : public ReaderPlace {
 public:
  GrblParser(const char* name, bool inch) : ReaderPlace(name), inch_(inch) {}

  bool line(Span raw, uint32_t no) {
    line_ = no;
    const Span t = trim(raw);
    if (!t.n || t.s[0] == '#' || t.s[0] == ';' || t.is("ok") || t.is("$$") || t.is("$#")) return true;
    if (t.s[0] == '$') return setting(t);
    if (t.s[0] == '[') return report(t);
    if (t.s[0] == '<') return t.s[t.n - 1] == '>' || fail(t.col + t.n, "a status report without its closing '>'");
    if (t.starts("Grbl")) return true;  // the welcome line: "Grbl 1.1h ['$' for help]", grblHAL's "GrblHAL ..."
    return fail(t.col, "expected a grbl setting ($N=VALUE) or report ([G54:X,Y,Z]), not " + quoted(t));
  }

  bool finish(MachineFile* out) {
    if (f_.keys.empty()) {
      line_ = 1;
      return fail(1, "no grbl setting ($110=...) or offset ([G54:...]) in the file");
    }
    MachineSpec& s = f_.spec;
    s.kind = MachineKind::kGrbl;
    s.inch = inch_;
    for (int a = 0; a < 3; ++a) {
      MachineAxis& ax = s.axis[a];
      ax.max_velocity_nm_per_min = velocity_[a];
      ax.max_accel_nm_per_s2 = accel_[a];
      if (travel_[a] <= 0) continue;
      const bool positive = (homing_ & 8) && (dir_mask_ & (1u << a));  // grblHAL: origin at the home position
      ax.min_nm = positive ? 0 : -travel_[a];
      ax.max_nm = positive ? travel_[a] : 0;
      ax.limited = soft_limits_;
    }
    *out = std::move(f_);
    return true;
  }


 private:
  bool setting(const Span& t) {
    if (t.n >= 2 && t.s[1] == 'N') return true;  // $N0=..., the startup blocks `$N` prints
    std::size_t i = 1;
    int32_t num = 0;
    for (; i < t.n && digit(t.s[i]); ++i) {
      if (i > 5) return fail(t.col + 1, "a grbl setting's number has at most 5 digits");
      num = num * 10 + (t.s[i] - '0');
    }
    if (i == 1) return fail(t.col, "expected a grbl setting $N=VALUE, not " + quoted(t));
    const std::string what = "$" + std::to_string(num);
    if (i == t.n || t.s[i] != '=') return fail(t.col + i, "expected '=' right after " + what);
    if (!known(num)) return true;  // the value may be anything (grblHAL has text settings)
    const Span v = t.from(i + 1);
    std::size_t e = 0;
    while (e < v.n && !blank(v.s[e])) ++e;
    const Span value = v.upto(e), rest = trim(v.from(e));
    if (!value.n) return fail(value.col, what + " needs a value");
    if (rest.n && (rest.s[0] != '(' || rest.s[rest.n - 1] != ')'))
      return fail(rest.col, "text after " + what + "'s value (grbl 0.9's note is in parentheses)");
    f_.keys.push_back(what);
    return setting_value(num, value, what);
  }

  static bool known(int32_t num) {
    return num == 13 || num == 20 || num == 22 || num == 23 || (num >= 110 && num <= 112) ||
           (num >= 120 && num <= 122) || (num >= 130 && num <= 132);
  }

  bool setting_value(int32_t num, const Span& v, const std::string& what) {
    Decimal d;
    int64_t x = 0;
    const bool is_num = decimal_all(v, &d);
    if (num == 13 || num == 20) {
      if (!whole(v, 0, 1, &x)) return fail(v.col, what + " is 0 or 1, not " + quoted(v));
      if (num == 13) inch_ = x != 0;
      else soft_limits_ = x != 0;
      return true;
    }
    if (num == 22 || num == 23) {
      if (!whole(v, 0, 65535, &x)) return fail(v.col, what + " is a mask, a whole number 0..65535, not " + quoted(v));
      (num == 22 ? homing_ : dir_mask_) = static_cast<uint32_t>(x);
      return true;
    }
    const int a = num % 10;
    if (num < 120) {
      if (!is_num || !scaled(d, kNmPerMm, 1, kMaxVelocityNmPerMin, &velocity_[a]))
        return fail(v.col, what + " is a rate in mm/min above 0 and at most 600000, not " + quoted(v));
    } else if (num < 130) {
      if (!is_num || !scaled(d, kNmPerMm, 1, kMaxAccelNmPerS2, &accel_[a]))
        return fail(v.col, what + " is an acceleration in mm/s^2 above 0 and at most 1000000, not " + quoted(v));
    } else if (!is_num || !scaled(d, kNmPerMm, 0, kLimitNm, &travel_[a])) {
      return fail(v.col, what + " is a travel in mm, 0 to 10000, not " + quoted(v));
    }
    return true;
  }

  // The coordinate system a [G5x: head names: 0..8, or -1.
  static int g5x(const Span& h) {
    static const char* const kNames[kMachineCoordSystems] = {"G54", "G55", "G56", "G57", "G58",
                                                             "G59", "G59.1", "G59.2", "G59.3"};
    for (int k = 0; k < kMachineCoordSystems; ++k)
      if (h.is(kNames[k])) return k;
    return -1;
  }

  bool report(const Span& t) {
    if (t.s[t.n - 1] != ']') return fail(t.col + t.n, "a report without its closing ']'");
    const std::size_t colon = t.find(':');
    if (colon == t.n) return fail(t.col, "expected a grbl report [NAME:...], not " + quoted(t));
    const Span head{t.s + 1, colon - 1, t.col + 1};
    const Span body{t.s + colon + 1, t.n - colon - 2, t.col + colon + 1};
    const std::string what = "[" + head.str() + ":";
    PointNm p{0, 0, 0};
    const int k = g5x(head);
    if (k >= 0 || head.is("G92")) {
      if (!coords(body, 3, &p, what)) return false;
      (k >= 0 ? f_.spec.work_offset[k] : f_.spec.g92) = p;
      return offsets_read(head);
    }
    if (head.is("G28") || head.is("G30")) return coords(body, 3, &p, what);
    if (head.is("TLO")) {
      if (!coords(body, 1, &p, what)) return false;
      f_.spec.tlo_nm = p.z_nm;
      return offsets_read(head);
    }
    if (head.is("PRB")) return probe(body, what);
    if (head.is("GC")) return modes(body);
    return true;  // [MSG:...], [VER:...], [OPT:...], ...: nothing of the machine
  }

  bool offsets_read(const Span& head) {
    f_.spec.have_offsets = true;
    f_.keys.push_back(head.str());
    return true;
  }

  // Comma-separated positions: 3 or more (a machine with more axes: the
  // first three are X, Y, Z), or with want 1 a single one, Z (a TLO).
  bool coords(const Span& body, int want, PointNm* p, const std::string& what) {
    int64_t v[3] = {0, 0, 0};
    int got = 0;
    std::size_t b = 0;
    for (std::size_t i = 0; i <= body.n; ++i) {
      if (i < body.n && body.s[i] != ',') continue;
      const Span w{body.s + b, i - b, body.col + b};
      Decimal d;
      int64_t x = 0;
      if (!decimal_all(w, &d) || !scaled(d, inch_ ? 25400000 : kNmPerMm, -kLimitNm, kLimitNm, &x))
        return fail(w.col, what + " holds positions in " + (inch_ ? "inch" : "mm") + " within +-10 m, not " +
                               quoted(w));
      if (got == 9) return fail(w.col, what + " has more than 9 axes");
      if (got < 3) v[got] = x;
      ++got;
      b = i + 1;
    }
    if (want == 1 && got == 1) v[2] = v[0];
    else if (got < 3) return fail(body.col, what + (want == 1 ? " needs Z (or X,Y,Z)" : " needs X,Y,Z"));
    *p = PointNm{v[0], v[1], v[2]};
    return true;
  }

  bool probe(const Span& body, const std::string& what) {
    PointNm p{0, 0, 0};
    std::size_t colon = body.n;
    while (colon > 0 && body.s[colon - 1] != ':') --colon;
    if (colon == 0) return coords(body, 3, &p, what);  // grbl 0.9: no success flag
    const Span flag = body.from(colon);
    if (!flag.is("0") && !flag.is("1")) return fail(flag.col, what + "'s success flag is 0 or 1, not " + quoted(flag));
    return coords(body.upto(colon - 1), 3, &p, what);
  }

  // $G's modes: the coordinate system in force.
  bool modes(const Span& body) {
    std::size_t b = 0;
    for (std::size_t i = 0; i <= body.n; ++i) {
      if (i < body.n && !blank(body.s[i])) continue;
      const int k = g5x(Span{body.s + b, i - b, body.col + b});
      if (k >= 0) {
        f_.spec.coord_system = static_cast<uint8_t>(k);
        f_.keys.push_back("GC");
      }
      b = i + 1;
    }
    return true;
  }

  bool inch_;
  MachineFile f_;
  int64_t velocity_[3] = {}, accel_[3] = {}, travel_[3] = {};
  bool soft_limits_ = false;
  uint32_t homing_ = 0, dir_mask_ = 0;
};

// $13 (the last one) before the rest: $#'s positions are in its units.
bool grbl_inch(const char* name, const char* text, std::size_t n) {
  Lines lines(name, text, n);
  Span l;
  uint32_t no = 0;
  std::string ignored;
  bool inch = false;
  while (lines.next(&l, &no, &ignored) == Next::kLine) {
    const Span t = trim(l);
    int64_t x = 0;
    if (!t.starts("$13=")) continue;
    Span v = t.from(4);
    std::size_t e = 0;
    while (e < v.n && !blank(v.s[e])) ++e;
    if (whole(v.upto(e), 0, 1, &x)) inch = x != 0;
  }
  return inch;
}

}  // namespace

bool parse_grbl(const char* name, const char* text, std::size_t n, MachineFile* out, std::string* err) {
  GrblParser p(name, grbl_inch(name, text, n));
  if (!each_line(name, text, n, err, [&](const Span& l, uint32_t no) { return p.line(l, no) || (*err = p.error(), false); }))
    return false;
  if (!p.finish(out)) return *err = p.error(), false;
  return true;
}

}  // namespace machine_text
}  // namespace dexmill
