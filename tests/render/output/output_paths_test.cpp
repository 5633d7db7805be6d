// Where outputs go (render/output/output_path.hpp, docs/reliability.md "Output
// paths"), through the real executable: a symbolic link stays and its target
// gets the output; a pipe or device gets a stream; a folder where a file is
// expected, an input of the run and an empty path are refused before any
// work; missing folders are made and removed again on failure; an interrupted
// run leaves earlier output byte for byte; a page keeps its companions in
// PAGE_files/ and never overwrites a file the user did not name.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"

using vibra::test::read_file;
using vibra::test::check_refusal;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::shell;
namespace fs = std::filesystem;

namespace {
const std::string kShortPaths = " --size 160x90 --set periods=0.5 -q ";  // 31 frames

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

size_t lines(const std::string& text) { return static_cast<size_t>(std::count(text.begin(), text.end(), '\n')); }

/// Every entry under `dir`, relative, sorted.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) found.push_back(e.path().lexically_relative(dir).string());
  std::sort(found.begin(), found.end());
  return found;
}

/// A FIFO with a reader that drains it on its own thread, as `cat FIFO &`
/// would; the reader never blocks, so a run that refuses the FIFO does not
/// hang the test.
class FifoReader {
 public:
  explicit FifoReader(const fs::path& path) {
    REQUIRE(::mkfifo(path.c_str(), 0644) == 0);
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK);
    REQUIRE(fd_ >= 0);
    thread_ = std::thread([this] {
      char buffer[1 << 16];
      for (;;) {
        const bool last = stop_;
        for (ssize_t n; (n = ::read(fd_, buffer, sizeof buffer)) > 0;) data_.append(buffer, static_cast<size_t>(n));
        if (last) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    });
  }
  ~FifoReader() {
    if (thread_.joinable()) finish();
  }
  /// What came through the FIFO; call after the writer has exited.
  std::string finish() {
    stop_ = true;
    thread_.join();
    ::close(fd_);
    return data_;
  }

 private:
  int fd_ = -1;
  std::atomic<bool> stop_ = false;
  std::string data_;
  std::thread thread_;
};

/// `vibra ARGS` run from `dir` as the working directory, through the shell.
vibra::test::CommandResult run_in(const ScratchDirectory& dir, const std::string& args) {
  ScratchDirectory logs;
  vibra::test::CommandResult result;
  const std::string out = shell("cd '" + dir.path.string() + "' && " + VIBRA_EXE + " " + args + " 2>'" + (logs / "err") +
                                "' >/dev/null; echo $?");
  result.exit_code = std::stoi(out);
  result.err = read_file(logs / "err");
  return result;
}

}  // namespace

TEST_CASE("a symbolic link at the output stays, and its target gets the output", "[output][paths]") {
  ScratchDirectory dir;
  fs::create_directory(dir.path / "data");
  write(dir.path / "data/real.csv", "old\n");
  fs::create_symlink("data/real.csv", dir.path / "link.csv");
  const auto solved = run_vibra("solve undamped --set periods=1 -o " + (dir / "link.csv"));
  INFO(solved.err);
  REQUIRE(solved.exit_code == 0);
  CHECK(fs::is_symlink(dir.path / "link.csv"));
  CHECK(fs::read_symlink(dir.path / "link.csv") == "data/real.csv");
  CHECK(read_file(dir.path / "data/real.csv") == run_vibra("solve undamped --set periods=1").out);
  CHECK_THAT(solved.err, Catch::Contains("link.csv") && Catch::Contains("real.csv"));  // wrote: both named

  // A link to a file not yet there: the file is made, the link kept.
  fs::create_symlink("data/later.png", dir.path / "still.png");
  REQUIRE(run_vibra("render --size 160x90 --at 1 -q -o " + (dir / "still.png")).exit_code == 0);
  CHECK(fs::is_symlink(dir.path / "still.png"));
  CHECK(read_file(dir.path / "data/later.png").substr(1, 3) == "PNG");

  // A video through a link: no temporary is left beside the link or the target.
  fs::create_symlink(dir.path / "data/clip.mp4", dir.path / "clip.mp4");
  REQUIRE(run_vibra("render" + kShortPaths + "-o " + (dir / "clip.mp4")).exit_code == 0);
  CHECK(fs::is_symlink(dir.path / "clip.mp4"));
  CHECK(fs::file_size(dir.path / "data/clip.mp4") > 1000);
  CHECK(entries(dir.path) == std::vector<std::string>{"clip.mp4", "data", "data/clip.mp4", "data/later.png",
                                                       "data/real.csv", "link.csv", "still.png"});
}

