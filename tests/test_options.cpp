// The option tables (tools/cli/option_table.h): the GNU forms of the parser,
// the suggestions for a misspelled option, and that every option of every
// table is in its subcommand's `--help` and in `dexmill --man-options`, so
// the help, the man page and the parser cannot drift apart.
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tools/cli/cli.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_suggest.h"

namespace {

using namespace dexmill::cli;
using namespace run_cli;

struct Args {
  std::string alpha;
  bool sw = false;
  std::vector<std::string> files;
};

const Option<Args> kArgsOptions[] = {
    {"--alpha", "V", "a value", [](Args* a, const char* v) -> int { return a->alpha = v, kExitOk; }},
    {"--switch", nullptr, "a switch", [](Args* a, const char*) -> int { return a->sw = true, kExitOk; }, "-s"},
};

const CommandText kArgsText = {"args", "usage: args\n", nullptr};

const OptionTable<Args>& args_table() {
  static const OptionTable<Args> t = [] {
    OptionTable<Args> table;
    table.text = &kArgsText;
    table.sections.push_back(section<Args>(nullptr, option_list(kArgsOptions), [](Args& a) -> Args& { return a; }));
    table.operand = [](Args* a, const char* arg, int) -> int { return a->files.emplace_back(arg), kExitOk; };
    return table;
  }();
  return t;
}

// Parses the words (the first is the subcommand's name) into *a.
int parse(std::vector<std::string> words, Args* a, bool* help) {
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(&w[0]);
  return parse_options(args_table(), static_cast<int>(argv.size()), argv.data(), a, help);
}

}  // namespace

TEST(options_gnu_forms) {
  Args a;
  bool help = true;
  CHECK_EQ(parse({"args", "--alpha=1,2", "-s", "--", "-x.ngc", "--alpha"}, &a, &help), 0);
  CHECK(!help);
  CHECK_EQ(a.alpha, std::string("1,2"));
  CHECK(a.sw);
  CHECK(a.files == (std::vector<std::string>{"-x.ngc", "--alpha"}));
  // A value may begin with '-'; "-" alone is an operand; "--alpha=" is an
  // empty value.
  a = Args();
  CHECK_EQ(parse({"args", "--alpha", "-5", "-", "--switch"}, &a, &help), 0);
  CHECK_EQ(a.alpha, std::string("-5"));
  CHECK(a.files == std::vector<std::string>{"-"});
  a = Args();
  CHECK_EQ(parse({"args", "--alpha=", "x"}, &a, &help), 0);
  CHECK(a.alpha.empty() && a.files == std::vector<std::string>{"x"});
  // --help among the options does nothing else; a value or an operand
  // after -- that reads --help is not one.
  a = Args();
  CHECK_EQ(parse({"args", "-s", "x", "--help"}, &a, &help), 0);
  CHECK(help && !a.sw && a.files.empty());
  CHECK_EQ(parse({"args", "--alpha", "--help", "--", "-h"}, &a, &help), 0);
  CHECK(!help);
  CHECK_EQ(a.alpha, std::string("--help"));
  CHECK(a.files == std::vector<std::string>{"-h"});
}

TEST(options_suggestions) {
  CHECK_EQ(edit_distance("strict", "strict"), 0u);
  CHECK_EQ(edit_distance("stirct", "strict"), 1u);  // neighbours swapped
  CHECK_EQ(edit_distance("colour", "color"), 1u);
  CHECK_EQ(edit_distance("", "abc"), 3u);
  CHECK_EQ(edit_distance("kitten", "sitting"), 3u);
  const std::vector<std::string> names{"--strict", "--stock", "--tool", "--tools", "--color", "-q", "--frames"};
  CHECK_EQ(suggest_option("--stirct", names), std::string("--strict"));
  CHECK_EQ(suggest_option("--colour", names), std::string("--color"));
  CHECK_EQ(suggest_option("--toolz", names), std::string("--tool or --tools"));
  CHECK_EQ(suggest_option("--frobnicate", names), std::string(""));
  CHECK_EQ(suggest_option("-x", names), std::string(""));  // one letter: never "-q"
  CHECK_EQ(suggest_option("--tx", names), std::string(""));  // fewer letters than edits
}

