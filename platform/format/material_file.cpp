// Material files; see material_file.h.
#include "platform/format/material_file.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "core/math/decimal.h"
#include "core/material/material_preset.h"
#include "platform/os/read_file.h"

namespace dexmill {
namespace {

constexpr int64_t kLimitNm = int64_t{10000} * 1000000;  // 10 m, as G-code coordinates

struct Word {
  const char* s;
  std::size_t n, col;  // col: 1-based
  bool is(const char* w) const { return std::strlen(w) == n && std::memcmp(s, w, n) == 0; }
  std::string str() const { return std::string(s, n); }
};

class Parser {
 public:
  Parser(const char* name, const BoxNm& stock) : name_(name), stock_(stock) { composition_clear(&c_); }

  bool line(const char* s, std::size_t n, uint32_t line_no) {
    line_ = line_no;
    std::vector<Word> w;
    for (std::size_t k = 0; k < n;) {
      if (s[k] == '#') break;
      if (s[k] == ' ' || s[k] == '\t' || s[k] == '\r') { ++k; continue; }
      const std::size_t b = k;
      while (k < n && s[k] != ' ' && s[k] != '\t' && s[k] != '\r' && s[k] != '#') ++k;
      w.push_back(Word{s + b, k - b, b + 1});
    }
    if (w.empty()) return true;
    const Word& head = w[0];
    if (head.is("preset")) return preset(w);
    if (head.is("material")) return material(w);
    if (head.is("layer")) return layer(w);
    if (head.is("box")) return box(w);
    if (head.is("cylinder")) return cylinder(w);
    if (head.is("default")) return set_default(w);
    return fail(head, "unknown statement '" + head.str() + "' (preset, material, layer, box, cylinder, default)");
  }

  bool finish(StockComposition* out) {
    if (line_ == 0) line_ = 1;  // an empty file
    if (c_.material_count == 0) return fail(Word{"", 0, 1}, "the file names no material");
    *out = c_;
    return true;
  }
  const std::string& error() const { return err_; }

 private:
  bool fail(const Word& at, const std::string& what) {
    char head[700];
    std::snprintf(head, sizeof head, "%s:%u:%zu: error: ", name_, static_cast<unsigned>(line_), at.col);
    err_ = head + what;
    return false;
  }

  bool count(const std::vector<Word>& w, std::size_t want, const char* form) {
    if (w.size() == want) return true;
    return fail(w.size() > want ? w[want] : w.back(), std::string("expected ") + form);
  }

  // A decimal in s[0, n) scaled (nm per mm, ...), within +-limit.
  static bool number(const char* s, std::size_t n, int64_t scale, int64_t limit, int64_t* out) {
    Decimal d;
    std::size_t pos = 0;
    if (n == 0 || decimal_parse(s, n, &pos, &d) != DecimalParse::kOk || pos != n) return false;
    *out = decimal_scale(d, scale);
    return *out >= -limit && *out <= limit;
  }

  // Comma-separated millimetre values, exactly `k` of them.
  bool mm_list(const Word& wd, std::size_t k, int64_t* v) {
    std::size_t got = 0, b = 0;
    for (std::size_t i = 0; i <= wd.n; ++i) {
      if (i < wd.n && wd.s[i] != ',') continue;
      if (got == k || !number(wd.s + b, i - b, 1000000, kLimitNm, &v[got]))
        return fail(wd, "'" + wd.str() + "' is not " + std::to_string(k) + " numbers in mm (comma-separated)");
      ++got;
      b = i + 1;
    }
    if (got != k) return fail(wd, "'" + wd.str() + "' is not " + std::to_string(k) + " numbers in mm (comma-separated)");
    return true;
  }

  bool material_index(const Word& wd, uint8_t* out) {
    for (int32_t k = 0; k < c_.material_count; ++k)
      if (wd.is(c_.materials[k].name)) {
        *out = static_cast<uint8_t>(k);
        return true;
      }
    return fail(wd, "no material named '" + wd.str() + "' (define it with a material line first)");
  }

