// The program corpora of tests/gcode: every bad program fails with the error
// written on its first line (`; expect LINE:COL: MESSAGE`), and every golden
// program's path (`dexmill path`, with --tools FAMILY.tbl when the program
// FAMILY_NAME.ngc has one) matches NAME.path byte for byte. Also the
// hosted reader (platform/input/gcode_file.h) on line ends, long lines and a long
// streamed file.
#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "platform/input/gcode_file.h"
#include "tests/alloc_count.h"
#include "tests/golden_check.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

std::vector<std::string> list(const std::string& dir, const char* ext) {
  std::vector<std::string> out;
  DIR* d = opendir(dir.c_str());
  if (!d) return out;
  while (dirent* e = readdir(d)) {
    std::string n = e->d_name;
    if (n.size() > std::strlen(ext) && n.compare(n.size() - std::strlen(ext), std::string::npos, ext) == 0)
      out.push_back(n);
  }
  closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

// Collects "LINE:COL: MESSAGE" of errors and warnings.
struct Collect final : GcodeMessages {
  std::vector<std::string> errors, warnings;
  static std::string text(const GcodeDiag& d) {
    char msg[400], buf[460];
    gcode_format_message(d, msg, sizeof msg);
    std::snprintf(buf, sizeof buf, "%u:%u: %s", d.line, d.col, msg);
    return buf;
  }
  void error(const GcodeDiag& d) override {
    ++errors_;
    errors.push_back(text(d));
  }
  void warning(const GcodeDiag& d) override {
    ++warnings_;
    warnings.push_back(text(d));
  }
};

std::string read_file(const std::string& path) {
  std::string s;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    std::fclose(f);
  }
  return s;
}

// Each program of `sub` (tests/gcode/SUB/*.ngc) gives the error its first
// line expects. With `memory`, the interpreter reads parameters and o-words
// (as `dexmill path` does); without, as a panel without that memory.
void check_bad_programs(const char* sub, std::size_t at_least, bool memory) {
  const std::string dir = std::string(t::tests_dir()) + "/gcode/" + sub;
  const auto files = list(dir, ".ngc");
  CHECK_GE(files.size(), at_least);
  for (const auto& name : files) {
    const std::string path = dir + "/" + name;
    std::string first = read_file(path);
    first = first.substr(0, first.find('\n'));
    const std::string tag = "; expect ";
    if (!CHECK(first.compare(0, tag.size(), tag) == 0)) {
      std::printf("  %s: first line must be '; expect LINE:COL: MESSAGE'\n", name.c_str());
      continue;
    }
    const std::string want = first.substr(tag.size());
    GcodeFile file;
    if (!CHECK(file.open(path.c_str()))) continue;
    Collect msgs;
    InterpOptions opt;
    opt.warnings = &msgs;
    const std::unique_ptr<GcodeMemory> mem = gcode_memory();
    if (memory) mem->attach(&opt);
    Interp interp(nullptr, opt);
    GcodeRunner runner(&file, &interp, &msgs, true);
    runner.run_all();
    const std::string got = msgs.errors.empty() ? "(no error)" : msgs.errors[0];
    if (got != want) {
      t::fail(__FILE__, __LINE__, "bad program", name.c_str());
      std::printf("  want %s\n  got  %s\n", want.c_str(), got.c_str());
    }
  }
}

}  // namespace

TEST(gcode_bad_corpus) { check_bad_programs("bad", 30, false); }

// O-word control flow's errors, each at the line where LinuxCNC 2.9's rs274
// gives its own (checked when they were written).
TEST(gcode_bad_control_flow) { check_bad_programs("bad_flow", 22, true); }