TEST_CASE("a FIFO or /dev/fd/1 gets the CSV as a stream, as -o - does", "[output][paths][stream]") {
  ScratchDirectory dir;
  const std::string expected = run_vibra("solve undamped --set periods=2").out;
  REQUIRE(lines(expected) > 10);
  {
    FifoReader reader(dir.path / "pipe.csv");
    const auto r = run_vibra("solve undamped --set periods=2 -o " + (dir / "pipe.csv"));
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(reader.finish() == expected);
    CHECK(fs::is_fifo(dir.path / "pipe.csv"));  // still the pipe, not a file in its place
  }
  // Standard output named as a path, redirected to a file: the file gets the stream.
  const auto r = run_vibra("solve undamped --set periods=2 -q -o /dev/fd/1 > " + (dir / "out.csv"));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(read_file(dir.path / "out.csv") == expected);
  const auto piped = run_vibra("solve undamped --set periods=2 -q -o /dev/stdout");
  CHECK(piped.exit_code == 0);
  CHECK(piped.out == expected);

  // A video in a stream format through a FIFO: the y4m header arrives.
  {
    FifoReader reader(dir.path / "video");
    const auto v = run_vibra("render" + kShortPaths + "--format y4m -o " + (dir / "video"));
    INFO(v.err);
    CHECK(v.exit_code == 0);
    CHECK_THAT(reader.finish(), Catch::StartsWith("YUV4MPEG2 W160 H90"));
  }
}

