// LinuxCNC INI files; see machine_file.h.
#include <cstdlib>
#include <utility>

#include "platform/format/machine_text.h"

namespace dexmill {
namespace machine_text {
namespace {

// Resolves a path of an INI file against its folder; "~/" is $HOME's.
std::string resolve(const std::string& dir, const std::string& p) {
  if (p.empty() || p[0] == '/') return p;
  if (p.size() >= 2 && p[0] == '~' && p[1] == '/') {
    const char* home = std::getenv("HOME");
    return home && *home ? std::string(home) + p.substr(1) : p;
  }
  std::string q = p;
  while (q.size() >= 2 && q[0] == '.' && q[1] == '/') q.erase(0, 2);
  if (dir.empty() || dir == ".") return q.empty() ? std::string(".") : q;
  if (q.empty()) return dir;
  return dir.back() == '/' ? dir + q : dir + "/" + q;
}



// LinuxCNC 2.8's joints: [JOINT_0] .. [JOINT_8], each a joint of the
// kinematics; with trivkins joint n moves the axis its `coordinates=`
// letter names (XYZABCUVW in order by default). A move must stay within
// both the axis's and its joints' limits (the planner keeps to the axis's,
// motion faults on a joint's), so an axis's travel is the intersection of
// its own and its joints', and its velocity and acceleration the least.
constexpr int kJoints = 9;
enum Sec : uint8_t {
  kSecOther, kSecTraj, kSecAxisX, kSecAxisY, kSecAxisZ, kSecEmcio, kSecRs274, kSecDisplay, kSecKins, kSecJoint0,
  kSecCount = kSecJoint0 + kJoints
};
const char* const kSecNames[kSecCount] = {"",        "TRAJ",    "AXIS_X",  "AXIS_Y",  "AXIS_Z",  "EMCIO",
                                          "RS274NGC", "DISPLAY", "KINS",    "JOINT_0", "JOINT_1", "JOINT_2",
                                          "JOINT_3", "JOINT_4", "JOINT_5", "JOINT_6", "JOINT_7", "JOINT_8"};

// The keys read; an axis's four follow kKeyAxis, axis by axis, then the
// joints' four, joint by joint.
enum Key : uint8_t {
  kKeyUnits, kKeyToolTable, kKeySubPath, kKeyParamFile, kKeyG92Volatile, kKeyFeedOverride, kKeyKinematics, kKeyAxis
};
enum AxisField : uint8_t { kMinLimit, kMaxLimit, kMaxVelocity, kMaxAccel, kAxisFields };
const char* const kAxisKeys[kAxisFields] = {"MIN_LIMIT", "MAX_LIMIT", "MAX_VELOCITY", "MAX_ACCELERATION"};

bool linuxcnc_section(const Span& s) {
  static const char* const kNames[] = {"EMC",   "TRAJ",     "KINS",    "EMCMOT", "TASK", "HAL",
                                       "HALUI", "EMCIO",    "RS274NGC", "DISPLAY", "FILTER"};
  for (const char* k : kNames)
    if (s.is(k)) return true;
  return s.starts("AXIS_") || s.starts("JOINT_") || s.starts("SPINDLE_");
}

class IniParser : public ReaderPlace {
 public:
  // units_only: the first pass, which finds LINEAR_UNITS alone (the values
  // before it in the file are in its units too).
  IniParser(const char* name, const std::string& dir, bool units_only, bool inch)
      : ReaderPlace(name), dir_(dir), units_only_(units_only), inch_(inch) {}

  bool line(Span raw, uint32_t no) {
    line_ = no;
    const Span t = trim(raw);
    if (!t.n || t.s[0] == '#' || t.s[0] == ';') return true;
    if (t.s[0] == '[') return section(t);
    const std::size_t eq = t.find('=');
    if (eq == t.n) return fail(t.col, "expected KEY = VALUE or a [SECTION] line, not " + quoted(t));
    const Span key = trim(t.upto(eq));
    if (!key.n) return fail(t.col + eq, "no key before '='");
    return assign(key, trim(t.from(eq + 1)), t.col + eq + 1);
  }

  bool finish(MachineFile* out) {
    if (!any_linuxcnc_) {
      line_ = 1;
      return fail(1, kNotMachine);
    }
    if (!join_joints()) return false;
    f_.spec.kind = MachineKind::kLinuxcnc;
    f_.spec.inch = inch_;
    for (int a = 0; a < 3; ++a) f_.spec.axis[a].limited = have_min_[a] && have_max_[a];
    *out = std::move(f_);
    return true;
  }

