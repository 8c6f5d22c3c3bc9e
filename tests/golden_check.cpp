// Goldens read by name, and written instead under DEXMILL_BLESS=1; see
// golden_check.h and tests/golden/README.md.
#include "tests/golden_check.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "platform/format/png.h"
#include "tests/inflate_oracle.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace t {

namespace {

bool read_bytes(const std::string& path, std::string* out) {
  out->clear();
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  char b[65536];
  size_t n;
  while ((n = std::fread(b, 1, sizeof b, f)) > 0) out->append(b, n);
  std::fclose(f);
  return true;
}

// mkdir -p.
void make_dirs(const std::string& dir) {
  for (size_t at = 1; at <= dir.size(); ++at)
    if (at == dir.size() || dir[at] == '/') mkdir(dir.substr(0, at).c_str(), 0755);
}

// Written whole under a temporary name, then renamed: a reader (another
// worker of the runner) sees the old file or the new one.
bool write_bytes(const std::string& path, const void* p, size_t n) {
  const size_t slash = path.rfind('/');
  if (slash != std::string::npos) make_dirs(path.substr(0, slash));
  const std::string tmp = path + ".tmp" + std::to_string(getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(p, 1, n, f) == n;
  if (std::fclose(f) != 0 || !ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

std::string hex16(uint64_t v) {
  char b[24];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

// The value of `name` in hashes.txt text; false when it has none.
bool find_hash(const std::string& text, const std::string& name, uint64_t* value, size_t* line_at, size_t* line_end) {
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    const size_t sp = line.find(' ');
    if (!line.empty() && line[0] != '#' && sp != std::string::npos && line.compare(0, sp, name) == 0 && sp == name.size()) {
      *value = std::strtoull(line.c_str() + sp + 1, nullptr, 16);
      *line_at = at;
      *line_end = end;
      return true;
    }
    at = end + 1;
  }
  return false;
}

// Sets name's value in hashes.txt, under an exclusive lock (the runner's
// workers bless at the same time), writing only when it changes.
bool bless_hash(const std::string& path, const std::string& name, uint64_t got, std::string* why) {
  const int fd = open(path.c_str(), O_RDWR | O_CREAT, 0644);
  if (fd < 0 || flock(fd, LOCK_EX) != 0) {
    *why = "cannot open and lock " + path + ": " + std::strerror(errno);
    if (fd >= 0) close(fd);
    return false;
  }
  std::string text;
  char b[4096];
  ssize_t n;
  while ((n = read(fd, b, sizeof b)) > 0) text.append(b, static_cast<size_t>(n));
  uint64_t have = 0;
  size_t at = 0, end = 0;
  const std::string line = name + " " + hex16(got);
  bool changed = true;
  if (find_hash(text, name, &have, &at, &end)) {
    changed = text.compare(at, end - at, line) != 0;
    text.replace(at, end - at, line);
  } else {
    if (!text.empty() && text.back() != '\n') text += '\n';
    text += line + "\n";
  }
  bool ok = true;
  if (changed) {
    ok = lseek(fd, 0, SEEK_SET) == 0 && write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
         ftruncate(fd, static_cast<off_t>(text.size())) == 0;
    if (!ok) *why = "cannot write " + path + ": " + std::strerror(errno);
  }
  close(fd);  // and the lock with it
  return ok;
}

uint32_t be32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) << 24 | static_cast<uint32_t>(p[1]) << 16 | static_cast<uint32_t>(p[2]) << 8 | p[3];
}

int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

bool same(const RgbImage& a, const RgbImage& b) { return a.w == b.w && a.h == b.h && a.rgb == b.rgb; }

std::string size_text(const RgbImage& im) { return std::to_string(im.w) + "x" + std::to_string(im.h); }

// Under bless, each golden's kind and name go to $DEXMILL_BLESS_LOG, one a
// line (one write each, appended: the runner's workers share the file), so
// tests/bless.sh can name the hashes and pictures no test checks any more.
void log_blessed(const char* kind, const std::string& name) {
  const char* log = std::getenv("DEXMILL_BLESS_LOG");
  if (!log || !*log) return;
  const int fd = open(log, O_WRONLY | O_APPEND | O_CREAT, 0644);
  if (fd < 0) return;
  const std::string line = std::string(kind) + " " + name + "\n";
  if (write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size())) std::printf("  (could not log %s)\n", log);
  close(fd);
}

bool allowed(const char* file, int line) {
  if (std::strstr(current_case(), "golden")) return true;
  const std::string why = std::string("case ") + current_case() +
                          " checks a golden but its name does not hold \"golden\": make bless would not run it";
  fail(file, line, "golden check", why.c_str());
  return false;
}

bool report(const char* file, int line, const std::string& what, const GoldenResult& r) {
  if (!r.ok) fail(file, line, what.c_str(), r.message.c_str());
  return r.ok;
}

}  // namespace

