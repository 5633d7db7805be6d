// Every command example in README.md and docs/*.md runs as written, so an
// example can never rot. The rules (also in docs/contributing.md):
//
// 1. An example is a line starting with `build/vibra ` or `vibra ` (after
//    leading spaces or a `$ ` prompt), inside a fenced code block tagged sh,
//    bash, shell or console, or in an indented code block (lines indented by
//    4 spaces after a blank line, outside fences; a list's wrapped text is
//    not one). A trailing `\` joins the next line. Fences with any other tag
//    (text, none) are never run.
// 2. An indented line containing `[`, `]` or `...` is a usage synopsis, not
//    an example.
// 3. Each example runs alone in a fresh empty directory holding build/vibra
//    (a link to the built executable; build/ is also on PATH for `vibra ...`)
//    and examples/ (a link to the repository's, for the files examples read)
//    under `bash -o pipefail -c`, stdin /dev/null, killed after 120 s. It
//    must exit 0.
// 4. An output named by `-o FILE` or `--output FILE` must exist afterwards
//    (a frame pattern with %d: its directory must hold a frame; `-` and
//    /dev/ paths are not checked).
// 5. Shrinking, mechanically: every `vibra render` and `vibra lecture` example runs at
//    --size 320x180 (its --size value replaced, or the option added before
//    the first pipe or at the end; a trailing comment is dropped). Nothing
//    else changes.
// 6. A trailing comment marks an example visibly in the docs:
//    `# vibra-example: fails` (must exit non-zero with one line on stderr),
//    `# vibra-example: skip (REASON)` (not run; the reason is required).
// 7. Known failures are listed below by exact command line with the issue
//    that tracks them; they must still fail, so the list cannot go stale.
// 8. Fewer examples than the docs are known to hold fails the test, so a
//    broken extractor cannot pass by running nothing.
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;