  bool inch() const { return inch_; }

 private:
  bool section(const Span& t) {
    const std::size_t close = t.find(']');
    if (close == t.n) return fail(t.col, "a section line without its ']'");
    const Span name{t.s + 1, close - 1, t.col + 1};
    if (!name.n) return fail(t.col, "an empty section name");
    const Span rest = trim(t.from(close + 1));
    if (rest.n && rest.s[0] != '#' && rest.s[0] != ';') return fail(rest.col, "text after the section's ']'");
    any_linuxcnc_ = any_linuxcnc_ || linuxcnc_section(name);
    sec_ = kSecOther;
    for (uint8_t k = 1; k < kSecCount; ++k)
      if (name.is(kSecNames[k])) sec_ = static_cast<Sec>(k);
    if (sec_ != kSecOther) {
      const uint32_t bit = 1u << sec_;
      if (seen_ & bit) sec_ = kSecOther;  // a repeat: LinuxCNC reads the first alone
      seen_ |= bit;
    }
    return true;
  }

  // The key `key` names in the section in force, if one that is read.
  bool key_of(const Span& key, int* k) const {
    switch (sec_) {
      case kSecTraj: *k = kKeyUnits; return key.is("LINEAR_UNITS");
      case kSecEmcio: *k = kKeyToolTable; return key.is("TOOL_TABLE");
      case kSecDisplay: *k = kKeyFeedOverride; return key.is("MAX_FEED_OVERRIDE");
      case kSecKins: *k = kKeyKinematics; return key.is("KINEMATICS");
      case kSecRs274:
        if (key.is("SUBROUTINE_PATH")) *k = kKeySubPath;
        else if (key.is("PARAMETER_FILE")) *k = kKeyParamFile;
        else if (key.is("DISABLE_G92_PERSISTENCE")) *k = kKeyG92Volatile;
        else return false;
        return true;
      case kSecAxisX: case kSecAxisY: case kSecAxisZ:
        for (int f = 0; f < kAxisFields; ++f)
          if (key.is(kAxisKeys[f])) {
            *k = kKeyAxis + (sec_ - kSecAxisX) * kAxisFields + f;
            return true;
          }
        return false;
      default:
        if (sec_ < kSecJoint0) return false;
        for (int f = 0; f < kAxisFields; ++f)
          if (key.is(kAxisKeys[f])) {
            *k = kKeyAxis + (3 + sec_ - kSecJoint0) * kAxisFields + f;
            return true;
          }
        return false;
    }
  }

  bool assign(const Span& key, const Span& val, std::size_t val_col) {
    int k = 0;
    if (!key_of(key, &k)) return true;  // not one of ours
    const uint64_t bit = uint64_t{1} << k;
    if (given_ & bit) return true;  // the first counts (LinuxCNC's inifile)
    given_ |= bit;
    const std::string what = "[" + std::string(kSecNames[sec_]) + "]" + key.str();
    if (units_only_) {
      bool is_inch = false;
      if (k == kKeyUnits && units(val, &is_inch)) inch_ = is_inch;
      return true;
    }
    if (!val.n) return fail(val_col, what + " needs a value");
    f_.keys.push_back(what);
    if (k >= kKeyAxis) return axis_value((k - kKeyAxis) / kAxisFields, (k - kKeyAxis) % kAxisFields, val, what);
    switch (k) {
      case kKeyUnits: {
        bool is_inch = false;
        if (!units(val, &is_inch))
          return fail(val.col, what + " is mm, inch (metric, in, imperial), 1 or 0.03937, not " + quoted(val));
        return true;  // the first pass found it (inch_)
      }
      case kKeyToolTable: f_.tool_table = resolve(dir_, val.str()); return true;
      case kKeyParamFile: f_.parameter_file = resolve(dir_, val.str()); return true;
      case kKeySubPath: f_.subroutine_path = path_list(val); return true;
      case kKeyG92Volatile: return boolean(val, what, &f_.disable_g92_persistence);
      case kKeyKinematics: return kinematics(val);
      default: {
        Decimal d;
        int64_t ppm = 0;
        if (!decimal_all(number_part(val), &d) || !scaled(d, 1000000, 1, kMaxFeedOverridePpm, &ppm))
          return fail(val.col, what + " is a ratio above 0 and at most 100 (1.2: 120 %), not " + quoted(val));
        f_.spec.max_feed_override_ppm = static_cast<int32_t>(ppm);
        return true;
      }
    }
  }

