// Runs the real `vibra` executable for end-to-end tests.
#pragma once
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace vibra::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

/// A number as a command-line value that reads back to the same double.
inline std::string exact_text(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// Runs `vibra ARGS` through the shell, capturing stdout and stderr;
/// `launcher` goes before the executable (`setpriv ...`).
inline CommandResult run_vibra(const std::string& args, const std::string& launcher = "") {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const std::string err_path = (dir / ("vibra_cli_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++))).string();
  const std::string command = launcher + VIBRA_EXE + " " + args + " 2>" + err_path;
  CommandResult result;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (std::FILE* f = std::fopen(err_path.c_str(), "rb")) {
    while ((n = std::fread(buffer.data(), 1, buffer.size(), f)) > 0) result.err.append(buffer.data(), n);
    std::fclose(f);
  }
  std::filesystem::remove(err_path);
  return result;
}

/// The standard output of a shell command (ffprobe, ffmpeg; binary safe).
inline std::string shell(const std::string& command) {
  std::string out;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[1 << 16];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  ::pclose(pipe);
  return out;
}

/// A file's bytes ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::string bytes;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) bytes.append(buffer, n);
    std::fclose(f);
  }
  return bytes;
}

/// Writes `text` to `path` (a test's own file), failing the test if it cannot.
inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f);
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  REQUIRE((std::fclose(f) == 0 && written));
}

/// In a forked child: becomes `vibra ARGS` (exit 127 if that fails).
[[noreturn]] inline void exec_vibra(const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(VIBRA_EXE)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(VIBRA_EXE, argv.data());
  ::_exit(127);
}

/// Starts `vibra ARGS` as a child process, without a shell, its stdout and
/// stderr written to the given files (e.g. /dev/null); returns its pid.
inline pid_t spawn_vibra(const std::vector<std::string>& args, const std::string& out_file,
                         const std::string& err_file) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(err, 2);
    exec_vibra(args);
  }
  return pid;
}

/// Runs `vibra ARGS` with its stdout into a pipe, reads `keep` bytes and
/// closes the pipe, as `| head -c KEEP` does; returns vibra's own exit code
/// and stderr (`out` holds the bytes read).
inline CommandResult read_then_close(const std::vector<std::string>& args, std::size_t keep) {
  static int counter = 0;
  const std::string err_path = (std::filesystem::temp_directory_path() /
                                ("vibra_pipe_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++)))
                                   .string();
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    ::dup2(fds[1], 1);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(err, 2);
    exec_vibra(args);
  }
  ::close(fds[1]);
  CommandResult result;
  result.out.resize(keep);
  std::size_t got = 0;
  while (got < keep) {
    const ssize_t n = ::read(fds[0], result.out.data() + got, keep - got);
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  result.out.resize(got);
  CHECK(got == keep);
  ::close(fds[0]);  // the reader goes away mid-stream
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.err = read_file(err_path);
  std::filesystem::remove(err_path);
  return result;
}

/// A fresh empty directory of its own under the temporary directory
/// (mkdtemp: no other process, suite or test case gets the same one), removed
/// with its contents by the destructor. Every file a test writes goes into
/// one, never to a fixed name in /tmp, so that two suites can run at once.
struct ScratchDirectory {
  std::filesystem::path path;
  ScratchDirectory() {
    // Never a name holding a command-line placeholder (OUT, SEGS): the tests
    // replace those in lines that hold this path (a name such as OUT4FH was).
    for (;;) {
      std::string name = (std::filesystem::temp_directory_path() / "vibra_test_XXXXXX").string();
      if (!::mkdtemp(name.data())) throw std::runtime_error("cannot create a scratch directory in " + name);
      path = name;
      const std::string leaf = path.filename().string();
      if (leaf.find("OUT") == std::string::npos && leaf.find("SEGS") == std::string::npos) return;
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  }
  ScratchDirectory(ScratchDirectory&& other) noexcept : path(std::move(other.path)) { other.path.clear(); }
  ScratchDirectory& operator=(ScratchDirectory&&) = delete;
  ~ScratchDirectory() {
    std::error_code ignored;
    if (!path.empty()) std::filesystem::remove_all(path, ignored);
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  bool empty() const { return std::filesystem::is_empty(path); }
};

/// Checks that a run was refused as every refusal must be: exit code 2 and
/// one line on stderr, "vibra: error: ..." containing `expected`. What the
/// run must not have written is the caller's to check (see check_refused).
inline void check_refusal(const CommandResult& r, const std::string& expected) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::StartsWith("vibra: error: ") && Catch::Contains(expected));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

/// Checks that `vibra ARGS` refuses bad input as every command must (see
/// check_refusal) and writes nothing: each OUT in `args` becomes a path in a
/// fresh directory, which must stay empty.
inline void check_refused(std::string args, const std::string& expected, const std::string& launcher = "") {
  ScratchDirectory dir;
  // From past each replacement: the scratch folder's random name may itself hold "OUT".
  const std::string out = dir / "out";
  for (auto at = args.find("OUT"); at != std::string::npos; at = args.find("OUT", at + out.size())) args.replace(at, 3, out);
  INFO("vibra " << args);
  check_refusal(run_vibra(args, launcher), expected);
  CHECK(dir.empty());
}

/// The cells of a command's CSV output, row by row (a trailing comma is an empty last cell).
inline std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
    if (!line.empty() && line.back() == ',') rows.back().push_back("");
  }
  return rows;
}

/// Checks that each of `parts` occurs in `text` and that their first
/// occurrences come in the given order (a missing part fails, where comparing
/// two find() results would pass with npos on the right).
inline void check_in_order(const std::string& text, const std::vector<std::string>& parts) {
  std::size_t previous = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::size_t at = text.find(parts[i]);
    INFO("'" << parts[i] << "'");
    REQUIRE(at != std::string::npos);
    if (i) CHECK(at > previous);
    previous = at;
  }
}

/// The types of an MP4 (ISO BMFF) file's top-level boxes, in file order.
inline std::vector<std::string> mp4_top_level_boxes(const std::string& bytes) {
  std::vector<std::string> boxes;
  std::uint64_t at = 0;
  while (at + 8 <= bytes.size()) {
    auto byte = [&](std::uint64_t i) { return std::uint64_t(static_cast<unsigned char>(bytes[i])); };
    std::uint64_t size = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    boxes.push_back(bytes.substr(at + 4, 4));
    if (size == 1 && at + 16 <= bytes.size()) {  // a 64-bit size follows the type
      size = 0;
      for (std::uint64_t k = 8; k < 16; ++k) size = size << 8 | byte(at + k);
    }
    if (size < 8) break;  // 0: to the end of the file
    at += size;
  }
  return boxes;
}

/// A PNG file's width and height from its IHDR chunk ({0, 0} if it is not a PNG).
inline std::pair<int, int> png_size(const std::filesystem::path& path) {
  const std::string bytes = read_file(path);
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || bytes.compare(12, 4, "IHDR") != 0) return {0, 0};
  auto be32 = [&](std::size_t i) {
    return int(static_cast<unsigned char>(bytes[i])) << 24 | int(static_cast<unsigned char>(bytes[i + 1])) << 16 |
           int(static_cast<unsigned char>(bytes[i + 2])) << 8 | int(static_cast<unsigned char>(bytes[i + 3]));
  };
  return {be32(16), be32(20)};
}

/// Whether this run is CI's (CI=true): a test that needs a tool (Chromium,
/// Slurm, GNU parallel, root, huge pages) must then fail when it is missing,
/// saying what to install, instead of skipping as on a developer's machine.
inline bool in_ci() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

}  // namespace vibra::test
