#include "platform/format/pgm.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "platform/os/output_file.h"
#include "platform/os/read_file.h"

namespace dexmill {

void pgm16_encode(int width, int height, const uint16_t* samples, std::vector<uint8_t>* out) {
  char header[64];
  const int header_bytes = std::snprintf(header, sizeof header, "P5\n%d %d\n65535\n", width, height);
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  out->resize(static_cast<std::size_t>(header_bytes) + 2 * count);
  std::memcpy(out->data(), header, static_cast<std::size_t>(header_bytes));
  uint8_t* p = out->data() + header_bytes;
  for (std::size_t i = 0; i < count; ++i) {
    p[2 * i] = static_cast<uint8_t>(samples[i] >> 8);
    p[2 * i + 1] = static_cast<uint8_t>(samples[i]);
  }
}

bool write_pgm16(const char* path, int width, int height, const uint16_t* samples, char* err, std::size_t errn) {
  OutputFile f;
  if (f.open(path)) {
    std::vector<uint8_t> bytes;
    pgm16_encode(width, height, samples, &bytes);
    f.write(bytes.data(), bytes.size());
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

namespace {

// The header's numbers: whitespace and '#' comments between them.
class PgmHeader {
 public:
  PgmHeader(const std::vector<unsigned char>& b) : b_(b) {}
  bool number(uint64_t* v) {
    for (;;) {
      while (pos_ < b_.size() && std::isspace(b_[pos_])) ++pos_;
      if (pos_ < b_.size() && b_[pos_] == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    if (pos_ >= b_.size() || !std::isdigit(b_[pos_])) return false;
    *v = 0;
    while (pos_ < b_.size() && std::isdigit(b_[pos_])) {
      *v = *v * 10 + static_cast<uint64_t>(b_[pos_++] - '0');
      if (*v > 0xFFFFFFFFull) return false;
    }
    return true;
  }
  size_t pos_ = 2;

 private:
  const std::vector<unsigned char>& b_;
};

}  // namespace

PgmRead read_pgm(const std::string& path, PgmImage* img, std::string* err) {
  std::vector<unsigned char> b;
  switch (read_whole_file(path, static_cast<size_t>(1) << 30, &b, err)) {
    case ReadFile::kOk: break;
    case ReadFile::kTooLarge: return PgmRead::kInputError;
    case ReadFile::kIoError: return PgmRead::kIoError;
  }
  return pgm_parse(path, b, img, err);
}

PgmRead pgm_parse(const std::string& path, const std::vector<unsigned char>& b, PgmImage* img, std::string* err) {
  auto input_error = [&](const std::string& what) {
    *err = path + ": error: " + what;
    return PgmRead::kInputError;
  };
  if (b.size() < 2 || b[0] != 'P' || (b[1] != '5' && b[1] != '2'))
    return input_error("not a PGM image (it must start with P5 or P2)");
  const bool binary = b[1] == '5';
  PgmHeader h(b);
  uint64_t w, ht, maxval;
  if (!h.number(&w) || !h.number(&ht) || !h.number(&maxval))
    return input_error("bad PGM header: width, height and maxval must follow the magic number");
  if (w < 1 || w > 65535 || ht < 1 || ht > 65535 || w * ht > (static_cast<uint64_t>(1) << 28))
    return input_error("PGM size " + std::to_string(w) + "x" + std::to_string(ht) + " is out of range");
  if (maxval < 1 || maxval > 65535) return input_error("PGM maxval " + std::to_string(maxval) + " is not in 1..65535");
  img->width = static_cast<int32_t>(w);
  img->height = static_cast<int32_t>(ht);
  img->maxval = static_cast<uint32_t>(maxval);
  const size_t count = static_cast<size_t>(w * ht);
  // Memory for the samples only as the file holds them: a header alone may
  // claim 2^28 (fuzzer: a 37-byte file had 84 MB taken and cleared).
  img->samples.clear();
  if (binary) {
    // Exactly one whitespace byte after maxval, then the samples.
    size_t p = h.pos_ + 1;
    const size_t bytes = maxval > 255 ? 2 : 1;
    if (h.pos_ >= b.size() || b.size() - p < count * bytes)
      return input_error("too few samples: " + std::to_string(w) + "x" + std::to_string(ht) + " needs " +
                         std::to_string(count * bytes) + " bytes of data, the file has " +
                         std::to_string(h.pos_ < b.size() ? b.size() - p : 0));
    img->samples.assign(count, 0);
    for (size_t k = 0; k < count; ++k, p += bytes) {
      const uint32_t s = bytes == 2 ? (static_cast<uint32_t>(b[p]) << 8 | b[p + 1]) : b[p];
      if (s > maxval) return input_error("sample " + std::to_string(k + 1) + " is above maxval");
      img->samples[k] = static_cast<uint16_t>(s);
    }
  } else {
    // A text sample takes two bytes at least: a digit and a separator.
    img->samples.reserve(std::min(count, (b.size() - std::min(h.pos_, b.size())) / 2 + 1));
    for (size_t k = 0; k < count; ++k) {
      uint64_t s;
      if (!h.number(&s))
        return input_error("too few samples: " + std::to_string(count) + " needed, " + std::to_string(k) + " found");
      if (s > maxval) return input_error("sample " + std::to_string(k + 1) + " is above maxval");
      img->samples.push_back(static_cast<uint16_t>(s));
    }
  }
  return PgmRead::kOk;
}

}  // namespace dexmill
