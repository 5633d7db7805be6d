// What a page, a video's metadata and a subtitle file record of how they were made: "vibra", never the binary's path, and paths relative to where it ran, never the folders above (core/input/shown_path.hpp).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "cli_support.hpp"
#include "core/input/shown_path.hpp"

using vibra::shown_argument;
using vibra::shown_path;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {
/// Runs the test body in `dir`, and goes back after.
struct WorkingDirectory {
  fs::path before = fs::current_path();
  explicit WorkingDirectory(const fs::path& dir) { fs::current_path(dir); }
  ~WorkingDirectory() { fs::current_path(before); }
};

void write(const fs::path& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f);
  REQUIRE(std::fwrite(text.data(), 1, text.size(), f) == text.size());
  REQUIRE(std::fclose(f) == 0);
}

/// `vibra ARGS` from the folder `dir`, by the executable's absolute path.
vibra::test::CommandResult run_in(const fs::path& dir, const std::string& args) {
  return run_vibra(args, "cd '" + dir.string() + "' && ");
}

const char* const kStory = "title = \"Origins\"\nsize = \"160x90\"\nfps = 10\n[[shot]]\ncard = \"Origins\"\nseconds = 0.3\n";
}  // namespace

TEST_CASE("shown_path: relative to the working directory, a file name outside its tree, devices as given", "[provenance]") {
  ScratchDirectory dir;
  const fs::path top = fs::canonical(dir.path);
  fs::create_directories(top / "out");
  WorkingDirectory here(top / "out");
  CHECK(shown_path((top / "out" / "a" / "story.toml").string()) == "a/story.toml");
  CHECK(shown_path((top / "story.toml").string()) == "../story.toml");
  CHECK(shown_path("x/../story.toml") == "x/../story.toml");  // relative: as given
  CHECK(shown_path("/dev/stdout") == "/dev/stdout");
  // A tree that shares no folder with the working directory shows no folder at all.
  const fs::path elsewhere = top.begin()->string() + (*std::next(top.begin()) == "usr" ? "opt" : "usr");
  CHECK(shown_path((elsewhere / "home" / "alice" / "road.csv").string()) == "road.csv");
  CHECK(shown_argument("road=" + (top / "road.csv").string()) == "road=../road.csv");
  CHECK(shown_argument("--output=" + (top / "out" / "x.mp4").string()) == "--output=x.mp4");
  CHECK(shown_argument("Theta=40") == "Theta=40");
}

TEST_CASE("a page's Made by says vibra and the paths as relative to where it ran", "[provenance][page]") {
  ScratchDirectory dir;
  const auto r = run_in(dir.path, "plot undamped --set T=1 -q -o " + (dir / "page.html"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(read_file(dir / "page.html"),
             Catch::Contains("Made by <code id=\"command\">vibra plot undamped --set T=1 -q -o page.html</code>"));
}

TEST_CASE("a lecture's video comment, subtitles and page name the storyboard relative to where it ran", "[provenance][lecture]") {
  ScratchDirectory dir;
  write(dir.path / "story.toml", kStory);
  fs::create_directories(dir.path / "out");
  const std::string story = (fs::canonical(dir.path) / "story.toml").string();
  const auto video = run_in(dir.path / "out", "lecture " + story + " -q -o talk.mp4");
  INFO(video.err);
  REQUIRE(video.exit_code == 0);
  CHECK_THAT(read_file(dir.path / "out" / "talk.vtt"), Catch::StartsWith("WEBVTT\n\nNOTE written by vibra lecture ../story.toml\n"));
  CHECK(vibra::test::shell("ffprobe -v error -show_entries format_tags=comment -of default=nw=1 '" +
                           (dir.path / "out" / "talk.mp4").string() + "'") == "TAG:comment=vibra lecture ../story.toml\n");
  const auto page = run_in(dir.path / "out", "lecture " + story + " -q -o talk.html");
  REQUIRE(page.exit_code == 0);
  const std::string html = read_file(dir.path / "out" / "talk.html");
  CHECK_THAT(html, Catch::Contains("Made by <code id=\"command\">vibra lecture ../story.toml -q -o talk.html</code>"));
  CHECK(html.find(dir.path.string()) == std::string::npos);  // no folder above where it ran
}
