// `vibra chapter`: its table agrees with docs/exercises.md, it builds a site whose index holds every command, --check
// catches a changed number, and a second run is byte for byte the same.
#include <signal.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/chapter/chapter_book_values.hpp"
#include "cli/chapter/chapter_items.hpp"
#include "cli/chapter/chapter_jobs.hpp"
#include "cli/chapter/chapter_tables.hpp"
#include "cli_support.hpp"
#include "core/error.hpp"

namespace fs = std::filesystem;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

namespace {
using Args = std::vector<std::string>;

/// A command as a POSIX shell splits it: words, '...' and "..." (with \" inside).
Args shell_words(const std::string& line) {
  Args words;
  std::string word;
  bool in_word = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ' ' && in_word) words.push_back(word), word.clear(), in_word = false;
    if (c == ' ') continue;
    in_word = true;
    if (c == '\'' || c == '"') {
      for (++i; i < line.size() && line[i] != c; ++i) word += (c == '"' && line[i] == '\\') ? line[++i] : line[i];
    } else {
      word += c;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

/// docs/exercises.md as a map from item key (fig1.7, ex1.12) to its commands' arguments after `vibra`.
std::map<std::string, std::vector<Args>> documented_commands() {
  const std::string text = read_file(fs::path(VIBRA_SOURCE_DIR) / "docs/exercises.md");
  std::map<std::string, std::vector<Args>> items;
  const std::regex row(R"(^\| (1\.\d+)(?:(, |-)(1\.\d+))? \| (.*)$)");
  std::string prefix = "ex";
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## Figures", 0) == 0) prefix = "fig";
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    std::vector<Args> commands;
    const std::string rest = m[4];
    const std::regex code("`vibra ([^`]*)`");
    for (auto it = std::sregex_iterator(rest.begin(), rest.end(), code); it != std::sregex_iterator(); ++it)
      commands.push_back(shell_words((*it)[1]));
    const int first = std::stoi(std::string(m[1]).substr(2));
    const int last = m[3].matched ? std::stoi(std::string(m[3]).substr(2)) : first;
    for (int n = first; n <= last; ++n) items[prefix + "1." + std::to_string(n)] = commands;
  }
  return items;
}

/// The commands of a site's index page, as arguments after `vibra`, by the section (item key) they are in.
std::map<std::string, std::vector<Args>> index_commands(const std::string& html) {
  std::map<std::string, std::vector<Args>> items;
  std::string section;
  std::istringstream in(html);
  const std::regex id(R"re(<section id="([a-z]+1\.\d+)">)re"), command(R"re(<pre class="cmd">vibra (.*)</pre>)re");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, id)) section = m[1], items[section];
    std::string unescaped;
    if (!std::regex_match(line, m, command)) continue;
    unescaped = std::regex_replace(std::string(m[1]), std::regex("&#39;"), "'");
    unescaped = std::regex_replace(unescaped, std::regex("&quot;"), "\"");
    unescaped = std::regex_replace(unescaped, std::regex("&amp;"), "&");
    items[section].push_back(shell_words(unescaped));
  }
  return items;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  REQUIRE(out.good());
}

std::set<std::string> files_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}
}  // namespace

TEST_CASE("the chapter table holds every figure and exercise once, with the commands docs/exercises.md shows",
          "[chapter]") {
  const auto documented = documented_commands();
  std::set<std::string> keys;
  for (const auto& item : vibra::cli::chapter_items()) {
    const std::string key = vibra::cli::item_key(item);
    INFO(key);
    CHECK(keys.insert(key).second);
    REQUIRE(documented.count(key) == 1);
    CHECK(item.commands == documented.at(key));
  }
  std::set<std::string> expected;
  for (int n = 1; n <= 22; ++n) expected.insert("fig1." + std::to_string(n));
  for (int n = 1; n <= 28; ++n) expected.insert("ex1." + std::to_string(n));
  CHECK(keys == expected);
  CHECK(documented.size() == expected.size());
}