  // The outcome of a composition_add_*: too many, or out of range.
  bool added(Status s, const Word& at, const std::string& what) {
    if (ok(s)) return true;
    return fail(at, s == Status::kBufferTooSmall ? "too many " + what : "an empty or out-of-range " + what);
  }

  bool preset(const std::vector<Word>& w) {
    if (!count(w, 2, "preset NAME")) return false;
    if (c_.material_count) return fail(w[0], "a preset must come before any material");
    const std::string name = w[1].str();
    if (!material_preset(name.c_str(), stock_, &c_)) {
      std::string names;
      for (int32_t k = 0; k < material_preset_count(); ++k) names += std::string(k ? ", " : "") + material_preset_name(k);
      return fail(w[1], "no preset named '" + name + "' (" + names + ")");
    }
    return true;
  }

  static bool rgb(const Word& v, std::size_t eq, Rgb8* out) {
    int64_t c[3];
    std::size_t got = 0, b = eq + 1;
    for (std::size_t i = b; i <= v.n; ++i) {
      if (i < v.n && v.s[i] != ',') continue;
      if (got == 3 || !number(v.s + b, i - b, 1, 255, &c[got]) || c[got] < 0) return false;
      ++got;
      b = i + 1;
    }
    if (got != 3) return false;
    *out = Rgb8{static_cast<uint8_t>(c[0]), static_cast<uint8_t>(c[1]), static_cast<uint8_t>(c[2])};
    return true;
  }

  bool material(const std::vector<Word>& w) {
    if (w.size() < 3) return fail(w.back(), "expected material NAME TEXTURE [KEY=VALUE ...]");
    Material m;
    const std::string name = w[1].str();
    if (!ok(material_set_name(&m, name.c_str())))
      return fail(w[1], "a material's name has 1 to " + std::to_string(kMaterialNameMax) + " characters");
    for (int32_t k = 0; k < c_.material_count; ++k)
      if (w[1].is(c_.materials[k].name)) return fail(w[1], "material '" + name + "' is already defined");
    const std::string tex = w[2].str();
    if (!texture_kind_from_name(tex.c_str(), &m.texture.kind))
      return fail(w[2], "unknown texture '" + tex + "' (plain, layers, marble, wood, bronze, granite)");
    for (std::size_t k = 3; k < w.size(); ++k)
      if (!option(w[k], &m)) return false;
    uint8_t index = 0;
    return added(composition_add_material(&c_, m, &index), w[1], "materials (at most " +
                 std::to_string(kCompositionMaxMaterials) + ")");
  }