  // LINEAR_UNITS: a name (any case), or a number LinuxCNC takes as units
  // per mm, 1 or 1/25.4 (within 1e-4 of it: 0.03937 is one).
  static bool units(const Span& v, bool* is_inch) {
    if (v.is_nocase("mm") || v.is_nocase("metric")) return *is_inch = false, true;
    if (v.is_nocase("in") || v.is_nocase("inch") || v.is_nocase("imperial")) return *is_inch = true, true;
    Decimal d;
    if (!decimal_all(number_part(v), &d)) return false;
    int64_t x = 0;
    if (scaled(d, 10000000, 9999000, 10001000, &x)) return *is_inch = false, true;
    if (scaled(d, 254000000, 9999000, 10001000, &x)) return *is_inch = true, true;
    return false;
  }

  bool boolean(const Span& v, const std::string& what, bool* out) {
    static const char* const kTrue[] = {"1", "true", "yes", "on"};
    static const char* const kFalse[] = {"0", "false", "no", "off"};
    for (int i = 0; i < 4; ++i) {
      if (v.is_nocase(kTrue[i])) return *out = true, true;
      if (v.is_nocase(kFalse[i])) return *out = false, true;
    }
    return fail(v.col, what + " is 1, yes, on, true or 0, no, off, false, not " + quoted(v));
  }

  std::string path_list(const Span& v) const {
    std::string out;
    std::size_t b = 0;
    for (std::size_t i = 0; i <= v.n; ++i) {
      if (i < v.n && v.s[i] != ':') continue;
      const std::string one = trim(Span{v.s + b, i - b, 1}).str();
      if (!one.empty()) out += (out.empty() ? "" : ":") + resolve(dir_, one);
      b = i + 1;
    }
    return out;
  }

  // [KINS] KINEMATICS: which axis each joint moves, where trivkins says
  // (its `coordinates=` letters, joint by joint); other kinematics map
  // joints to no axis, and their limits are not the axes'.
  bool kinematics(const Span& v) {
    for (int j = 0; j < kJoints; ++j) joint_axis_[j] = -1;
    const std::string t = v.str();
    if (t.compare(0, 8, "trivkins") != 0 || (t.size() > 8 && t[8] != ' ' && t[8] != '\t')) return true;
    const std::size_t at = t.find("coordinates=");
    const std::string letters = at == std::string::npos ? std::string("XYZABCUVW") : t.substr(at + 12);
    for (std::size_t j = 0; j < letters.size() && j < static_cast<std::size_t>(kJoints); ++j) {
      const char c = letters[j];
      if (c == ' ' || c == '\t') break;
      joint_axis_[j] = (c == 'X' || c == 'x') ? 0 : (c == 'Y' || c == 'y') ? 1 : (c == 'Z' || c == 'z') ? 2 : -1;
    }
    return true;
  }

  // Each axis within its joints' limits too (the comment at kJoints).
  bool join_joints() {
    for (int j = 0; j < kJoints; ++j) {
      const int a = joint_axis_[j];
      if (a < 0) continue;
      MachineAxis& ax = f_.spec.axis[a];
      const MachineAxis& jt = joint_[j];
      if (jt.max_velocity_nm_per_min && (!ax.max_velocity_nm_per_min || jt.max_velocity_nm_per_min < ax.max_velocity_nm_per_min))
        ax.max_velocity_nm_per_min = jt.max_velocity_nm_per_min;
      if (jt.max_accel_nm_per_s2 && (!ax.max_accel_nm_per_s2 || jt.max_accel_nm_per_s2 < ax.max_accel_nm_per_s2))
        ax.max_accel_nm_per_s2 = jt.max_accel_nm_per_s2;
      if (joint_min_[j]) ax.min_nm = have_min_[a] && ax.min_nm > jt.min_nm ? ax.min_nm : jt.min_nm;
      if (joint_max_[j]) ax.max_nm = have_max_[a] && ax.max_nm < jt.max_nm ? ax.max_nm : jt.max_nm;
      have_min_[a] = have_min_[a] || joint_min_[j];
      have_max_[a] = have_max_[a] || joint_max_[j];
      if (have_min_[a] && have_max_[a] && ax.min_nm > ax.max_nm) {
        line_ = joint_line_[j];
        return fail(1, std::string("[") + kSecNames[kSecJoint0 + j] + "]'s limits leave its axis " + "XYZ"[a] +
                           " no travel within [" + kSecNames[kSecAxisX + a] + "]'s");
      }
    }
    return true;
  }