TEST_CASE("two commands of the chapter never write the same file unless they are the same command", "[chapter]") {
  std::map<std::string, Args> writer;
  for (const auto& item : vibra::cli::chapter_items())
    for (const auto& args : item.commands) {
      const std::string out = vibra::cli::command_output(args);
      if (out.empty()) continue;
      INFO(out);
      CHECK((writer.emplace(out, args).first->second == args));
      CHECK(out.find('/') == std::string::npos);  // the site is one flat folder
    }
}

TEST_CASE("vibra chapter --only picks a number's figure and exercise, or one by key, and refuses what the chapter lacks",
          "[chapter]") {
  using vibra::cli::select_items;
  auto keys = [](const std::string& only) {
    std::vector<std::string> out;
    for (const auto* item : select_items(only)) out.push_back(vibra::cli::item_key(*item));
    return out;
  };
  CHECK(keys("1.12,1.21") == std::vector<std::string>{"fig1.12", "fig1.21", "ex1.12", "ex1.21"});
  CHECK(keys("ex1.9,fig1.2") == std::vector<std::string>{"fig1.2", "ex1.9"});
  CHECK(keys("1.28") == std::vector<std::string>{"ex1.28"});
  CHECK(keys("").size() == 50);
  CHECK_THROWS_AS(select_items("1.29"), vibra::UsageError);
  CHECK_THROWS_AS(select_items("fig1.23"), vibra::UsageError);
  CHECK_THROWS_AS(select_items("1.12,"), vibra::UsageError);
}

TEST_CASE("table_cell reads a cell by column and row from aligned tables and from CSV", "[chapter]") {
  using vibra::cli::table_cell;
  const std::string aligned =
      "Convergence of undamped, schemes a,b: E = sqrt(...), r = ln(E_{i-1}/E_i) / ln 2\n"
      "scheme    i      dt        E      r\n"
      "centered  0   0.025  0.08354\n"
      "centered  1  0.0125  0.02085  2.002\n"
      "adjusted  0   0.025  2.5e-05\n"
      "adjusted  1  0.0125  1.6e-06  4.003\n"
      "adjusted: The rates have settled: r = 4.00 over the last two levels (order 4).\n";
  CHECK(table_cell(aligned, "r", {{"scheme", "centered"}, {"i", "last"}}) == "2.002");
  CHECK(table_cell(aligned, "r", {{"scheme", "adjusted"}, {"i", "1"}}) == "4.003");
  CHECK(table_cell(aligned, "r", {{"scheme", "centered"}, {"i", "0"}}) == "");  // the empty first rate
  CHECK(table_cell(aligned, "E", {{"i", "last"}}) == "1.6e-06");  // the sentence under the table is no row
  CHECK(table_cell(aligned, "E", {{"scheme", "other"}}) == "");
  CHECK(table_cell(aligned, "w", {{"i", "0"}}) == "");
  const std::string csv = "t,u,v\n0,1,0\n0.1,0.8026079119782128,-3.55\n0.2,0.2883589207400532,-5.71\n";
  CHECK(table_cell(csv, "u", {{"t", "0.1"}}) == "0.8026079119782128");
  CHECK(table_cell(csv, "v", {{"t", "last"}}) == "-5.71");
}

TEST_CASE("mask_columns replaces a timing column's cells and leaves the rest as they were", "[chapter]") {
  const std::string text =
      "heading line\n"
      "scheme  orbits  max_error     cpu_s\n"
      "pefrl       10  1.047e-06  0.000364\n"
      "pefrl       10  6.545e-08     0.012\n";
  CHECK(vibra::cli::mask_columns(text, {"cpu_s"}) ==
        "heading line\n"
        "scheme  orbits  max_error     cpu_s\n"
        "pefrl       10  1.047e-06         -\n"
        "pefrl       10  6.545e-08         -\n");
  CHECK(vibra::cli::mask_columns("a,cpu_s\n1,0.5\n", {"cpu_s"}) == "a,cpu_s\n1,-\n");
  CHECK(vibra::cli::mask_columns(text, {"elapsed"}) == text);
}