  bool option(const Word& v, Material* m) {
    const char* eqp = static_cast<const char*>(std::memchr(v.s, '=', v.n));
    if (!eqp) return fail(v, "expected KEY=VALUE, not '" + v.str() + "'");
    const std::size_t eq = static_cast<std::size_t>(eqp - v.s);
    const Word key{v.s, eq, v.col};
    const char* val = v.s + eq + 1;
    const std::size_t vn = v.n - eq - 1;
    Texture& t = m->texture;
    MaterialProcess& p = m->process;
    int64_t x = 0;
    if (key.is("colour") || key.is("color") || key.is("vein")) {
      Rgb8 c;
      if (!rgb(v, eq, &c)) return fail(v, "a colour is R,G,B with each 0..255");
      const bool vein = key.is("vein");
      switch (t.kind) {
        case TextureKind::kPlain: if (vein) return fail(v, "a plain material has no veins"); t.plain = c; break;
        case TextureKind::kMarble: (vein ? t.marble.vein : t.marble.base) = c; break;
        case TextureKind::kWood: (vein ? t.wood.dark : t.wood.light) = c; break;
        case TextureKind::kBronze: if (vein) return fail(v, "bronze has no veins"); t.bronze.base = c; break;
        case TextureKind::kGranite: if (vein) return fail(v, "granite has no veins"); t.granite.base = c; break;
        case TextureKind::kLayers: return fail(v, "a layers texture takes its colours from its layers' materials");
      }
      return true;
    }
    if (key.is("period")) {
      if (!number(val, vn, 1000000, kLimitNm, &x) || x <= 0) return fail(v, "period is a length in mm above 0");
      if (t.kind == TextureKind::kMarble) t.marble.period_nm = x;
      else if (t.kind == TextureKind::kWood) t.wood.ring_pitch_nm = x;
      else return fail(v, "only marble and wood have a period");
      return true;
    }
    if (key.is("seed")) {
      if (!number(val, vn, 1, 4294967295LL, &x) || x < 0) return fail(v, "seed is a whole number 0..4294967295");
      const uint32_t s = static_cast<uint32_t>(x);
      t.marble.seed = t.wood.seed = t.bronze.seed = t.granite.seed = s;
      return true;
    }
    if (key.is("max_feed")) {
      if (!number(val, vn, 1000000, kLimitNm, &x) || x <= 0) return fail(v, "max_feed is a feed in mm/min above 0");
      p.max_feed_nm_per_min = x;
      return true;
    }
    if (key.is("spindle")) {
      const char* dots = nullptr;
      for (std::size_t i = 0; i + 1 < vn; ++i)
        if (val[i] == '.' && val[i + 1] == '.') { dots = val + i; break; }
      int64_t lo = 0, hi = 0;
      if (!dots || !number(val, static_cast<std::size_t>(dots - val), 1, 1000000, &lo) ||
          !number(dots + 2, vn - static_cast<std::size_t>(dots - val) - 2, 1, 1000000, &hi) || lo < 0 || hi < lo)
        return fail(v, "spindle is MIN..MAX in rpm, 0 <= MIN <= MAX <= 1000000");
      p.spindle_min_rpm = static_cast<int32_t>(lo);
      p.spindle_max_rpm = static_cast<int32_t>(hi);
      return true;
    }
    if (key.is("coolant")) {
      const Word vw{val, vn, v.col};
      if (vw.is("yes")) p.coolant_allowed = true;
      else if (vw.is("no")) p.coolant_allowed = false;
      else return fail(v, "coolant is yes or no");
      return true;
    }
    if (key.is("tolerance")) {
      if (!number(val, vn, 1000000, kLimitNm, &x) || x <= 0) return fail(v, "tolerance is a length in mm above 0");
      p.tolerance_nm = x;
      return true;
    }
    if (key.is("density")) {
      if (!number(val, vn, 1000, 100000, &x) || x <= 0) return fail(v, "density is g/cm3, above 0 and at most 100");
      p.density_mg_per_cm3 = static_cast<int32_t>(x);
      return true;
    }
    bool known = false;
    if (!cutting_option(v, key, val, vn, &p, &known)) return false;
    if (known) return true;
    return fail(v, "unknown key '" + key.str() +
                       "' (colour, vein, period, seed, max_feed, spindle, coolant, tolerance, density, kc1.1, mc, "
                       "max_chip)");
  }

  // The cutting keys (core/engage/engage_load.h): *known when key is one.
  bool cutting_option(const Word& v, const Word& key, const char* val, std::size_t vn, MaterialProcess* p, bool* known) {
    int64_t x = 0;
    *known = true;
    if (key.is("kc1.1") || key.is("kc11")) {
      if (!number(val, vn, 1, 100000, &x) || x <= 0) return fail(v, "kc1.1 is a force in N/mm2, 1..100000");
      p->kc11_n_per_mm2 = static_cast<int32_t>(x);
      return true;
    }
    if (key.is("mc")) {
      if (!number(val, vn, 1000000, 999999, &x) || x < 0) return fail(v, "mc is Kienzle's exponent, 0 <= mc < 1");
      p->mc_ppm = static_cast<int32_t>(x);
      return true;
    }
    if (key.is("max_chip")) {
      if (!number(val, vn, 1000000, 100000000, &x) || x <= 0) return fail(v, "max_chip is a chip per tooth in mm, above 0 and at most 100");
      p->max_chip_nm = x;
      return true;
    }
    *known = false;
    return true;
  }

