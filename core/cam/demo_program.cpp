// Generator of the built-in demo program; see demo_program.h. All geometry is
// in integer micrometres and the sines come from core/math/trig.h, so the text is
// the same on every machine.
#include "core/cam/demo_program.h"

#include "core/math/fixed.h"
#include "core/math/text_out.h"
#include "core/math/trig.h"

namespace dexmill {
namespace {

// Pocket (um) and the relief left in it.
constexpr int32_t kPx0 = 20000, kPx1 = 80000, kPy0 = 15000, kPy1 = 55000;
constexpr int32_t kFloor = -9000;
constexpr int32_t kToolR = 3000;

// Relief height (um, z) at (x, y): a paraboloid dome of 6 mm on the 9 mm
// deep floor, with diagonal ripples of 0.8 mm.
int32_t relief(int32_t x, int32_t y) {
  const int64_t dx = x - 50000, dy = y - 35000, r = 14000;
  const int64_t d2 = dx * dx + dy * dy;
  const int64_t dome = d2 < r * r ? 6000 * (r * r - d2) / (r * r) : 0;
  const int64_t phase = static_cast<int64_t>(x) + y / 2;
  const uint32_t a = static_cast<uint32_t>((phase * 4294967296LL) / 12000);
  const int64_t ripple = 400 + (400 * static_cast<int64_t>(sincos_bam(a).sin_q30)) / (1 << 30);
  return static_cast<int32_t>(kFloor + dome + ripple);
}

// The highest relief within a disc of radius rr around (x, y), sampled on a
// 0.5 mm lattice (what the roughing must stay above).
int32_t relief_max(int32_t x, int32_t y, int32_t rr) {
  int32_t m = INT32_MIN;
  for (int32_t dy = -rr; dy <= rr; dy += 500)
    for (int32_t dx = -rr; dx <= rr; dx += 500)
      if (static_cast<int64_t>(dx) * dx + static_cast<int64_t>(dy) * dy <= static_cast<int64_t>(rr) * rr)
        m = max_of(m, relief(x + dx, y + dy));
  return m;
}

// Drop cutter: the lowest tip height of a ball of radius R at (x, y) that
// touches the relief nowhere below it.
int32_t ball_tip(int32_t x, int32_t y) {
  int32_t z = INT32_MIN;
  for (int32_t dy = -kToolR; dy <= kToolR; dy += 500) {
    for (int32_t dx = -kToolR; dx <= kToolR; dx += 500) {
      const int64_t d2 = static_cast<int64_t>(dx) * dx + static_cast<int64_t>(dy) * dy;
      if (d2 > static_cast<int64_t>(kToolR) * kToolR) continue;
      const int32_t lift = kToolR - static_cast<int32_t>(isqrt_u64(static_cast<uint64_t>(kToolR) * kToolR - d2));
      z = max_of(z, relief(x + dx, y + dy) - lift);
    }
  }
  return z;
}

// The text into the caller's buffer (TextOut: what fits, the whole length counted).
class Writer {
 public:
  explicit Writer(TextOut* o) : text(*o) {}
  TextOut& text;