TEST(gcode_golden_paths) {
  const char* bin = t::dexmill_binary();
  if (!CHECK(bin != nullptr)) {
    std::printf("  DEXMILL is not set (make test sets it to the built binary)\n");
    return;
  }
  const std::string dir = std::string(t::tests_dir()) + "/gcode/paths";
  const auto files = list(dir, ".ngc");
  CHECK_GE(files.size(), 7u);
  for (const auto& name : files) {
    const std::string base = dir + "/" + name.substr(0, name.size() - 4);
    // A family's tool table: comp_lines.ngc runs with comp.tbl when there is
    // one. The tables are in mm, the programs in mm or inch: --tool-units
    // says so (core/sim/tool_units.h would take an inch program's units).
    const std::string table = dir + "/" + name.substr(0, name.find('_')) + ".tbl";
    const std::string tools = read_file(table).empty() ? "" : " --tools '" + table + "' --tool-units mm";
    const std::string cmd = std::string("'") + bin + "' path '" + base + ".ngc'" + tools + " 2>&1";
    std::string got;
    if (std::FILE* p = popen(cmd.c_str(), "r")) {
      char buf[4096];
      std::size_t n;
      while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) got.append(buf, n);
      const int rc = pclose(p);
      CHECK_EQ(rc, 0);
    }
    // NAME.path is the golden (make bless writes it), and a program that
    // prints nothing has none to pin.
    CHECK(!got.empty());
    CHECK_GOLDEN_TEXT(base + ".path", got);
  }
}

TEST(gcode_file_line_ends) {
  const char* path = "/tmp/dexmill_test_line_ends.ngc";
  std::FILE* f = std::fopen(path, "wb");
  // CRLF, LF, an empty line, a 300-byte line, and a last line with no newline.
  std::fputs("G21\r\nG0 X1\n\n(", f);
  for (int i = 0; i < 300; ++i) std::fputc('x', f);
  std::fputs(")\nG0 X2", f);
  std::fclose(f);
  GcodeFile file;
  CHECK(file.open(path));
  CHECK_GT(file.total_bytes(), 300);
  const char* text;
  std::size_t len;
  uint32_t line;
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kLine);
  CHECK_EQ(len, 3u);
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kLine);
  CHECK_EQ(std::string(text, len), std::string("G0 X1"));
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kLine);
  CHECK_EQ(len, 0u);
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kTooLong);
  CHECK_EQ(line, 4u);
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kLine);
  CHECK_EQ(std::string(text, len), std::string("G0 X2"));
  CHECK_EQ(line, 5u);
  CHECK_EQ(file.next(&text, &len, &line), GcodeFile::Read::kEof);
  CHECK_EQ(static_cast<int64_t>(file.bytes_read()), file.total_bytes());
  std::remove(path);
}

TEST(gcode_file_streams_150k_lines_without_heap) {
  const char* path = "/tmp/dexmill_test_150k.ngc";
  std::FILE* f = std::fopen(path, "wb");
  std::fputs("G21 G90 F1000\n", f);
  for (int i = 0; i < 150000; ++i) std::fprintf(f, "G1 X%d.%02d Y%d Z-%d.5\n", i % 500, i % 100, (i / 500) % 300, i % 3);
  std::fputs("M2\n", f);
  std::fclose(f);
  GcodeFile file;
  CHECK(file.open(path));
  Collect msgs;
  InterpOptions opt;
  opt.warnings = &msgs;
  struct Count final : CanonSink {
    uint64_t n = 0;
    void emit(const CanonRecord&) override { ++n; }
  } sink;
  Interp interp(&sink, opt);
  GcodeRunner runner(&file, &interp, &msgs, true);
  const uint64_t before = t::heap_allocations();
  runner.run_all();
  CHECK_EQ(t::heap_allocations() - before, 0u);
  CHECK_EQ(msgs.errors.size(), 0u);
  CHECK_EQ(sink.n, 150001u);
  CHECK_EQ(runner.lines(), 150002u);
  std::remove(path);
}