bool blessing() {
  const char* b = std::getenv("DEXMILL_BLESS");
  return b && std::strcmp(b, "1") == 0;
}

GoldenPlace golden_place() {
  GoldenPlace p;
  p.dir = std::string(tests_dir()) + "/golden";
  const char* out = std::getenv("DEXMILL_GOLDEN_OUT");
  p.out_dir = out && *out ? out : "/tmp/dexmill-golden-out";
  p.bless = blessing();
  return p;
}

RgbImage rgb_of_frame(const dexmill::FrameView& fb) {
  RgbImage im;
  im.w = fb.width;
  im.h = fb.height;
  im.rgb.reserve(static_cast<size_t>(im.w) * im.h * 3);
  for (int32_t y = 0; y < fb.height; ++y)
    for (int32_t x = 0; x < fb.width; ++x) {
      const dexmill::Rgb c = dexmill::pixel_unpack(fb.format, dexmill::frame_pixel(fb, x, y));
      im.rgb.insert(im.rgb.end(), {c.r, c.g, c.b});
    }
  return im;
}

RgbImage rgb_of_ppm(const std::string& bytes) {
  RgbImage im;
  int w = 0, h = 0, maxval = 0, used = 0;
  if (bytes.compare(0, 2, "P6") != 0 || std::sscanf(bytes.c_str(), "P6 %d %d %d%n", &w, &h, &maxval, &used) != 3 ||
      maxval != 255 || w <= 0 || h <= 0)
    return im;
  const size_t at = static_cast<size_t>(used) + 1, n = static_cast<size_t>(w) * h * 3;
  if (bytes.size() != at + n) return im;
  im.w = w;
  im.h = h;
  im.rgb.assign(bytes.begin() + static_cast<long>(at), bytes.end());
  return im;
}

std::vector<uint8_t> png_of(const RgbImage& img) {
  std::vector<uint8_t> out;
  dexmill::png_encode_rgb8(img.rgb.data(), img.w, img.h, &out);
  return out;
}

RgbImage rgb_of_png(const std::vector<uint8_t>& png) {
  static const uint8_t kSig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  RgbImage none, im;
  if (png.size() < 8 || std::memcmp(png.data(), kSig, 8) != 0) return none;
  std::vector<uint8_t> zdata;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t len = be32(&png[at]);
    if (len > png.size() - at - 12) return none;
    const uint8_t* body = &png[at + 8];
    if (std::memcmp(&png[at + 4], "IHDR", 4) == 0) {
      if (len != 13 || body[8] != 8 || body[9] != 2 || body[12] != 0) return none;  // RGB8, not interlaced
      im.w = static_cast<int32_t>(be32(body));
      im.h = static_cast<int32_t>(be32(body + 4));
    } else if (std::memcmp(&png[at + 4], "IDAT", 4) == 0) {
      zdata.insert(zdata.end(), body, body + len);
    }
    at += 12 + len;
  }
  std::vector<uint8_t> filtered;
  oracle::InflateStats st;
  if (im.w <= 0 || im.h <= 0 || im.w > 1 << 14 || im.h > 1 << 14 ||
      !oracle::zlib_decompress(zdata.data(), zdata.size(), &filtered, &st))
    return none;
  const size_t row = static_cast<size_t>(im.w) * 3;
  if (filtered.size() != static_cast<size_t>(im.h) * (row + 1)) return none;
  im.rgb.assign(static_cast<size_t>(im.h) * row, 0);
  for (size_t y = 0; y < static_cast<size_t>(im.h); ++y) {
    const uint8_t* in = &filtered[y * (row + 1)];
    uint8_t* out = &im.rgb[y * row];
    const uint8_t* up = y ? out - row : nullptr;
    for (size_t i = 0; i < row; ++i) {
      const int a = i >= 3 ? out[i - 3] : 0, b = up ? up[i] : 0, c = up && i >= 3 ? up[i - 3] : 0;
      int p = 0;
      switch (in[0]) {
        case 0: p = 0; break;
        case 1: p = a; break;
        case 2: p = b; break;
        case 3: p = (a + b) / 2; break;
        case 4: p = paeth(a, b, c); break;
        default: return none;
      }
      out[i] = static_cast<uint8_t>(in[1 + i] + p);
    }
  }
  return im;
}