TEST(options_gnu_forms_on_the_command_line) {
  if (skip()) return;
  struct Case {
    const char* args;
    int code;
    const char* message;
  } cases[] = {
      {"run pocket.ngc --strcit", 2, "dexmill: error: unknown option '--strcit'; did you mean --strict? (try 'dexmill run --help')"},
      {"run pocket.ngc --frobnicate=3", 2, "dexmill: error: unknown option '--frobnicate' (try 'dexmill run --help')"},
      {"run pocket.ngc --size=0x0", 2, "dexmill: error: --size needs WxH"},
      {"run pocket.ngc --strict=yes", 2, "dexmill: error: --strict takes no value"},
      {"run -- -nofile.ngc", 3, "dexmill: error: cannot open '-nofile.ngc'"},
      {"check --simulate -- pocket.ngc --image x.png", 2, "more than one input file ('pocket.ngc' and '--image')"},
      {"zig --stock 0,0,-10,10,10,0 --stepovr 1 panel", 2, "did you mean --stepover? (try 'dexmill zig --help')"},
      {"optimize pocket.ngc --material wood -o", 2, "dexmill: error: -o needs a file (or - for standard output)"},
      {"bench --lsit", 2, "dexmill: error: bench: unknown option '--lsit'; did you mean --list?\n"},
  };
  for (const Case& c : cases) {
    const Result r = run_command(c.args);
    if (r.code != c.code || !has(r.err, c.message)) std::printf("  %s: exit %d\n", c.args, r.code);
    CHECK_EQ(r.code, c.code);
    CHECK(has(r.err, c.message));
  }
  // --opt=value reaches the option as --opt value does.
  const Result r = run_command("path pocket.ngc --chord=0.5 --units=mm");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "tol=0.5\n"));
}

// Every option of every table in the help of the subcommand that lists it,
// and as a .TP entry under its subcommand's .SS in the man page's lists.
TEST(options_in_help_and_man_page) {
  if (skip()) return;
  const Result man = run_command("--man-options");
  CHECK_EQ(man.code, 0);
  const std::vector<CommandDoc> docs = command_docs();
  CHECK_EQ(docs.size(), 7u);  // run, path, check, bench, optimize, measure, zig
  std::size_t at = 0;
  for (const CommandDoc& d : docs) {
    const std::string name = d.text->name;
    const Result help = run_command(name + " --help");
    CHECK_EQ(help.code, 0);
    // This subcommand's part of the man page: from its .SS to the next.
    const std::size_t ss = man.out.find(".SS \"dexmill " + name + "\"\n", at);
    if (!CHECK(ss != std::string::npos)) continue;
    at = ss + 1;
    const std::string part = man.out.substr(ss, man.out.find(".SS ", at) - ss);
    std::size_t listed = 0;
    for (const SectionDoc& s : d.sections) {
      if (s.see) {
        CHECK(has(help.out, (std::string("every option of dexmill ") + s.see).c_str()));
        CHECK(has(part, (std::string("every option of \\fBdexmill ") + s.see + "\\fR").c_str()));
        const Result other = run_command(std::string(s.see) + " --help");
        for (const OptionDoc& o : s.options) CHECK(has(other.out, ("  " + option_label(o) + " ").c_str()));
        continue;
      }
      for (const OptionDoc& o : s.options) {
        ++listed;
        CHECK(has(help.out, ("  " + option_label(o) + " ").c_str()));
        CHECK(has(part, (".TP\n" + std::string(o.alias ? "\\fB" + roff_text(o.alias) + "\\fR, " : "") + "\\fB" +
                         roff_text(o.name) + "\\fR")
                            .c_str()));
      }
    }
    std::size_t tp = 0;
    for (std::size_t p = part.find(".TP\n"); p != std::string::npos; p = part.find(".TP\n", p + 1)) ++tp;
    CHECK_EQ(tp, listed);
  }
}
