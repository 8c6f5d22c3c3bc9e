// The zig-milling program; see zig_program.h.
#include "tools/cam/zig_program.h"

#include <vector>

#include "core/math/fixed.h"
#include "platform/os/clock.h"
#include "tools/cam/feed_word.h"

namespace dexmill {
namespace cli {
namespace {

// nm as mm, exact (6 decimals, trailing zeros dropped).
std::string mm(int64_t nm) { return decimal_text(Decimal{nm, 6}); }

struct Writer {
  std::string* text;
  void line(const std::string& s) {
    text->append(s);
    text->push_back('\n');
  }
};

}  // namespace

bool zig_program(const DesignGrid& d, const ToolProfile& p, const ZigProgramOptions& o, int64_t floor_nm,
                 std::string* text, ZigProgramStats* stats, std::string* err) {
  const double t0 = clock_now_s();
  const GridGeometry& g = d.geo;
  std::vector<int32_t> words(zig_tool_words(p, g));
  ZigTool t;
  if (!ok(zig_tool_build(p, g, words.data(), words.size(), &t))) {
    *err = "the tool is too large for the design's pitch (over " + std::to_string(kZigMaxReach) + " dexels of radius)";
    return false;
  }
  const ZigOptions& zo = o.zig;
  const int64_t floor_lsb = div_ceil(floor_nm - g.z0_nm, g.lsb_nm);
  std::vector<int64_t> scratch(zig_stripe_scratch(d, t, zo));
  const int32_t n = zig_positions(d, zo), stripes = zig_stripe_count(d, zo);
  std::vector<int64_t> z(static_cast<size_t>(n)), next(static_cast<size_t>(n));
  const char ua = zo.along_y ? 'Y' : 'X', va = zo.along_y ? 'X' : 'Y';
  auto u_nm = [&](int32_t u) { return (zo.along_y ? g.y0_nm : g.x0_nm) + static_cast<int64_t>(u) * g.pitch_nm; };
  auto v_nm = [&](int32_t v) { return (zo.along_y ? g.x0_nm : g.y0_nm) + static_cast<int64_t>(v) * g.pitch_nm; };
  auto z_nm = [&](int64_t lsb) { return g.z0_nm + lsb * g.lsb_nm; };
  const std::string feed = " F" + mm(o.feed_nm_per_min), plunge = " F" + mm(o.plunge_nm_per_min);

  Writer w{text};
  for (size_t at = 0; at < o.header.size();) {
    size_t end = o.header.find('\n', at);
    if (end == std::string::npos) end = o.header.size();
    w.line("(" + o.header.substr(at, end - at) + ")");
    at = end + 1;
  }
  w.line("G21 G90 G17 G94");
  w.line("S" + std::to_string(o.spindle_rpm) + " M3");
  w.line("G0 Z" + mm(o.safe_z_nm));
  if (!ok(zig_stripe(d, t, zo, 0, floor_lsb, scratch.data(), scratch.size(), next.data()))) {
    *err = "zig: scratch";
    return false;
  }
  uint64_t moves = 0;
  for (int32_t s = 0; s < stripes; ++s) {
    z.swap(next);
    if (s + 1 < stripes) (void)zig_stripe(d, t, zo, s + 1, floor_lsb, scratch.data(), scratch.size(), next.data());
    const int32_t v = zig_stripe_row(d, zo, s);
    const bool reverse = o.zigzag && s % 2 == 1;
    auto pos = [&](int32_t m) { return reverse ? n - 1 - m : m; };  // the m-th position in cutting order
    const int32_t k0 = pos(0);
    if (s == 0 || !o.zigzag) {
      w.line("G0 " + std::string(1, ua) + mm(u_nm(zig_position_u(d, zo, k0))) + " " + std::string(1, va) + mm(v_nm(v)));
      w.line("G1 Z" + mm(z_nm(z[static_cast<size_t>(k0)])) + plunge);
      ++moves;
    }
    // The positions in order, each dropped when it lies on the straight
    // line from the last one written to the next.
    int32_t last = 0;
    bool first = true;
    for (int32_t m = 1; m < n; ++m) {
      const int32_t k = pos(m), kl = pos(last);
      if (m + 1 < n) {
        const int32_t kn = pos(m + 1);
        const int64_t ul = zig_position_u(d, zo, kl), uk = zig_position_u(d, zo, k), un = zig_position_u(d, zo, kn);
        const int64_t zl = z[static_cast<size_t>(kl)], zk = z[static_cast<size_t>(k)], zn = z[static_cast<size_t>(kn)];
        if ((uk - ul) * (zn - zl) == (zk - zl) * (un - ul)) continue;
      }
      w.line("G1 " + std::string(1, ua) + mm(u_nm(zig_position_u(d, zo, k))) + " Z" + mm(z_nm(z[static_cast<size_t>(k)])) +
             (first ? feed : ""));
      first = false;
      last = m;
      ++moves;
    }
    const int32_t kend = pos(n - 1);
    if (!o.zigzag || s + 1 == stripes) {
      w.line("G0 Z" + mm(o.safe_z_nm));
      continue;
    }
    // Zigzag: over to the next stripe at this end, at a height that no
    // design column under the way asks more of (the step's own interval
    // needs, the cross direction being the along one).
    const int32_t u_end = zig_position_u(d, zo, kend), v_next = zig_stripe_row(d, zo, s + 1);
    const int64_t z_end = z[static_cast<size_t>(kend)], z_next = next[static_cast<size_t>(kend)];
    int64_t z_way = max_of(z_end, z_next);
    for (int64_t q = static_cast<int64_t>(v) * kZigPhases; q < static_cast<int64_t>(v_next) * kZigPhases; ++q) {
      int64_t l, r;
      zig_interval_need(d, t, !zo.along_y, static_cast<int32_t>(q / kZigPhases), u_end, static_cast<int32_t>(q % kZigPhases), &l, &r);
      z_way = max_of(z_way, max_of(max_of(l, r), floor_lsb));
    }
    if (z_way > z_end) w.line("G1 Z" + mm(z_nm(z_way)));
    w.line("G1 " + std::string(1, va) + mm(v_nm(v_next)));
    if (z_next < z_way) w.line("G1 Z" + mm(z_nm(z_next)));
    moves += 1 + (z_way > z_end) + (z_next < z_way);
  }
  w.line("M5");
  w.line("M30");
  stats->positions = static_cast<uint64_t>(n) * static_cast<uint64_t>(stripes);
  stats->moves = moves;
  stats->stripes = static_cast<uint32_t>(stripes);
  stats->seconds = clock_now_s() - t0;
  return true;
}

}  // namespace cli
}  // namespace dexmill