RgbImage diff_image(const RgbImage& expected, const RgbImage& actual, int64_t* differing) {
  RgbImage d;
  d.w = expected.w > actual.w ? expected.w : actual.w;
  d.h = expected.h > actual.h ? expected.h : actual.h;
  d.rgb.assign(static_cast<size_t>(d.w) * d.h * 3, 0);
  *differing = 0;
  for (int32_t y = 0; y < d.h; ++y)
    for (int32_t x = 0; x < d.w; ++x) {
      uint8_t* o = &d.rgb[(static_cast<size_t>(y) * d.w + x) * 3];
      if (x >= expected.w || y >= expected.h || x >= actual.w || y >= actual.h) {
        o[0] = 255, o[1] = 0, o[2] = 255;
        ++*differing;
        continue;
      }
      const uint8_t* e = &expected.rgb[(static_cast<size_t>(y) * expected.w + x) * 3];
      const uint8_t* a = &actual.rgb[(static_cast<size_t>(y) * actual.w + x) * 3];
      if (e[0] == a[0] && e[1] == a[1] && e[2] == a[2]) {
        const uint8_t grey = static_cast<uint8_t>((e[0] * 77 + e[1] * 150 + e[2] * 29) >> 10);  // luma / 4
        o[0] = o[1] = o[2] = grey;
        continue;
      }
      ++*differing;
      for (int k = 0; k < 3; ++k) {
        const int dk = std::abs(static_cast<int>(e[k]) - a[k]);
        o[k] = static_cast<uint8_t>(dk == 0 ? 0 : (128 + 4 * dk > 255 ? 255 : 128 + 4 * dk));
      }
    }
  return d;
}

GoldenResult golden_hash_result(const GoldenPlace& at, const std::string& name, uint64_t got) {
  GoldenResult r;
  const std::string path = at.dir + "/hashes.txt";
  if (at.bless) {
    r.ok = bless_hash(path, name, got, &r.message);
    log_blessed("hash", name);
    return r;
  }
  std::string text;
  uint64_t want = 0;
  size_t b = 0, e = 0;
  if (!read_bytes(path, &text) || !find_hash(text, name, &want, &b, &e)) {
    r.ok = false;
    r.message = name + " has no hash in " + path + " (got " + hex16(got) + "; make bless pins it)";
  } else if (want != got) {
    r.ok = false;
    r.message = name + ": hash " + hex16(got) + ", golden " + hex16(want) + " (" + path + ")";
  }
  return r;
}