  // A value of [AXIS_*] (a < 3) or of [JOINT_(a - 3)].
  bool axis_value(int a, int field, const Span& val, const std::string& what) {
    const char* unit = inch_ ? "inch" : "mm";
    const int64_t per = inch_ ? 25400000 : kNmPerMm;  // nm per unit
    const bool joint = a >= 3;
    MachineAxis& ax = joint ? joint_[a - 3] : f_.spec.axis[a];
    bool& have_min = joint ? joint_min_[a - 3] : have_min_[a];
    bool& have_max = joint ? joint_max_[a - 3] : have_max_[a];
    if (joint) joint_line_[a - 3] = line_;
    Decimal d;
    const bool num = decimal_all(number_part(val), &d);
    int64_t v = 0;
    switch (field) {
      case kMaxVelocity:
        if (!num || !scaled(d, per * 60, 1, kMaxVelocityNmPerMin, &v))
          return fail(val.col, what + " is a speed in " + unit + " per second, above 0 and at most 10 m/s, not " +
                                   quoted(val));
        ax.max_velocity_nm_per_min = v;
        return true;
      case kMaxAccel:
        if (!num || !scaled(d, per, 1, kMaxAccelNmPerS2, &v))
          return fail(val.col, what + " is an acceleration in " + unit +
                                   " per second^2, above 0 and at most 1000 m/s^2, not " + quoted(val));
        ax.max_accel_nm_per_s2 = v;
        return true;
      default:
        if (!num || !scaled(d, per, -kLimitNm, kLimitNm, &v))
          return fail(val.col, what + " is a position in " + unit + " within +-10 m, not " + quoted(val));
        (field == kMinLimit ? ax.min_nm : ax.max_nm) = v;
        (field == kMinLimit ? have_min : have_max) = true;
        if (have_min && have_max && ax.min_nm > ax.max_nm)
          return fail(val.col, std::string("[") + kSecNames[joint ? kSecJoint0 + a - 3 : kSecAxisX + a] +
                                   "] MIN_LIMIT is above its MAX_LIMIT");
        return true;
    }
  }

  const std::string& dir_;
  bool units_only_, inch_;
  MachineFile f_;
  Sec sec_ = kSecOther;
  uint32_t seen_ = 0;
  uint64_t given_ = 0;
  bool any_linuxcnc_ = false;
  bool have_min_[3] = {}, have_max_[3] = {};
  MachineAxis joint_[kJoints];
  bool joint_min_[kJoints] = {}, joint_max_[kJoints] = {};
  uint32_t joint_line_[kJoints] = {};
  int8_t joint_axis_[kJoints] = {0, 1, 2, -1, -1, -1, -1, -1, -1};  // trivkins' XYZ.. without a [KINS] line
};

// Feeds the INI's lines to p, a line ending in '\' joined with the next.
bool run_ini(IniParser* p, const char* name, const char* text, std::size_t n, std::string* err) {
  Lines lines(name, text, n);
  std::string joined;
  uint32_t first = 0;
  bool joining = false;
  for (;;) {
    Span l;
    uint32_t no = 0;
    const Next r = lines.next(&l, &no, err);
    if (r == Next::kBad) return false;
    if (r == Next::kEnd) break;
    const bool more = l.n && l.s[l.n - 1] == '\\';
    if (!more && !joining) {
      if (!p->line(l, no)) return *err = p->error(), false;
      continue;
    }
    if (!joining) {
      joined.clear();
      first = no;
      joining = true;
    }
    joined.append(l.s, more ? l.n - 1 : l.n);
    if (more) continue;
    joining = false;
    if (!p->line(Span{joined.data(), joined.size(), 1}, first)) return *err = p->error(), false;
  }
  if (joining && !p->line(Span{joined.data(), joined.size(), 1}, first)) return *err = p->error(), false;
  return true;
}

}  // namespace

bool parse_ini(const char* name, const char* text, std::size_t n, const std::string& dir, MachineFile* out,
               std::string* err) {
  IniParser units(name, dir, true, false);
  std::string ignored;
  run_ini(&units, name, text, n, &ignored);  // its errors are the second pass's too
  IniParser p(name, dir, false, units.inch());
  if (!run_ini(&p, name, text, n, err)) return false;
  if (!p.finish(out)) return *err = p.error(), false;
  return true;
}

}  // namespace machine_text
}  // namespace dexmill