TEST_CASE("outputs that cannot stream refuse a FIFO or device with one line", "[output][paths][stream]") {
  ScratchDirectory dir;
  const std::pair<std::string, std::string> cases[] = {
      {"render" + kShortPaths + "-o FIFO", "add --format y4m"},  // a video streams only in a stream format
      {"render" + kShortPaths + "-o /dev/null", "add --format y4m"},
      {"render" + kShortPaths + "--at 1 -o FIFO", "give a file name"},
      {"render" + kShortPaths + "-o page.html", "give a file name"},
      {"plot undamped -o FIFO", "give a file name"},
      {"analyze convergence undamped --levels 3 -o FIFO", "give a file name"},
      {"render" + kShortPaths + "--segment 0/2 --format y4m -o FIFO", "not a stream"},
  };
  for (const auto& [args, expected] : cases) {
    std::string command = args;
    const std::string name = command.find("page.html") != std::string::npos ? "page.html" : "fifo.png";
    FifoReader reader(dir.path / name);
    for (const char* placeholder : {"FIFO", "page.html"})
      if (const auto at = command.find(placeholder); at != std::string::npos)
        command.replace(at, std::string(placeholder).size(), dir / name);
    INFO("vibra " << command);
    check_refusal(run_vibra(command), expected);
    CHECK(reader.finish().empty());
    CHECK(fs::is_fifo(dir.path / name));
    CHECK(entries(dir.path) == std::vector<std::string>{name});
    fs::remove(dir.path / name);
  }
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("a folder where a file is expected is refused before any work", "[output][paths]") {
  ScratchDirectory dir;
  for (const char* name : {"p.html", "out.mp4", "still.png", "u.csv", "fig.svg"}) fs::create_directory(dir.path / name);
  const std::pair<std::string, std::string> cases[] = {
      {"render" + kShortPaths + "-o " + (dir / "p.html"), "p.html"},
      {"render" + kShortPaths + "--skip-existing -o " + (dir / "p.html"), "p.html"},  // a folder is not a complete page
      {"render" + kShortPaths + "-o " + (dir / "out.mp4"), "out.mp4"},
      {"render" + kShortPaths + "--skip-existing -o " + (dir / "out.mp4"), "out.mp4"},
      {"render" + kShortPaths + "--at 1 -o " + (dir / "still.png"), "still.png"},
      {"solve undamped -o " + (dir / "u.csv"), "u.csv"},
      {"plot undamped -o " + (dir / "fig.svg"), "fig.svg"},
      {"analyze convergence undamped --levels 3 -o " + (dir / "fig.svg"), "fig.svg"},
  };
  for (const auto& [args, named] : cases) {
    INFO("vibra " << args);
    const auto start = std::chrono::steady_clock::now();
    check_refusal(run_vibra(args), named + "' is a folder");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
  }
  // Nothing else appeared: no companions of the page, no temporaries.
  CHECK(entries(dir.path) == std::vector<std::string>{"fig.svg", "out.mp4", "p.html", "still.png", "u.csv"});
}

TEST_CASE("missing folders are made for every kind of output, and removed when the run fails", "[output][paths]") {
  ScratchDirectory dir;
  const std::pair<std::string, std::string> made[] = {
      {"solve undamped --set periods=1 -q -o " + (dir / "a/b/u.csv"), "a/b/u.csv"},
      {"render" + kShortPaths + "-o " + (dir / "c/d/clip.mp4"), "c/d/clip.mp4"},
      {"render" + kShortPaths + "--at 1 -o " + (dir / "e/still.svg"), "e/still.svg"},
      {"render" + kShortPaths + "-o " + (dir / "f/g/page.html"), "f/g/page_files/page.csv"},
      {"plot undamped -q -o " + (dir / "h/fig.png"), "h/fig.png"},
      {"analyze convergence undamped --levels 3 -q -o " + (dir / "i/j/c.svg"), "i/j/c.svg"},
      {"render" + kShortPaths + "-o " + (dir / "k/l/tmp_%04d.png"), "k/l/tmp_0030.png"},
  };
  for (const auto& [args, file] : made) {
    INFO("vibra " << args);
    const auto r = run_vibra(args);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(fs::is_regular_file(dir.path / file));
  }
  // A run that fails after its work began leaves none of the folders it made.
  ScratchDirectory failing;
  const std::string failures[] = {
      "solve undamped --set scheme=forward-euler --set dt=0.3 --set T=1e4 -o " + (failing / "m/n/u.csv"),
      "render undamped --set scheme=forward-euler --set dt=0.3 --set T=1e4 --size 160x90 -q -o " +
          (failing / "o/p/page.html"),
  };
  for (const auto& args : failures) {
    INFO("vibra " << args);
    check_refusal(run_vibra(args), "");
    CHECK(failing.empty());
  }
}

TEST_CASE("an interrupted render leaves an earlier run's frames byte for byte", "[output][paths][signals]") {
  ScratchDirectory dir, logs;
  const std::string pattern = dir / "frames/f_%04d.png";
  // The earlier run: 301 small frames.
  REQUIRE(run_vibra("render --size 160x90 --set periods=5 -q -o " + pattern).exit_code == 0);
  std::map<fs::path, std::string> earlier;
  for (const auto& e : fs::directory_iterator(dir.path / "frames")) earlier[e.path()] = read_file(e.path());
  REQUIRE(earlier.size() == 302);  // and the ledger of the frames vibra wrote
  auto new_frames_exist = [&] {  // replaced frames, or frames waiting beside them
    for (const auto& e : fs::recursive_directory_iterator(dir.path / "frames")) {
      const auto old = earlier.find(e.path());
      if (e.is_regular_file() && (old == earlier.end() || read_file(e.path()) != old->second)) return true;
    }
    return false;
  };
  // The new run draws other, larger frames under the same names, slowly enough to be stopped.
  const pid_t pid = vibra::test::spawn_vibra(
      {"render", "--size", "960x540", "--set", "periods=5", "--set", "Theta=20", "--threads", "1", "-q", "-o", pattern},
      logs / "out", logs / "err");
  for (int i = 0; i < 1000 && !new_frames_exist(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK_THAT(read_file(logs / "err"), Catch::StartsWith("vibra: interrupted by signal 2"));
  std::map<fs::path, std::string> after;
  for (const auto& e : fs::recursive_directory_iterator(dir.path / "frames")) after[e.path()] = read_file(e.path());
  CHECK(after.size() == earlier.size());  // no frame lost, none added, no temporary left
  size_t same = 0;
  for (const auto& [path, bytes] : earlier) same += after.count(path) && after[path] == bytes;
  CHECK(same == earlier.size());
}

TEST_CASE("a shorter run leaves exactly its own frames under the pattern", "[output][paths]") {
  ScratchDirectory dir;
  const std::string pattern = dir / "frames/f_%04d.png";
  REQUIRE(run_vibra("render --size 160x90 --set periods=0.5 -q -o " + pattern).exit_code == 0);  // 31 frames
  REQUIRE(entries(dir.path / "frames").size() == 31 + 1);  // and the ledger of the frames vibra wrote
  // The user's own files in the folder, one of them almost a frame's name.
  write(dir.path / "frames/notes.txt", "mine");
  write(dir.path / "frames/f_12ab.png", "mine too");
  write(dir.path / "frames/g_0040.png", "another pattern's");
  // A segment of a longer render removes nothing: the other segments' frames belong there.
  REQUIRE(run_vibra("render --size 160x90 --set periods=1 -q --segment 0/2 -o " + pattern).exit_code == 0);
  CHECK(entries(dir.path / "frames").size() == 31 + 1 + 3 + 1);  // and the segment's own ledger
  const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + pattern);  // 7 frames
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("removed 24 frames of an earlier run"));
  std::vector<std::string> expected = {".vibra-frames", "f_12ab.png"};  // the segment's ledger folded into the run's
  for (int i = 0; i < 7; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "f_%04d.png", i);
    expected.push_back(name);
  }
  expected.push_back("g_0040.png");
  expected.push_back("notes.txt");
  std::sort(expected.begin(), expected.end());
  CHECK(entries(dir.path / "frames") == expected);
}