  void line(const char* s) {
    text.puts(s);
    text.put('\n');
  }
  // "G1 X.. Y.. Z.." with each axis given (INT32_MIN: left out), um -> mm.
  void move(const char* code, int32_t x, int32_t y, int32_t z, int32_t feed = 0) {
    text.puts(code);
    axis('X', x);
    axis('Y', y);
    axis('Z', z);
    if (feed) axis('F', feed * 1000);
    text.put('\n');
  }
  // " X-12.5": um as mm, the shortest exact decimals.
  void axis(char letter, int32_t um) {
    if (um == INT32_MIN) return;
    const int64_t a = um < 0 ? -static_cast<int64_t>(um) : um;
    int64_t frac = a % 1000;
    text.put(' ');
    text.put(letter);
    if (um < 0) text.put('-');
    text.put_uint(static_cast<uint64_t>(a / 1000));
    if (!frac) return;
    text.put('.');
    for (int64_t d = 100; frac; d /= 10) {
      text.put(static_cast<char>('0' + frac / d));
      frac %= d;
    }
  }
  // "G3 X<x> Y<y> <rest>\n" of whole mm (the contour's corners).
  void arc_mm(int32_t x_mm, int32_t y_mm, const char* rest) {
    text.puts("G3 X");
    text.put_int(x_mm);
    text.puts(" Y");
    text.put_int(y_mm);
    text.put(' ');
    text.puts(rest);
    text.put('\n');
  }
};

constexpr int32_t kNone = INT32_MIN;
constexpr int32_t kSafe = 5000;

}  // namespace

bool demo_design_top_um(int32_t x, int32_t y, int32_t* z) {
  auto within = [](int64_t dx, int64_t dy, int64_t r) { return dx * dx + dy * dy <= r * r; };
  const int32_t holes[4][2] = {{7000, 7000}, {93000, 7000}, {93000, 63000}, {7000, 63000}};
  for (const auto& h : holes)
    if (within(x - h[0], y - h[1], 2500)) return false;  // the spot drill's 5 mm shaft, through
  for (int32_t cx : {8000, 92000})
    if (within(x - cx, y - 35000, 5000)) {
      *z = -8000;
      return true;
    }
  // The pocket: the roughing passes run to 3 mm from its walls, so its
  // corners are the 6 mm tool's, 3 mm radii.
  const int32_t rc = kToolR;
  if (x >= kPx0 && x <= kPx1 && y >= kPy0 && y <= kPy1) {
    const int32_t qx = x < kPx0 + rc ? kPx0 + rc : x > kPx1 - rc ? kPx1 - rc : x;
    const int32_t qy = y < kPy0 + rc ? kPy0 + rc : y > kPy1 - rc ? kPy1 - rc : y;
    if (within(x - qx, y - qy, rc)) {
      // The contour passes at each level leave a flat band one tool wide
      // along the walls at the floor; the relief rises inside it.
      const bool band = x < kPx0 + 2 * kToolR || x > kPx1 - 2 * kToolR || y < kPy0 + 2 * kToolR || y > kPy1 - 2 * kToolR;
      *z = band ? kFloor : relief(x, y);
      return true;
    }
  }
  *z = 0;
  return true;
}

const char* demo_tool_table() {
  return "; dexmill demo tool table (LinuxCNC format; the shape comes from the comment)\n"
         "T1 P1 D6.0 Z+30.0 ;flat end mill 6 mm\n"
         "T2 P2 D6.0 Z+35.0 ;ball end mill 6 mm\n"
         "T3 P3 D5.0 Z+40.0 ;spot drill vbit:5:118\n";
}

const char* demo_stock() { return "0,0,-20,100,70,0"; }

const char* demo_material() { return "wood-on-aluminium"; }

size_t demo_program_write(char* buf, size_t n) {
  TextOut out{buf, n, 0};
  Writer w(&out);
  w.line("(dexmill demo: a 100 x 70 x 20 mm block, Z0 on its top, X0 Y0 at its front left corner)");
  w.line("(simulate it yourself: dexmill run out/demo.ngc --stock 0,0,-20,100,70,0 --tools TABLE)");
  w.line("G21 G90 G17 G94 G54");
  w.line("G0 Z10");
  w.line("(T1: flat end mill 6 mm)");
  w.line("T1 M6");
  w.line("S12000 M3");
  w.line("G0 Z5");
  w.line("(helical bores, 10 mm, 8 mm deep)");
  for (int32_t cx : {8000, 92000}) {
    w.move("G0", cx + 2000, 35000, kNone);
    w.move("G0", kNone, kNone, 1000);
    w.move("G1", kNone, kNone, 0, 300);
    for (int32_t z = -1000; z >= -8000; z -= 1000) {
      w.text.puts("G3");
      w.axis('X', cx + 2000);
      w.axis('Y', 35000);
      w.axis('Z', z);
      w.text.puts(" I-2 J0 F600\n");
    }
    w.line("G3 I-2 J0");  // a last flat turn at the bottom
    w.move("G0", kNone, kNone, kSafe);
  }
  w.line("(waterline roughing of the pocket, 0.3 mm left on the relief)");
  const int32_t cx0 = kPx0 + kToolR, cx1 = kPx1 - kToolR, cy0 = kPy0 + kToolR, cy1 = kPy1 - kToolR;
  for (int32_t level = -2000; level >= kFloor; level = level == -8000 ? kFloor : level - 2000) {
    w.text.puts("(level Z");
    w.text.put_int(level / 1000);
    w.line(")");
    for (int32_t y = cy0; y <= cy1; y += 2500) {
      int32_t run_start = kNone, last_ok = kNone;
      for (int32_t x = cx0; x <= cx1 + 500; x += 500) {
        const bool ok = x <= cx1 && relief_max(x, y, kToolR + 300) <= level - 300;
        if (ok) {
          if (run_start == kNone) run_start = x;
          last_ok = x;
          continue;
        }
        if (run_start != kNone) {
          w.move("G0", run_start, y, kNone);
          w.move("G0", kNone, kNone, level + 1000);
          w.move("G1", kNone, kNone, level, 300);
          w.move("G1", last_ok, kNone, kNone, 1200);
          w.move("G0", kNone, kNone, kSafe);
          run_start = kNone;
        }
      }
    }
    // Contour along the pocket's walls (6 mm corner radius: 3 mm arcs).
    const int32_t r = 3000;
    w.move("G0", cx0 + r, cy0, kNone);
    w.move("G0", kNone, kNone, level + 1000);
    w.move("G1", kNone, kNone, level, 300);
    w.move("G1", cx1 - r, kNone, kNone, 1200);
    w.arc_mm(cx1 / 1000, (cy0 + r) / 1000, "I0 J3");
    w.move("G1", kNone, cy1 - r, kNone);
    w.arc_mm((cx1 - r) / 1000, cy1 / 1000, "I-3 J0");
    w.move("G1", cx0 + r, kNone, kNone);
    w.arc_mm(cx0 / 1000, (cy1 - r) / 1000, "I0 J-3");
    w.move("G1", kNone, cy0 + r, kNone);
    w.arc_mm((cx0 + r) / 1000, cy0 / 1000, "I3 J0");
    w.move("G0", kNone, kNone, kSafe);
    if (level == kFloor) break;
  }
  w.line("(T2: ball end mill 6 mm, zig finishing of the relief)");
  w.line("G0 Z10");
  w.line("T2 M6");
  w.line("S14000 M3");
  bool first = true;
  for (int32_t y = cy0; y <= cy1; y += 600) {
    w.move("G0", cx0, y, kNone);
    w.move("G0", kNone, kNone, first ? 2000 : ball_tip(cx0, y) + 1000);
    first = false;
    w.move("G1", kNone, kNone, ball_tip(cx0, y), 400);
    bool feed_set = false;
    for (int32_t x = cx0 + 500; x <= cx1; x += 500) {
      w.move("G1", x, kNone, ball_tip(x, y), feed_set ? 0 : 1500);
      feed_set = true;
    }
    w.move("G0", kNone, kNone, kSafe);
  }
  w.line("(T3: spot drill, four through holes)");
  w.line("G0 Z10");
  w.line("T3 M6");
  // 12000 rpm: the lowest the beech of the demo's block allows (and
  // within the aluminium's range), so the process rules pass.
  w.line("S12000 M3");
  w.line("G98 G81 X7 Y7 Z-22 R2 F200");
  w.line("X93");
  w.line("Y63");
  w.line("X7");
  w.line("G80");
  w.line("G0 Z20");
  w.line("M5");
  w.line("M30");
  (void)out.end();
  return out.len;
}

}  // namespace dexmill
