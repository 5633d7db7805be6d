// docs/architecture.md is a true map: it names every folder that holds source files, and every production file says on line 1 what it is for.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = VIBRA_SOURCE_DIR;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// What counts as source: code, build files, scripts, scene and page sources.
bool is_source_file(const fs::directory_entry& entry) {
  static const std::set<std::string> kSourceExtensions = {".cpp", ".hpp", ".h",    ".py",  ".sh",  ".cmake",
                                                          ".toml", ".js",  ".css", ".in",  ".ipynb"};
  const fs::path& path = entry.path();
  if (kSourceExtensions.count(path.extension().string()) || path.filename() == "CMakeLists.txt") return true;
  const bool executable = (entry.status().permissions() & fs::perms::owner_exec) != fs::perms::none;
  return path.extension().empty() && executable;  // scripts/test, .ci/run
}

/// Folders that are not the source tree: builds, caches, version control, virtual environments.
bool is_outside_source_tree(const fs::path& relative) {
  const std::string top = relative.begin()->string();
  const std::string name = relative.filename().string();
  const bool hidden = top.front() == '.' && top != ".ci";  // .git, .venv, tool caches; .ci holds the CI's script
  return hidden || top.rfind("build", 0) == 0 || name == "__pycache__";
}

/// Folders of data, not source: vendored code and the fuzzers' inputs.
bool is_data_folder(const std::string& relative) {
  return relative == "third_party" || relative.rfind("third_party/", 0) == 0 ||
         relative.rfind("tests/fuzz/corpus", 0) == 0 || relative.rfind("tests/fuzz/regressions", 0) == 0;
}

/// Every folder under the repository root (relative to it) that directly holds a source file.
std::vector<std::string> source_folders() {
  std::vector<std::string> folders;
  auto it = fs::recursive_directory_iterator(kRoot);
  for (; it != fs::recursive_directory_iterator(); ++it) {
    if (!it->is_directory()) continue;
    const fs::path relative = fs::relative(it->path(), kRoot);
    if (is_outside_source_tree(relative)) {
      it.disable_recursion_pending();
      continue;
    }
    const auto files = fs::directory_iterator(it->path());
    if (std::any_of(fs::begin(files), fs::end(files), [](const auto& e) { return e.is_regular_file() && is_source_file(e); }))
      folders.push_back(relative.generic_string());
  }
  std::sort(folders.begin(), folders.end());
  return folders;
}

/// The C++ files: the libraries, the Python bindings, the benchmarks, the tests and the browser build.
std::vector<fs::path> cpp_sources() {
  std::vector<fs::path> files;
  for (const char* top : {"src", "render", "scenes", "python/src", "bench", "tests", "web"})
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / top)) {
      const std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) files.push_back(entry.path());
    }
  std::sort(files.begin(), files.end());
  return files;
}

/// Whether `line` is a `//` comment of at least four words.
bool says_what_it_is(const std::string& line) {
  if (line.rfind("// ", 0) != 0) return false;
  std::istringstream words(line.substr(3));
  int count = 0;
  for (std::string word; words >> word;) ++count;
  return count >= 4;
}

}  // namespace

TEST_CASE("architecture map: docs/architecture.md names every folder that holds source files", "[docs]") {
  const std::string map = read_text(kRoot / "docs" / "architecture.md");
  REQUIRE(!map.empty());
  const std::vector<std::string> folders = source_folders();
  REQUIRE(folders.size() >= 20);  // a walk that finds nothing must not pass
  std::vector<std::string> missing;
  for (const std::string& folder : folders)
    if (folder != "." && map.find('`' + folder + "/`") == std::string::npos) missing.push_back(folder + "/");
  INFO("write each as `FOLDER/` in docs/architecture.md, with what it holds");
  for (const std::string& folder : missing) UNSCOPED_INFO("missing from the map: " << folder);
  CHECK(missing.empty());
}

TEST_CASE("architecture map: line 1 of every C++ source file says what the file is for", "[docs]") {
  const std::vector<fs::path> files = cpp_sources();
  REQUIRE(files.size() >= 400);  // src, render, scenes, python/src, bench and tests were all found
  std::vector<std::string> silent;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    if (!says_what_it_is(first)) silent.push_back(fs::relative(file, kRoot).generic_string());
  }
  INFO("give each a line 1 such as `// What this file is for, in a few words.`");
  for (const std::string& file : silent) UNSCOPED_INFO("line 1 says nothing: " << file);
  CHECK(silent.empty());
}

TEST_CASE("architecture map: no source folder holds more than 25 files", "[docs]") {
  // Past that a folder is a pile a newcomer scrolls through: split it by concept.
  constexpr long kMostFiles = 25;
  std::vector<std::string> piles;
  for (const std::string& folder : source_folders()) {
    if (folder == "." || is_data_folder(folder)) continue;  // the root's few files; data
    const auto entries = fs::directory_iterator(kRoot / folder);
    const long files = std::count_if(fs::begin(entries), fs::end(entries), [](const auto& e) { return e.is_regular_file(); });
    if (files > kMostFiles) piles.push_back(folder + " holds " + std::to_string(files) + " files");
  }
  for (const std::string& pile : piles) UNSCOPED_INFO(pile);
  CHECK(piles.empty());
}

/// The first line that is not a #! line, with its comment opener removed
/// ("" when it is not a comment): what a source file in any language says.
static std::string first_comment(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  if (line.rfind("#!", 0) == 0) std::getline(in, line);
  for (const char* opener : {"// ", "# ", "/* ", "<!-- ", "\"\"\""})
    if (line.rfind(opener, 0) == 0) return "// " + line.substr(std::string(opener).size());
  return "";
}

TEST_CASE("architecture map: line 1 of every other source file says what the file is for", "[docs]") {
  // Scripts, CMake, Python, the page's template, script and style, scene presets: all but data.
  std::vector<std::string> silent;
  long checked = 0;
  auto it = fs::recursive_directory_iterator(kRoot);
  for (; it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), kRoot);
    const std::string name = relative.generic_string();
    if (it->is_directory()) {
      if (is_outside_source_tree(relative) || is_data_folder(name)) it.disable_recursion_pending();
      continue;
    }
    const std::string ext = relative.extension().string();
    if (!it->is_regular_file() || !is_source_file(*it) || ext == ".cpp" || ext == ".hpp" || ext == ".ipynb") continue;
    ++checked;
    if (!says_what_it_is(first_comment(it->path()))) silent.push_back(name);
  }
  REQUIRE(checked >= 60);  // scripts, CMake files, Python, presets and the page were all found
  INFO("give each a first line such as `# What this file is for, in a few words.`");
  for (const std::string& file : silent) UNSCOPED_INFO("line 1 says nothing: " << file);
  CHECK(silent.empty());
}