GoldenResult golden_image_result(const GoldenPlace& at, const std::string& name, uint64_t got, const RgbImage& actual) {
  GoldenResult r = golden_hash_result(at, name, got);
  const std::string ref = at.dir + "/frames/" + name + ".png";
  std::string bytes;
  const bool have = read_bytes(ref, &bytes);
  const RgbImage expected = rgb_of_png(std::vector<uint8_t>(bytes.begin(), bytes.end()));
  const bool equal = same(expected, actual);
  if (at.bless) {
    log_blessed("frame", name);
    if (!equal) {
      const std::vector<uint8_t> png = png_of(actual);
      if (!write_bytes(ref, png.data(), png.size())) {
        r.ok = false;
        r.message += (r.message.empty() ? "" : "; ") + std::string("cannot write ") + ref;
      }
    }
    return r;
  }
  if (r.ok && equal) return r;
  std::string msg = r.message;
  if (r.ok) msg = name + ": the hash is the golden one but the reference picture is not the frame (a stale picture)";
  else if (equal) msg += "; yet the frame equals the reference picture " + ref + " (a stale picture)";
  r.ok = false;
  make_dirs(at.out_dir);
  const std::string base = at.out_dir + "/" + name;
  const std::vector<uint8_t> act = png_of(actual);
  write_bytes(base + ".actual.png", act.data(), act.size());
  if (expected.w == 0) {
    msg = (r.message.empty() ? name + ": the hash is the golden one, but" : r.message + ";") + " " + ref +
          (have ? " is not a picture" : " is missing") +
          " (make bless writes it); the actual frame: " + base + ".actual.png";
    r.message = msg;
    return r;
  }
  int64_t differing = 0;
  const RgbImage d = diff_image(expected, actual, &differing);
  const std::vector<uint8_t> dp = png_of(d);
  write_bytes(base + ".expected.png", bytes.data(), bytes.size());
  write_bytes(base + ".diff.png", dp.data(), dp.size());
  msg += "; " + std::to_string(differing) + " pixels differ (expected " + size_text(expected) + ", actual " +
         size_text(actual) + "); pictures: " + base + ".expected.png " + base + ".actual.png " + base + ".diff.png";
  r.message = msg;
  return r;
}

GoldenResult golden_text_result(const GoldenPlace& at, const std::string& path, const std::string& got) {
  GoldenResult r;
  std::string want;
  const bool have = read_bytes(path, &want);
  if (have && want == got) return r;
  if (at.bless) {
    if (!write_bytes(path, got.data(), got.size())) {
      r.ok = false;
      r.message = "cannot write " + path;
    }
    return r;
  }
  r.ok = false;
  if (!have) {
    r.message = path + " is missing (make bless writes it)";
    return r;
  }
  // The first differing line, for the log.
  size_t line = 1, i = 0;
  while (i < got.size() && i < want.size() && got[i] == want[i]) line += got[i++] == '\n';
  auto line_at = [](const std::string& s, size_t pos) {
    size_t b = s.rfind('\n', pos ? pos - 1 : 0);
    b = (b == std::string::npos || pos == 0) ? 0 : b + 1;
    return b >= s.size() ? std::string("(end of text)") : s.substr(b, s.find('\n', b) - b);
  };
  r.message = path + " differs at line " + std::to_string(line) + ":\n  want: " + line_at(want, i) +
              "\n  got:  " + line_at(got, i);
  return r;
}

std::string golden_out_value(const std::string& line_prefix, const char* key) {
  std::string text;
  read_bytes(std::string(tests_dir()) + "/golden/golden.out", &text);
  size_t at = 0;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    if (text.compare(at, line_prefix.size(), line_prefix) == 0) {
      const std::string line = " " + text.substr(at, end - at), k = std::string(" ") + key + "=";
      const size_t v = line.find(k);
      if (v == std::string::npos) return std::string();
      const size_t b = v + k.size();
      return line.substr(b, line.find(' ', b) - b);
    }
    at = end + 1;
  }
  return std::string();
}

bool check_golden_hash(const char* file, int line, const std::string& name, uint64_t got) {
  return allowed(file, line) && report(file, line, "golden hash " + name, golden_hash_result(golden_place(), name, got));
}

bool check_golden_frame(const char* file, int line, const std::string& name, const dexmill::FrameView& fb) {
  return allowed(file, line) &&
         report(file, line, "golden frame " + name,
                golden_image_result(golden_place(), name, dexmill::frame_hash(fb), rgb_of_frame(fb)));
}

bool check_golden_file(const char* file, int line, const std::string& name, const std::string& path) {
  if (!allowed(file, line)) return false;
  std::string bytes;
  if (!read_bytes(path, &bytes)) {
    fail(file, line, ("golden file " + name).c_str(), (path + " was not written").c_str());
    return false;
  }
  const uint64_t got = run_cli::fnv(bytes);
  const RgbImage im = rgb_of_ppm(bytes);
  const GoldenPlace at = golden_place();
  return report(file, line, "golden file " + name,
                im.w ? golden_image_result(at, name, got, im) : golden_hash_result(at, name, got));
}

bool check_golden_text(const char* file, int line, const std::string& path, const std::string& got) {
  return allowed(file, line) && report(file, line, "golden text", golden_text_result(golden_place(), path, got));
}

}  // namespace t