  bool layer(const std::vector<Word>& w) {
    if (!count(w, 4, "layer Z0 Z1 NAME")) return false;
    int64_t z0 = 0, z1 = 0;
    if (!number(w[1].s, w[1].n, 1000000, kLimitNm, &z0)) return fail(w[1], "Z0 is a height in mm");
    if (!number(w[2].s, w[2].n, 1000000, kLimitNm, &z1)) return fail(w[2], "Z1 is a height in mm");
    if (z1 <= z0) return fail(w[2], "a layer's Z1 must be above its Z0");
    uint8_t m = 0;
    return material_index(w[3], &m) &&
           added(composition_add_layer(&c_, z0, z1, m), w[0], "layers (at most " + std::to_string(kCompositionMaxLayers) + ")");
  }

  bool box(const std::vector<Word>& w) {
    if (!count(w, 3, "box X0,Y0,Z0,X1,Y1,Z1 NAME")) return false;
    int64_t v[6];
    if (!mm_list(w[1], 6, v)) return false;
    if (v[3] <= v[0] || v[4] <= v[1] || v[5] <= v[2]) return fail(w[1], "a box needs X0<X1, Y0<Y1, Z0<Z1");
    uint8_t m = 0;
    return material_index(w[2], &m) &&
           added(composition_add_box(&c_, BoxNm{PointNm{v[0], v[1], v[2]}, PointNm{v[3], v[4], v[5]}}, m), w[0],
                 "inserts (at most " + std::to_string(kCompositionMaxInserts) + ")");
  }

  bool cylinder(const std::vector<Word>& w) {
    if (!count(w, 3, "cylinder X,Y,R,Z0,Z1 NAME")) return false;
    int64_t v[5];
    if (!mm_list(w[1], 5, v)) return false;
    if (v[2] <= 0 || v[2] > kCompositionMaxRadiusNm) return fail(w[1], "a cylinder's radius must be above 0 and at most 1 m");
    if (v[4] <= v[3]) return fail(w[1], "a cylinder's Z1 must be above its Z0");
    uint8_t m = 0;
    return material_index(w[2], &m) &&
           added(composition_add_cylinder(&c_, v[0], v[1], v[2], v[3], v[4], m), w[0],
                 "inserts (at most " + std::to_string(kCompositionMaxInserts) + ")");
  }

  bool set_default(const std::vector<Word>& w) {
    if (!count(w, 2, "default NAME")) return false;
    uint8_t m = 0;
    return material_index(w[1], &m) && added(composition_set_default(&c_, m), w[1], "default material");
  }

  const char* name_;
  BoxNm stock_;
  StockComposition c_;
  uint32_t line_ = 0;
  std::string err_;
};

}  // namespace

bool material_file_parse(const char* name, const char* text, std::size_t n, const BoxNm& stock, StockComposition* out,
                         std::string* err) {
  // The composition is a few KB: on the heap, not the stack.
  std::unique_ptr<Parser> p(new Parser(name, stock));
  uint32_t line = 0;
  for (std::size_t b = 0; b < n;) {
    std::size_t e = b;
    while (e < n && text[e] != '\n') ++e;
    ++line;
    if (std::memchr(text + b, '\0', e - b)) {
      char head[700];
      std::snprintf(head, sizeof head, "%s:%u:1: error: a NUL byte (is this a text file?)", name, static_cast<unsigned>(line));
      *err = head;
      return false;
    }
    if (!p->line(text + b, e - b, line)) {
      *err = p->error();
      return false;
    }
    b = e + 1;
  }
  if (!p->finish(out)) {
    *err = p->error();
    return false;
  }
  return true;
}

MaterialLoad material_file_load(const std::string& path, const BoxNm& stock, StockComposition* out, std::string* err) {
  std::vector<unsigned char> bytes;
  const ReadFile r = read_whole_file(path, kMaterialFileMaxBytes, &bytes, err);
  if (r == ReadFile::kIoError) return MaterialLoad::kIoError;
  if (r != ReadFile::kOk) return MaterialLoad::kInputError;
  return material_file_parse(path.c_str(), reinterpret_cast<const char*>(bytes.data()), bytes.size(), stock, out, err)
             ? MaterialLoad::kOk
             : MaterialLoad::kInputError;
}

}  // namespace dexmill
