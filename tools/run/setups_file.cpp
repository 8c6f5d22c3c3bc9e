// tools/run/setups_file.h: the setups file read into the chain's programs.
#include "tools/run/setups_file.h"

#include <cstring>
#include <string>
#include <vector>

#include "core/stock/stock_file.h"
#include "platform/os/path_name.h"
#include "platform/os/read_file.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_option_table.h"
#include "tools/run/setup_text.h"

namespace dexmill {
namespace cli {
namespace {

constexpr size_t kMaxSetupsFileBytes = size_t(1) << 20;

struct Word {
  std::string text;
  int column;  // of its first byte, from 1
};

// The line's words: split at blanks, '"' quoting blanks, '#' a comment
// from a word's start. False at an unclosed quote (*bad_column: its column).
bool split(const std::string& line, std::vector<Word>* words, int* bad_column) {
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) ++at;
    if (at >= line.size() || line[at] == '#') return true;
    Word w{"", static_cast<int>(at) + 1};
    int quote_column = 0;
    while (at < line.size() && (quote_column || (line[at] != ' ' && line[at] != '\t' && line[at] != '\r'))) {
      if (line[at] == '"') quote_column = quote_column ? 0 : static_cast<int>(at) + 1;
      else w.text += line[at];
      ++at;
    }
    if (quote_column) return *bad_column = quote_column, false;
    words->push_back(w);
  }
  return true;
}

// A path of the file as the command line would name it.
std::string beside(const std::string& setups_file, const std::string& path) {
  if (path.empty() || path[0] == '/') return path;
  const std::string folder = folder_of(setups_file);
  return folder == "." ? path : folder + "/" + path;
}

const char* const kSystems[9] = {"g54", "g55", "g56", "g57", "g58", "g59", "g59.1", "g59.2", "g59.3"};

// The options a key stands for (the ones the program's line may change).
const char* option_of(const std::string& key) {
  static const char* const kKeys[][2] = {{"tools", "--tools"},       {"design", "--design"},
                                         {"design-offset", "--design-offset"}, {"design-z", "--design-z"},
                                         {"fixture", "--fixture"},   {"table", "--table"}};
  for (const auto& k : kKeys)
    if (key == k[0]) return k[1];
  return nullptr;
}

std::string place(const std::string& file, int line, int column) {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

// One key=value of program k's line into the job.
int take_key(const std::string& file, int line, const Word& w, int k, RunOptions* o, JobOptions::Step* step) {
  const size_t eq = w.text.find('=');
  const int value_column = w.column + static_cast<int>(eq == std::string::npos ? 0 : eq + 1);
  const std::string key = eq == std::string::npos ? w.text : w.text.substr(0, eq);
  const bool known = key == "setup" || option_of(key) || key.compare(0, 2, "g5") == 0;
  FailPlace at(place(file, line, eq == std::string::npos || !known ? w.column : value_column));
  if (eq == std::string::npos || eq == 0)
    return fail(kExitInput, "'%s' is not key=value (the program comes first on its line, then setup=, tools=, "
                "design=, design-offset=, design-z=, fixture=, table=, g54= ... g59.3=)", w.text.c_str());
  const std::string value = w.text.substr(eq + 1);
  JobOptions& j = o->job;
  if (key == "setup") {
    StockSetup s;
    std::string why;
    if (!setup_parse(value, &s, &why)) return fail(kExitInput, "setup=%s: %s", value.c_str(), why.c_str());
    j.setups.push_back(s);
    j.setup_texts.push_back(value);
    j.setup_program.push_back(k);
    return kExitOk;
  }
  for (int c = 0; c < 9; ++c)
    if (key == kSystems[c]) {
      int64_t d[3];
      if (!parse_mm_list(value.c_str(), 3, d))
        return fail(kExitInput, "%s= needs the origin's X,Y,Z in mm, not '%s'", key.c_str(), value.c_str());
      step->have_work_offsets = true;
      step->work_offsets[c] = PointNm{d[0], d[1], d[2]};
      return kExitOk;
    }
  const char* option = option_of(key);
  if (!option)
    return fail(kExitInput, "unknown key '%s' (setup=, tools=, design=, design-offset=, design-z=, fixture=, table=, "
                "g54= ... g59.3=)", key.c_str());
  const bool file_value = key == "tools" || (key == "design" && (has_extension(value, ".stl") || has_extension(value, ".pgm")));
  step->options.emplace_back(option, file_value ? beside(file, value) : value);
  // Checked now, as the option checks it, so that the chain never stops
  // half way on a bad line.
  RunOptions scratch = *o;
  if (std::strcmp(option, "--fixture") == 0) scratch.job.checks.fixtures.clear();
  return apply_option(run_option_table(), option, step->options.back().second.c_str(), &scratch) ? kExitInput : kExitOk;
}

}  // namespace

int read_setups_file(RunOptions* o) {
  JobOptions& j = o->job;
  const std::string& file = j.setups_file;
  if (j.operands_seen > 0) return fail(kExitUsage, "--setups %s names the programs: give no FILE", file.c_str());
  if (!j.setups.empty()) return fail(kExitUsage, "--setups %s: give the setups in the file, not by --setup", file.c_str());
  std::vector<unsigned char> bytes;
  std::string err;
  const ReadFile r = read_whole_file(file, kMaxSetupsFileBytes, &bytes, &err);
  if (r != ReadFile::kOk) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return r == ReadFile::kIoError ? kExitIo : kExitInput;
  }
  std::vector<std::string> programs;
  size_t at = 0;
  for (int line = 1; at < bytes.size(); ++line) {
    size_t end = at;
    while (end < bytes.size() && bytes[end] != '\n') ++end;
    const std::string text(bytes.begin() + static_cast<long>(at), bytes.begin() + static_cast<long>(end));
    at = end + 1;
    const size_t nul = text.find('\0');
    if (nul != std::string::npos) {
      FailPlace p(place(file, line, static_cast<int>(nul) + 1));
      return fail(kExitInput, "a NUL byte: a setups file is text");
    }
    std::vector<Word> words;
    int bad = 0;
    if (!split(text, &words, &bad)) {
      FailPlace p(place(file, line, bad));
      return fail(kExitInput, "a quote that is not closed on its line");
    }
    if (words.empty()) continue;
    const int k = static_cast<int>(programs.size());
    FailPlace p(place(file, line, words[0].column));
    if (k >= kStockMaxPrograms)
      return fail(kExitInput, "more than %d programs: a stock remembers %d (split the job with --save-stock)",
                  kStockMaxPrograms, kStockMaxPrograms);
    if (words[0].text.find('=') != std::string::npos || words[0].text == "-")
      return fail(kExitInput, "'%s': a line starts with its program's file", words[0].text.c_str());
    programs.push_back(beside(file, words[0].text));
    JobOptions::Step step;
    step.place = file + ":" + std::to_string(line);
    for (size_t w = 1; w < words.size(); ++w)
      if (const int code = take_key(file, line, words[w], k, o, &step)) return code;
    {  // the line's options together (a PGM design and its heights)
      RunOptions scratch = *o;
      FailPlace whole(place(file, line, 1));
      if (const int code = apply_step(step, &scratch)) return code;
      if (finish_run_options(&scratch)) return kExitInput;
    }
    j.steps.push_back(step);
  }
  if (programs.empty()) {
    FailPlace p(place(file, 1, 1));
    return fail(kExitInput, "no program: a setups file has a line for each program, in the order they run");
  }
  j.file = programs[0];
  j.chain.assign(programs.begin() + 1, programs.end());
  j.operands_seen = static_cast<int>(programs.size());
  return kExitOk;
}

int apply_step(const JobOptions::Step& step, RunOptions* one) {
  bool fixtures = false;
  for (const auto& kv : step.options)
    if (kv.first == "--fixture") fixtures = true;
  if (fixtures) one->job.checks.fixtures.clear();  // this setup's clamps, not the command line's
  for (const auto& kv : step.options)
    if (const int code = apply_option(run_option_table(), kv.first.c_str(), kv.second.c_str(), one)) return code;
  if (step.have_work_offsets) {
    one->job.have_work_offsets = true;
    for (int c = 0; c < 9; ++c) one->job.work_offsets[c] = step.work_offsets[c];
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