namespace {

struct DocExample {
  std::string where;    ///< "docs/render.md:42"
  std::string command;  ///< as written, without a trailing mark
  enum class Mark { run, fails, skip } mark = Mark::run;
};

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

bool is_vibra_command(const std::string& line) { return starts_with(line, "build/vibra ") || line == "build/vibra" ||
                                                        starts_with(line, "vibra ") || line == "vibra"; }

/// Splits off a trailing `# vibra-example: ...` mark. Throws for an unknown
/// mark or a skip without a reason, so a typo cannot silently skip.
DocExample with_mark(std::string command, const std::string& where) {
  DocExample example{where, command, DocExample::Mark::run};
  const size_t at = command.find("# vibra-example:");
  if (at == std::string::npos) return example;
  const std::string mark = trim(command.substr(at + 16));
  example.command = trim(command.substr(0, at));
  if (mark == "fails") {
    example.mark = DocExample::Mark::fails;
  } else if (starts_with(mark, "skip (") && mark.size() > 7 && mark.back() == ')') {
    example.mark = DocExample::Mark::skip;
  } else {
    throw std::runtime_error(where + ": unknown mark '" + mark + "': use 'fails' or 'skip (REASON)'");
  }
  return example;
}

/// The examples of one markdown text, by rules 1, 2 and 6.
std::vector<DocExample> extract_examples(const std::string& text, const std::string& file) {
  std::vector<DocExample> examples;
  std::istringstream in(text);
  std::string line, pending;
  int number = 0, pending_line = 0;
  bool in_fence = false, shell_fence = false;
  bool code_block = false;  // an indented code block: after a blank line, not a list's wrapped text
  bool previous_blank = true;
  while (std::getline(in, line)) {
    ++number;
    const std::string stripped = trim(line);
    const bool indented = starts_with(line, "    ");
    code_block = !in_fence && indented && (previous_blank || code_block);
    previous_blank = stripped.empty();
    if (!pending.empty()) {  // a continued command
      const bool more = !stripped.empty() && stripped.back() == '\\';
      pending += " " + (more ? trim(stripped.substr(0, stripped.size() - 1)) : stripped);
      if (!more) {
        examples.push_back(with_mark(pending, file + ":" + std::to_string(pending_line)));
        pending.clear();
      }
      continue;
    }
    if (starts_with(stripped, "```")) {
      if (!in_fence) {
        const std::string tag = trim(stripped.substr(3));
        shell_fence = tag == "sh" || tag == "bash" || tag == "shell" || tag == "console";
      }
      in_fence = !in_fence;
      continue;
    }
    if (in_fence ? !shell_fence : !code_block) continue;
    std::string command = starts_with(stripped, "$ ") ? trim(stripped.substr(2)) : stripped;
    if (!is_vibra_command(command)) continue;
    if (!in_fence && (command.find_first_of("[]") != std::string::npos || command.find("...") != std::string::npos))
      continue;  // a synopsis
    if (command.back() == '\\') {
      pending = trim(command.substr(0, command.size() - 1));
      pending_line = number;
      continue;
    }
    examples.push_back(with_mark(command, file + ":" + std::to_string(number)));
  }
  return examples;
}

/// Where a shell comment starts (a `#` beginning a word outside quotes), or npos.
size_t comment_start(const std::string& command) {
  char quote = 0;
  for (size_t i = 0; i < command.size(); ++i) {
    const char c = command[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && (i == 0 || command[i - 1] == ' ' || command[i - 1] == '\t')) {
      return i;
    }
  }
  return std::string::npos;
}

/// The command without its trailing comment, for matching and parsing.
std::string code_of(const std::string& command) { return trim(command.substr(0, comment_start(command))); }

/// Words of a command's code as the shell splits them (quotes removed),
/// enough to find options and their values.
std::vector<std::string> words(const std::string& command) {
  std::vector<std::string> out;
  std::string word;
  bool any = false;
  char quote = 0;
  for (char c : code_of(command)) {
    if (quote) {
      if (c == quote) quote = 0;
      else word += c;
    } else if (c == '\'' || c == '"') {
      quote = c, any = true;
    } else if (c == ' ' || c == '\t') {
      if (any || !word.empty()) out.push_back(word);
      word.clear(), any = false;
    } else {
      word += c;
    }
  }
  if (any || !word.empty()) out.push_back(word);
  return out;
}

/// Rule 5: `vibra render` runs at 320x180. Works on the code (the comment is
/// dropped): the --size value is replaced, or the option goes before the
/// first pipe, or at the end.
std::string shrunk(const std::string& command) {
  const auto w = words(command);
  if (w.size() < 2 || (w[1] != "render" && w[1] != "lecture")) return command;
  const std::string code = code_of(command), small = "320x180";
  const size_t size = code.find(" --size ");
  if (size != std::string::npos) {
    const size_t value = size + 8, end = code.find(' ', value);
    return code.substr(0, value) + small + (end == std::string::npos ? "" : code.substr(end));
  }
  const size_t pipe = code.find(" | ");
  if (pipe == std::string::npos) return code + " --size " + small;
  return code.substr(0, pipe) + " --size " + small + code.substr(pipe);
}

/// Rule 4: the outputs an example names.
std::vector<std::string> named_outputs(const std::string& command) {
  std::vector<std::string> out;
  const auto w = words(command);
  for (size_t i = 0; i + 1 < w.size(); ++i)
    if ((w[i] == "-o" || w[i] == "--output") && w[i + 1] != "-" && !starts_with(w[i + 1], "/dev/"))
      out.push_back(w[i + 1]);
  return out;
}

bool output_exists(const fs::path& dir, const std::string& output) {
  if (output.find('%') == std::string::npos) return fs::exists(dir / output);
  const fs::path frames = (dir / output).parent_path();
  return fs::is_directory(frames) && !fs::is_empty(frames);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string single_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct Outcome {
  int status;
  std::string err;
};

/// Rule 3: runs one command from a fresh directory holding build/vibra.
Outcome run_example(const std::string& command, const vibra::test::ScratchDirectory& dir,
                    const vibra::test::ScratchDirectory& logs) {
  const fs::path bin = logs.path / "build";
  fs::create_directories(bin);
  if (!fs::exists(bin / "vibra")) fs::create_symlink(VIBRA_EXE, bin / "vibra");
  fs::create_directories(dir.path / "build");
  fs::create_symlink(VIBRA_EXE, dir.path / "build" / "vibra");
  fs::create_directory_symlink(fs::path(VIBRA_SOURCE_DIR) / "examples", dir.path / "examples");
  const std::string shell = "cd " + single_quoted(dir.path.string()) + " && PATH=" + single_quoted(bin.string()) +
                            ":\"$PATH\" timeout 120 bash -o pipefail -c " + single_quoted(command) +
                            " </dev/null >/dev/null 2>" + single_quoted(logs / "err");
  const int status = std::system(shell.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), read_text(logs / "err")};
}

/// Rule 7: examples that fail today (by their code, without a comment), each
/// with the issue that tracks its fix.
const std::map<std::string, std::string> kKnownFailures = {
};

/// Optional parts of the build an example may need, by the option that uses
/// them: a build without the part (the mutants' and sanitizers' builds skip
/// the browser build) must refuse the example with one line naming the part.
struct BuildPart {
  const char* option;
  bool built;
  const char* refusal;  ///< what the one-line error says
};
constexpr BuildPart kBuildParts[] = {
    {"--live", VIBRA_TESTS_HAVE_WEB, "needs the browser build"},
};

/// The part `command` needs that this build lacks, if any.
const BuildPart* missing_part(const std::string& command) {
  for (const BuildPart& part : kBuildParts)
    if (!part.built && command.find(part.option) != std::string::npos) return &part;
  return nullptr;
}

/// Rule 8: the docs hold at least this many runnable examples.
constexpr size_t kMinimumExamples = 40;

std::vector<DocExample> all_examples() {
  const fs::path root = VIBRA_SOURCE_DIR;
  std::vector<fs::path> files{root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  std::sort(files.begin() + 1, files.end());
  std::vector<DocExample> examples;
  for (const auto& file : files) {
    auto found = extract_examples(read_text(file), fs::relative(file, root).string());
    examples.insert(examples.end(), found.begin(), found.end());
  }
  return examples;
}

}  // namespace

TEST_CASE("doc examples: the extractor's rules", "[doc_examples]") {
  const std::string markdown =
      "Text that mentions vibra solve undamped is not an example.\n"
      "- a list item whose text wraps onto a line that\n"
      "    vibra would not run\n"
      "\n"
      "    vibra solve MODEL [--set KEY=VALUE]...\n"
      "    vibra ascii undamped --exact\n"
      "    ffmpeg -i x.yuv\n"
      "\n"
      "```sh\n"
      "build/vibra solve undamped | head -n 2\n"
      "$ vibra plot undamped \\\n"
      "    -o u.svg\n"
      "build/vibra solve nope   # vibra-example: fails\n"
      "build/vibra ascii pendulum --set T=inf   # vibra-example: skip (runs until Ctrl-C)\n"
      "scripts/setup\n"
      "```\n"
      "```text\n"
      "build/vibra render\n"
      "```\n"
      "```\n"
      "vibra render\n"
      "```\n";
  const auto examples = extract_examples(markdown, "x.md");
  REQUIRE(examples.size() == 5);
  CHECK(examples[0].command == "vibra ascii undamped --exact");
  CHECK(examples[0].where == "x.md:6");
  CHECK(examples[1].command == "build/vibra solve undamped | head -n 2");
  CHECK(examples[2].command == "vibra plot undamped -o u.svg");
  CHECK(examples[2].where == "x.md:11");
  CHECK(examples[3].command == "build/vibra solve nope");
  CHECK(examples[3].mark == DocExample::Mark::fails);
  CHECK(examples[4].mark == DocExample::Mark::skip);
  CHECK_THROWS_WITH(extract_examples("```sh\nvibra solve x  # vibra-example: skip\n```\n", "y.md"),
                    Catch::Contains("y.md:2") && Catch::Contains("skip (REASON)"));
}

TEST_CASE("doc examples: renders shrink to 320x180, nothing else changes", "[doc_examples]") {
  CHECK(shrunk("build/vibra render") == "build/vibra render --size 320x180");
  CHECK(shrunk("build/vibra render --size 1920x1080 -o x.webm") == "build/vibra render --size 320x180 -o x.webm");
  CHECK(shrunk("build/vibra render -o x.mp4   # a video") == "build/vibra render -o x.mp4 --size 320x180");
  CHECK(shrunk("vibra render -o - | cat") == "vibra render -o - --size 320x180 | cat");
  CHECK(shrunk("build/vibra solve undamped --set dt=0.1") == "build/vibra solve undamped --set dt=0.1");
  CHECK(shrunk("build/vibra lecture story.toml -o x.mp4") == "build/vibra lecture story.toml -o x.mp4 --size 320x180");
  CHECK(code_of("vibra render --set \"colors.bob=#ff0000\"  # red") == "vibra render --set \"colors.bob=#ff0000\"");
  CHECK(named_outputs("build/vibra render -o 'a b.mp4' --set \"s=sin(u)\"") == std::vector<std::string>{"a b.mp4"});
  CHECK(named_outputs("vibra solve undamped --output x.csv -o -") == std::vector<std::string>{"x.csv"});
}

TEST_CASE("doc examples: the README's quick start is exactly two commands", "[doc_examples]") {
  const std::string readme = read_text(fs::path(VIBRA_SOURCE_DIR) / "README.md");
  const size_t section = readme.find("## Quick start");
  REQUIRE(section != std::string::npos);
  const size_t open = readme.find("```sh\n", section), close = readme.find("```", open + 6);
  REQUIRE(close != std::string::npos);
  CHECK(readme.substr(open + 6, close - open - 6) == "scripts/setup && build/vibra render\nscripts/test\n");
}

TEST_CASE("doc examples: every command in README.md and docs/*.md runs as written", "[doc_examples]") {
  const auto examples = all_examples();
  size_t runnable = 0;
  for (const auto& example : examples) {
    if (example.mark == DocExample::Mark::skip) continue;
    ++runnable;
    const std::string command = shrunk(example.command);
    INFO(example.where << ": " << example.command << "\n  ran: " << command);
    vibra::test::ScratchDirectory dir, logs;
    const Outcome outcome = run_example(command, dir, logs);
    INFO("exit status " << outcome.status << ", stderr:\n" << outcome.err);
    const auto known = kKnownFailures.find(code_of(example.command));
    const BuildPart* part = example.mark == DocExample::Mark::run ? missing_part(command) : nullptr;
    if (part) {
      INFO("this build lacks what " << part->option << " needs: the example must be refused in one line");
      CHECK(outcome.status == 2);
      CHECK(outcome.err.find(part->refusal) != std::string::npos);
      CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
    } else if (known != kKnownFailures.end()) {
      INFO("a known failure (" << known->second << "): when it passes, remove it from kKnownFailures");
      CHECK(outcome.status != 0);
    } else if (example.mark == DocExample::Mark::fails) {
      CHECK(outcome.status != 0);
      CHECK(outcome.status != 124);  // timeout's status: a hang is not the documented error
      CHECK(std::count(outcome.err.begin(), outcome.err.end(), '\n') == 1);
    } else {
      CHECK(outcome.status == 0);
      for (const auto& output : named_outputs(command)) {
        INFO("named output " << output);
        CHECK(output_exists(dir.path, output));
      }
    }
  }
  CHECK(runnable >= kMinimumExamples);
}