TEST_CASE("every stored book number names an item with that command, and a file replaces one by its name",
          "[chapter]") {
  for (const auto& number : vibra::cli::book_numbers()) {
    INFO(number.item << " " << vibra::cli::quantity_name(number));
    const auto items = vibra::cli::select_items(number.item);
    REQUIRE(items.size() == 1);
    CHECK(number.command < items[0]->commands.size());
  }
  ScratchDirectory dir;
  const std::string file = dir / "book.csv";
  write_text(file, "# tampered\nex1.12,r i=last,3\n");
  const auto numbers = vibra::cli::book_numbers_with(file);
  size_t changed = 0;
  for (size_t i = 0; i < numbers.size(); ++i) changed += numbers[i].book != vibra::cli::book_numbers()[i].book;
  CHECK(changed == 1);
  write_text(file, "ex1.12,r i=first,3\n");
  CHECK_THROWS_AS(vibra::cli::book_numbers_with(file), vibra::UsageError);
  write_text(file, "ex1.12,r i=last\n");
  CHECK_THROWS_AS(vibra::cli::book_numbers_with(file), vibra::UsageError);
}

TEST_CASE(
    "a site for --only 1.12,1.21 runs every command docs/exercises.md gives those items and shows each in its index",
    "[chapter]") {
  ScratchDirectory dir;
  const auto r = run_vibra("chapter --only 1.12,1.21 --jobs 2 -q -o " + (dir / "site/"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const fs::path site = dir.path / "site";
  const std::string index = read_file(site / "index.html");
  const auto shown = index_commands(index);
  const auto documented = documented_commands();
  CHECK(shown.size() == 4);
  for (const char* key : {"fig1.12", "fig1.21", "ex1.12", "ex1.21"}) {
    INFO(key);
    REQUIRE(shown.count(key) == 1);
    CHECK(shown.at(key) == documented.at(key));
    for (const Args& args : shown.at(key)) {
      const std::string out = vibra::cli::command_output(args);
      if (!out.empty()) CHECK(fs::file_size(site / out) > 1000);  // the command ran: its picture is there
    }
  }
  vibra::test::check_in_order(index, {"id=\"fig1.12\"", "id=\"fig1.21\"", "id=\"ex1.12\"", "id=\"ex1.21\""});
  // Standard output is kept beside the pictures, and the book's rate 2 stands beside vibra's.
  CHECK_THAT(read_file(site / "ex1.12-1.txt"), Catch::Contains("The rates have settled"));
  CHECK_THAT(read_file(site / "ex1.21-1.txt"), Catch::StartsWith("t,u,v\n0,1,0\n"));
  CHECK(std::regex_search(index, std::regex("<td>r i=last</td><td>2</td><td>2[0-9.]*</td><td>agrees</td>")));
  CHECK_THAT(index, Catch::Contains("(1.124) has a sign error"));
  CHECK(files_in(site) == std::set<std::string>{".vibra-manifest", "index.html", "figure_1_12.png", "figure_1_21.png",
                                                "ex1.12-1.txt", "ex1.21-1.txt"});
  CHECK(files_in(dir.path) == std::set<std::string>{"site"});  // no staging folder left beside it
}

TEST_CASE("vibra chapter --check exits 1 naming a book value that differs from vibra's, and 0 when all agree", "[chapter]") {
  ScratchDirectory dir;
  const auto agree = run_vibra("chapter --only ex1.12,ex1.6 --check");
  INFO(agree.err);
  CHECK(agree.exit_code == 0);
  CHECK(agree.err == "vibra: chapter --check: all 2 of the book's numbers agree\n");
  write_text(dir / "book.csv", "ex1.12,r i=last,3\n");
  const auto differs = run_vibra("chapter --only ex1.12,ex1.6 --check --book-values " + (dir / "book.csv"));
  INFO(differs.err);
  CHECK(differs.exit_code == 1);
  CHECK_THAT(differs.err, Catch::StartsWith("vibra: chapter --check: ex1.12 r i=last: the book gives 3, vibra 2"));
  CHECK(std::count(differs.err.begin(), differs.err.end(), '\n') == 1);
  vibra::test::check_refused("chapter --only ex1.12 --check --book-values " + (dir / "book.csv") + "-missing",
                             "--book-values");
}

TEST_CASE("a second chapter run makes the same site byte for byte, timings masked, videos included",
          "[chapter][heavy]") {
  ScratchDirectory dir;
  for (const char* site : {"a", "b"}) {
    const auto r = run_vibra("chapter --only 1.12,fig1.20,ex1.28 --jobs 2 -q -o " + (dir / site));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
  const auto names = files_in(dir.path / "a");
  CHECK(names.count("figure_1_20.mp4") == 1);
  CHECK(names.count("ex1.28-3.txt") == 1);
  CHECK(names == files_in(dir.path / "b"));
  for (const std::string& name : names) {
    INFO(name);
    CHECK(read_file(dir.path / "a" / name) == read_file(dir.path / "b" / name));
  }
  CHECK_THAT(read_file(dir.path / "a" / "ex1.28-3.txt"), Catch::Contains("  -\n"));
}

TEST_CASE("vibra chapter replaces its own earlier site and refuses a folder holding anything else", "[chapter]") {
  ScratchDirectory dir;
  const std::string site = dir / "site";
  REQUIRE(run_vibra("chapter --only ex1.19 -q -o " + site).exit_code == 0);
  REQUIRE(run_vibra("chapter --only fig1.17 -q -o " + site).exit_code == 0);
  CHECK(files_in(site) == std::set<std::string>{".vibra-manifest", "index.html", "figure_1_17.png"});
  write_text(site + "/notes.txt", "mine");
  const auto refused = run_vibra("chapter --only ex1.19 -q -o " + site);
  vibra::test::check_refusal(refused, "notes.txt");
  CHECK(read_file(site + "/notes.txt") == "mine");
  CHECK(files_in(site).size() == 4);
  CHECK(files_in(dir.path) == std::set<std::string>{"site"});
}

TEST_CASE("Ctrl-C stops vibra chapter and its running commands, leaving no site and no staging folder", "[chapter]") {
  ScratchDirectory dir;
  const pid_t pid = vibra::test::spawn_vibra({"chapter", "--jobs", "2", "-o", dir / "site"}, dir / "out", dir / "err");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  REQUIRE(::kill(pid, SIGINT) == 0);  // the parent alone: it must stop its commands itself
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  INFO(read_file(dir / "err"));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK_THAT(read_file(dir / "err"), Catch::EndsWith("vibra: interrupted by signal 2; no site was written\n"));
  CHECK(files_in(dir.path) == std::set<std::string>{"out", "err"});
}

TEST_CASE("run_chapter_jobs runs each command from the folder, keeps its output, and names one that fails",
          "[chapter]") {
  ScratchDirectory dir;
  using vibra::cli::ChapterJob;
  const std::vector<ChapterJob> jobs = {
      {{"solve", "undamped", "--set", "dt=0.1", "--set", "T=0.1"}, "a.txt", "first"},
      {{"solve", "undamped", "--set", "dt=0.1", "--set", "T=0.2", "-o", "run.csv"}, "b.txt", "second"}};
  vibra::cli::run_chapter_jobs(jobs, dir.path, 2, true);
  CHECK(read_file(dir.path / "a.txt") == "t,u,v\n0,1,0\n0.1,0.8026079119782128,-3.558205396299734\n");
  CHECK(read_file(dir.path / "b.txt").empty());  // "wrote" went to its messages, which are gone
  CHECK_THAT(read_file(dir.path / "run.csv"), Catch::StartsWith("t,u,v\n0,1,0\n0.1,"));
  CHECK(files_in(dir.path) == std::set<std::string>{"a.txt", "b.txt", "run.csv"});
  const std::vector<ChapterJob> failing = {{{"solve", "no-such-model"}, "c.txt", "third"}};
  try {
    vibra::cli::run_chapter_jobs(failing, dir.path, 1, true);
    FAIL("a failing command must throw");
  } catch (const std::exception& e) {
    CHECK_THAT(
        std::string(e.what()),
        Catch::StartsWith("chapter: 'vibra solve no-such-model' failed (exit 2): unknown model 'no-such-model'"));
  }
}
