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

/// The production C++ files: the libraries, the Python bindings and the benchmarks.
std::vector<fs::path> production_sources() {
  std::vector<fs::path> files;
  for (const char* top : {"src", "render", "scenes", "python/src", "bench"})
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

TEST_CASE("architecture map: line 1 of every production source file says what the file is for", "[docs]") {
  const std::vector<fs::path> files = production_sources();
  REQUIRE(files.size() >= 300);  // src, render, scenes, python/src and bench were all found
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