TEST_CASE("a page keeps its companions in PAGE_files/ and leaves the user's files alone", "[output][paths][page]") {
  ScratchDirectory dir;
  for (const char* name : {"lecture.mp4", "lecture.webm", "lecture.csv"}) write(dir.path / name, std::string("mine: ") + name);
  const auto r = run_vibra("render --size 160x90 --set periods=0.5 -o " + (dir / "lecture.html"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* name : {"lecture.mp4", "lecture.webm", "lecture.csv"}) CHECK(read_file(dir.path / name) == std::string("mine: ") + name);
  CHECK(entries(dir.path / "lecture_files") ==  // and the manifest that proves them vibra's
        std::vector<std::string>{".vibra-manifest", "lecture.csv", "lecture.mp4", "lecture.webm"});
  const std::string html = read_file(dir.path / "lecture.html");
  CHECK_THAT(html, Catch::Contains("<source src=\"lecture_files/lecture.mp4\"") &&
                       Catch::Contains("<a href=\"lecture_files/lecture.csv\" download>"));
  // The closing line names every file written.
  const std::string wrote = r.err.substr(r.err.rfind("vibra: wrote"));
  for (const char* name : {"lecture.html", "lecture_files/lecture.mp4", "lecture_files/lecture.webm", "lecture_files/lecture.csv"})
    CHECK_THAT(wrote, Catch::Contains(name));

  // Again, as a frames player: vibra's own folder is replaced whole, without --force.
  REQUIRE(run_vibra("render" + kShortPaths + "--frames-player -o " + (dir / "lecture.html")).exit_code == 0);
  const auto files = entries(dir.path / "lecture_files");
  CHECK(files.size() == 34);  // 31 frames, their ledger, the CSV and the manifest
  CHECK(std::find(files.begin(), files.end(), "lecture.mp4") == files.end());
  CHECK_THAT(read_file(dir.path / "lecture.html"), Catch::Contains("\"prefix\":\"lecture_files/frame_\""));

  // A PAGE_files/ folder that is not vibra's is refused, naming it; --force replaces it.
  fs::create_directory(dir.path / "notes_files");
  write(dir.path / "notes_files/mine.txt", "my notes");
  const auto refused = run_vibra("render" + kShortPaths + "-o " + (dir / "notes.html"));
  check_refusal(refused, dir / "notes_files");
  CHECK_THAT(refused.err, Catch::Contains("--force"));
  CHECK_FALSE(fs::exists(dir.path / "notes.html"));
  CHECK(read_file(dir.path / "notes_files/mine.txt") == "my notes");
  REQUIRE(run_vibra("render" + kShortPaths + "--force -o " + (dir / "notes.html")).exit_code == 0);
  CHECK(entries(dir.path / "notes_files") ==
        std::vector<std::string>{".vibra-manifest", "notes.csv", "notes.mp4", "notes.webm"});
}

TEST_CASE("a segment's file is overwritten only when vibra wrote it for that segment", "[output][paths][segment]") {
  ScratchDirectory dir;
  write(dir.path / "clip.seg-0-of-2.mp4", "my own video");
  const auto refused = run_vibra("render" + kShortPaths + "--segment 0/2 -o " + (dir / "clip.mp4"));
  check_refusal(refused, dir / "clip.seg-0-of-2.mp4");
  CHECK_THAT(refused.err, Catch::Contains("--force"));
  CHECK(read_file(dir.path / "clip.seg-0-of-2.mp4") == "my own video");
  REQUIRE(run_vibra("render" + kShortPaths + "--segment 0/2 --force -o " + (dir / "clip.mp4")).exit_code == 0);
  // Now vibra's: a second run replaces it without --force.
  CHECK(run_vibra("render" + kShortPaths + "--segment 0/2 -o " + (dir / "clip.mp4")).exit_code == 0);
}

TEST_CASE("an input of the run is never an output of it", "[output][paths]") {
  ScratchDirectory dir;
  std::string heights;
  for (int i = 0; i < 200; ++i) heights += std::to_string(0.01 * (i % 7)) + "\n";
  write(dir.path / "road.csv", heights);
  const std::string road = " --set road=" + (dir / "road.csv") + " --set dx=0.2 --set T=2 ";
  const auto solved = run_vibra("solve bumpy-road" + road + "-o " + (dir / "road.csv"));
  check_refusal(solved, dir / "road.csv");
  CHECK_THAT(solved.err, Catch::Contains("reads"));
  CHECK(read_file(dir.path / "road.csv") == heights);

  // The page's CSV goes to road_files/, so the road stays; a page that would write its road is refused.
  const auto page = run_vibra("render bumpy_road" + road + "--size 160x90 -q -o " + (dir / "road.html"));
  INFO(page.err);
  CHECK(page.exit_code == 0);
  CHECK(read_file(dir.path / "road.csv") == heights);
  fs::rename(dir.path / "road.csv", dir.path / "road_files/road.csv");
  const auto inside = run_vibra("render bumpy_road --set road=" + (dir / "road_files/road.csv") +
                                " --set dx=0.2 --set T=2 --size 160x90 -q -o " + (dir / "road.html"));
  check_refusal(inside, "road.csv");
  CHECK(read_file(dir.path / "road_files/road.csv") == heights);

  // The scene file itself (any name is read as a scene file).
  write(dir.path / "scene.png", "model = \"undamped\"\nT = 1\n");
  const auto scene = run_vibra("render " + (dir / "scene.png") + " --size 160x90 --at 0.5 -q -o " + (dir / "scene.png"));
  check_refusal(scene, "scene.png");
  CHECK(read_file(dir.path / "scene.png") == "model = \"undamped\"\nT = 1\n");
}

TEST_CASE("an empty output path is an error, not the default name", "[output][paths][cli]") {
  ScratchDirectory dir;
  for (const char* args : {"render -o ''", "render --output ''", "solve undamped -o ''", "plot undamped -o ''",
                           "analyze convergence undamped --levels 3 -o ''", "concat a.mp4 -o ''"}) {
    INFO("vibra " << args);
    check_refusal(run_in(dir, args), "empty");
    CHECK(dir.empty());
  }
}