namespace {

void write_file(const char* path, const std::string& bytes) {
  std::FILE* f = std::fopen(path, "wb");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
}

// The lines of a file as "N:text" (one per kLine), "N:too long", "not text",
// "endless", until the end.
std::vector<std::string> read_lines(const char* path) {
  std::vector<std::string> out;
  GcodeFile file;
  if (!file.open(path)) return out;
  for (;;) {
    const char* text;
    std::size_t len;
    uint32_t line = 0;
    const GcodeFile::Read r = file.next(&text, &len, &line);
    if (r == GcodeFile::Read::kEof || r == GcodeFile::Read::kIoError) break;
    if (r == GcodeFile::Read::kLine) out.push_back(std::to_string(line) + ":" + std::string(text, len));
    if (r == GcodeFile::Read::kTooLong) out.push_back(std::to_string(line) + ":too long");
    if (r == GcodeFile::Read::kNotText) out.push_back("not text");
    if (r == GcodeFile::Read::kEndless) {
      out.push_back("endless");
      break;
    }
  }
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "|";
  return s;
}

// Runs a file through the interpreter as `dexmill check` does.
std::vector<std::string> check_errors(const char* path) {
  GcodeFile file;
  Collect msgs;
  if (!file.open(path)) return {"cannot open"};
  InterpOptions opt;
  opt.warnings = &msgs;
  Interp interp(nullptr, opt);
  GcodeRunner runner(&file, &interp, &msgs, false);
  runner.run_all();
  return msgs.errors;
}

}  // namespace

TEST(gcode_file_cr_only_line_ends) {
  const char* path = "/tmp/dexmill_test_cr.ngc";
  // An old Mac file: CR ends each line, an empty line is an empty line.
  write_file(path, "G21\rG0 X1\r\rG1 Y2 F100\rM2");
  CHECK_EQ(join(read_lines(path)), std::string("1:G21|2:G0 X1|3:|4:G1 Y2 F100|5:M2|"));
  // Once CR ends lines, a later CRLF is one line end, even split across reads.
  std::string s;
  int lines = 0;
  while (s.size() + 6 < 65535 - 100) {
    s += "G0 X1\r";
    ++lines;
  }
  s += "(" + std::string(65535 - s.size() - 2, 'x') + ")";
  s += "\r\nG0 X2\r";
  CHECK_EQ(s.size(), 65536u + 7);
  CHECK_EQ(s[65535], '\r');
  write_file(path, s);
  const std::vector<std::string> got = read_lines(path);
  CHECK_EQ(got.size(), static_cast<std::size_t>(lines + 2));
  CHECK_EQ(got.back(), std::to_string(lines + 2) + ":G0 X2");
  // A CRLF file, and one with stray CRs, keep their LF lines (CR is white space).
  write_file(path, "G21\r\nG0 X1\r\r\nG0\rX2\n");
  CHECK_EQ(join(read_lines(path)), std::string("1:G21|2:G0 X1\r|3:G0\rX2|"));
  std::remove(path);
}

TEST(gcode_file_utf8_bom_is_skipped) {
  const char* path = "/tmp/dexmill_test_bom.ngc";
  write_file(path, "\xEF\xBB\xBFG21\nG0 X1\n");
  CHECK_EQ(join(read_lines(path)), std::string("1:G21|2:G0 X1|"));
  CHECK_EQ(check_errors(path).size(), 0u);
  // Only at the start: elsewhere the bytes are not G-code.
  write_file(path, "G21\n\xEF\xBB\xBFG0 X1\n");
  const std::vector<std::string> e = check_errors(path);
  CHECK_EQ(e.size(), 1u);
  if (!e.empty()) CHECK_EQ(e[0], std::string("2:1: unexpected character '\\xEF' (not part of any G-code word)"));
  std::remove(path);
}

