// Helpers of the `dexmill run` tests; see run_cli_util.h.
#include "tests/run_cli_util.h"

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/runner.h"

namespace run_cli {

namespace {

std::string& tmp_path() {
  static std::string dir;
  return dir;
}

// The folder goes when the test binary ends (whichever test made it).
void remove_tmp_dir() {
  const std::string& dir = tmp_path();
  if (!dir.empty() && std::system(("chmod -R u+w '" + dir + "'; rm -rf '" + dir + "'").c_str()) != 0)
    std::printf("  (could not remove %s)\n", dir.c_str());
}

}  // namespace

std::string tmp_dir() {
  std::string& dir = tmp_path();
  if (dir.empty()) {
    char t[] = "/tmp/dexmill-run-test-XXXXXX";
    if (mkdtemp(t)) {
      dir = t;
      std::atexit(remove_tmp_dir);
    }
  }
  return dir;
}

std::string slurp(const std::string& path) {
  std::string s;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return s;
  char b[65536];
  size_t n;
  while ((n = std::fread(b, 1, sizeof b, f)) > 0) s.append(b, n);
  std::fclose(f);
  return s;
}

uint64_t fnv(const std::string& s) {
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) { h ^= c; h *= 1099511628211ULL; }
  return h;
}
uint64_t file_hash(const std::string& path) { return fnv(slurp(path)); }

std::string write_tmp(const char* name, const char* text) {
  const std::string path = tmp_dir() + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f) {
    std::fputs(text, f);
    std::fclose(f);
  }
  return path;
}

void write_file(const std::string& path, const std::string& bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
}

Result run(const std::string& args, const char* stdin_file, bool in_tmp, const std::string& prefix) {
  return run_command("run " + args, stdin_file, in_tmp, prefix);
}

Result run_command(const std::string& args, const char* stdin_file, bool in_tmp, const std::string& prefix) {
  Result r;
  const char* bin = t::dexmill_binary();
  if (!bin) return r;
  std::string a;
  for (char c : args) {
    if (c == '%') a += tmp_dir();
    else a += c;
  }
  char abs[4096];
  const std::string binary = realpath(bin, abs) ? abs : bin;
  const std::string err = tmp_dir() + "/stderr.txt", out = tmp_dir() + "/stdout.txt";
  const std::string cwd = in_tmp ? tmp_dir() : std::string(t::tests_dir()) + "/run";
  std::string cmd = "cd '" + cwd + "' && " + prefix + " '" + binary + "' " + a + " 2>'" + err + "' >'" + out + "'";
  char in_abs[4096];
  if (stdin_file && realpath(stdin_file, in_abs)) stdin_file = in_abs;
  cmd += stdin_file ? " <'" + std::string(stdin_file) + "'" : std::string(" </dev/null");
  const int st = std::system(cmd.c_str());
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.err = slurp(err);
  r.out = slurp(out);
  return r;
}

Result run_shell(const std::string& script) {
  Result r;
  const char* bin = t::dexmill_binary();
  if (!bin) return r;
  char abs[4096];
  const std::string binary = std::string("'") + (realpath(bin, abs) ? abs : bin) + "'";
  std::string s;
  for (size_t k = 0; k < script.size(); ++k) {
    if (script.compare(k, 5, "{bin}") == 0) {
      s += binary;
      k += 4;
    } else if (script[k] == '%') {
      s += tmp_dir();
    } else {
      s += script[k];
    }
  }
  const std::string err = tmp_dir() + "/stderr.txt", out = tmp_dir() + "/stdout.txt";
  const std::string cmd = "cd '" + std::string(t::tests_dir()) + "/run' && { " + s + "\n} 2>'" + err + "' >'" + out + "' </dev/null";
  const int st = std::system(cmd.c_str());
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.err = slurp(err);
  r.out = slurp(out);
  return r;
}

bool has(const std::string& s, const char* part) {
  if (s.find(part) != std::string::npos) return true;
  std::printf("  wanted '%s' in: %s\n", part, s.c_str());
  return false;
}

bool lacks(const std::string& s, const char* part) {
  if (s.find(part) == std::string::npos) return true;
  std::printf("  did not want '%s' in: %s\n", part, s.c_str());
  return false;
}

std::string report_body(const std::string& path) {
  std::string s = slurp(path);
  const size_t t = s.find("  \"timing\"");
  return t == std::string::npos ? s : s.substr(0, t);
}

bool skip() {
  if (t::dexmill_binary()) return false;
  std::printf("  (skipped: set DEXMILL to the built binary)\n");
  return true;
}

std::string assessment_of(const std::string& report) {
  const size_t a = report.find("  \"assessment\""), b = report.find("  \"timing\"");
  return a == std::string::npos || b == std::string::npos ? std::string() : report.substr(a, b - a);
}

std::vector<unsigned char> ppm_rgb(const std::string& bytes, int skip_bottom_rows) {
  int w = 0, h = 0, maxval = 0, used = 0;
  if (std::sscanf(bytes.c_str(), "P6 %d %d %d%n", &w, &h, &maxval, &used) != 3 || maxval != 255) return {};
  const size_t at = static_cast<size_t>(used) + 1, n = static_cast<size_t>(w) * h * 3;
  if (bytes.size() < at + n || skip_bottom_rows > h) return {};
  const size_t kept = static_cast<size_t>(w) * (h - skip_bottom_rows) * 3;
  return std::vector<unsigned char>(bytes.begin() + static_cast<long>(at), bytes.begin() + static_cast<long>(at + kept));
}

Image read_ppm(const std::string& path) {
  Image im;
  const std::string bytes = slurp(path);
  if (std::sscanf(bytes.c_str(), "P6 %d %d", &im.w, &im.h) != 2) return im;
  im.rgb = ppm_rgb(bytes);
  if (im.rgb.size() != static_cast<size_t>(im.w) * im.h * 3) im = Image();  // not read: no pixels to index
  return im;
}

namespace {

// The names in folder dir that `match` takes; -1 without the folder.
template <class Match>
int count_entries(const std::string& dir, Match match) {
  DIR* d = opendir(dir.c_str());
  if (!d) return -1;
  int n = 0;
  while (const dirent* e = readdir(d))
    if (match(std::string(e->d_name))) ++n;
  closedir(d);
  return n;
}

}  // namespace

int count_names(const std::string& dir, const char* part) {
  const int n = count_entries(dir, [part](const std::string& name) { return name.find(part) != std::string::npos; });
  return n < 0 ? 0 : n;
}

int count_prefixed(const std::string& dir, const char* prefix) {
  return count_entries(dir, [prefix](const std::string& name) { return name.rfind(prefix, 0) == 0; });
}

}  // namespace run_cli