TEST(gcode_file_binary_is_not_a_text_file) {
  const char* path = "/tmp/dexmill_test_binary.ngc";
  // The start of a PNG image (a 1x1 pixel), and of an ELF executable.
  const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0,
                               0, 1, 0, 0, 0, 1, 8, 6, 0, 0, 0, 0x1f, 0x15, 0xc4, 0x89, 0, 0, 0, 10, 'I', 'D',
                               'A', 'T', 0x78, 0x9c, 0x63, 0, 1, 0, 0, 5, 0, 1, 0x0d, 0x0a, 0x2d, 0xb4};
  write_file(path, std::string(reinterpret_cast<const char*>(png), sizeof png));
  CHECK_EQ(join(read_lines(path)), std::string("not text|"));
  std::vector<std::string> e = check_errors(path);
  CHECK_EQ(e.size(), 1u);
  if (!e.empty()) CHECK_EQ(e[0], std::string("1:1: not a text file (binary data, such as the byte \\x01; G-code is plain text)"));
  std::string elf("\x7f" "ELF\x02\x01\x01", 7);
  elf += std::string(9, '\0') + "\x02\0>\0\x01\0\0\0" + std::string(300, '\x01') + "\n";
  write_file(path, elf);
  CHECK_EQ(check_errors(path).size(), 1u);
  // UTF-16 (Notepad's "Unicode") is text, but not text dexmill reads.
  write_file(path, std::string("\xFF\xFEG\0" "0\0\n\0", 8));
  e = check_errors(path);
  CHECK_EQ(e.size(), 1u);
  if (!e.empty()) CHECK_EQ(e[0], std::string("1:1: the file is UTF-16 text; save it as UTF-8 or ASCII"));
  // A stray control byte in a text file is a typo on its line.
  write_file(path, "G21\nG0 X1 \x01\nG0 X2\nG0 X3\nG0 X4\nG0 X5\nM2\n");
  e = check_errors(path);
  CHECK_EQ(e.size(), 1u);
  if (!e.empty()) CHECK_EQ(e[0], std::string("2:7: unexpected character '\\x01' (not part of any G-code word)"));
  std::remove(path);
}

TEST(gcode_file_endless_line_stops) {
  const char* path = "/tmp/dexmill_test_endless.ngc";
  // A long line is skipped to its end, and the lines after it are read.
  write_file(path, std::string(300000, 'x') + "\nG0 X2\n");
  CHECK_EQ(join(read_lines(path)), std::string("1:too long|2:G0 X2|"));
  // No line end in reach: one error, and reading stops.
  write_file(path, std::string(2 * GcodeFile::kGcodeMaxSkip, '(') + "\nG0 X2\n");
  CHECK_EQ(join(read_lines(path)), std::string("1:too long|endless|"));
  std::remove(path);
  // /dev/zero: NUL bytes with no line end, forever.
  const std::vector<std::string> e = check_errors("/dev/zero");
  CHECK_EQ(e.size(), 1u);
  if (!e.empty()) CHECK_EQ(e[0], std::string("1:257: line is longer than 256 characters"));
}

namespace {

// A pipe fed `text` by a child process (it is longer than a pipe's buffer
// and the reader's), opened by name as `dexmill path -` meets standard input.
bool open_pipe(GcodeFile* file, const std::string& text, int* read_fd, pid_t* writer) {
  int fds[2];
  if (pipe(fds) != 0) return false;
  *writer = fork();
  if (*writer == 0) {
    close(fds[0]);
    const bool wrote = write(fds[1], text.data(), text.size()) == static_cast<ssize_t>(text.size());
    _exit(wrote ? 0 : 1);
  }
  close(fds[1]);
  *read_fd = fds[0];
  return *writer > 0 && file->open(("/dev/fd/" + std::to_string(fds[0])).c_str());
}

}  // namespace

// A pipe's copy (kept for loops and calls that go back) stops growing at
// its limit: reading goes on to the end, a seek back past the dropped copy
// fails (an error, never a silent wrong line) and within the limit works.
TEST(gcode_file_pipe_copy_is_bounded) {
  std::string text = "G21 G90\n";
  for (int i = 0; i < 20000; ++i) text += "G1 X" + std::to_string(i) + " F100\n";  // 300 KB
  text += "M2\n";
  for (const uint64_t limit : {uint64_t(1) << 20, uint64_t(200000)}) {
    GcodeFile file;
    file.set_pipe_copy_limit(limit);
    int fd = -1;
    pid_t writer = -1;
    CHECK(open_pipe(&file, text, &fd, &writer));
    const char* line;
    std::size_t len;
    uint32_t no;
    CHECK_EQ(file.next(&line, &len, &no), GcodeFile::Read::kLine);
    const SourcePos first = file.line_start();
    int lines = 1;
    while (file.next(&line, &len, &no) == GcodeFile::Read::kLine) ++lines;
    CHECK_EQ(lines, 20002);  // read to the end either way
    CHECK_EQ(file.seek(first), limit > text.size());
    close(fd);
    int status = -1;
    CHECK(waitpid(writer, &status, 0) == writer && status == 0);
  }
}
