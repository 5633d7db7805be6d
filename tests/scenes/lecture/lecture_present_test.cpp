// vibra lecture --present and --shots-dir: the storyboard's then and intro keys, each shot's own video and first frame
// (frame for frame the one-file video's), the presentation page's data, index.md and beamer.tex, refusals.
// tests/browser/check_presentation.py drives the page in Chromium.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scenes/lecture/storyboard.hpp"

using vibra::test::check_refusal;
using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::shell;
using vibra::test::write_file;
namespace fs = std::filesystem;
using vibra::scenes::ShotEnd;

namespace {
// The storyboard the browser test uses too: 10 fps, shots of 10, 20, 30 and 5
// frames, 65 in all; a card that holds (the default), a spring that goes on
// by itself, one that plays 1 s once and then loops, a card that loops whole.
const fs::path kStoryFile = fs::path(VIBRA_SOURCE_DIR) / "tests/browser/present_story.toml";

const std::vector<std::string> kStems = {"01-springs", "02-spring", "03-spring", "04-the-end"};
const std::vector<long long> kFrames = {10, 20, 30, 5};

/// The MD5 of every decoded frame of a video's picture, in order.
std::vector<std::string> frame_hashes(const fs::path& video) {
  const std::string text = shell("ffmpeg -v error -i '" + video.string() +
                                 "' -map 0:v -f framemd5 - | grep -v '^#' | awk -F, '{print $6}'");
  std::vector<std::string> hashes;
  for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1)
    hashes.push_back(text.substr(at, end - at));
  return hashes;
}

/// The names in a folder, sorted.
std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// The shots' files in a folder as --present and --shots-dir name them, with `more`, sorted.
std::vector<std::string> shot_names(std::vector<std::string> more) {
  for (const std::string& stem : kStems) more.insert(more.end(), {stem + ".mp4", stem + ".png"});
  more.push_back(".vibra-manifest");
  std::sort(more.begin(), more.end());
  return more;
}

/// Each shot's video holds its frames, and the frames
/// of all of them in order are the one-file video's, decoded to the same bytes.
void check_frame_for_frame(const fs::path& folder, const fs::path& whole) {
  std::vector<std::string> joined;
  for (std::size_t i = 0; i < kStems.size(); ++i) {
    const fs::path video = folder / (kStems[i] + ".mp4");
    INFO(video);
    const std::vector<std::string> hashes = frame_hashes(video);
    CHECK(hashes.size() == std::size_t(kFrames[i]));
    joined.insert(joined.end(), hashes.begin(), hashes.end());
  }
  CHECK(joined.size() == 65);
  CHECK(joined == frame_hashes(whole));
  // Each shot was coded on its own from a keyframe: the joined video has one at each shot's start, and only there.
  CHECK(shell("ffprobe -v error -select_streams v:0 -show_entries frame=key_frame,pts_time -of csv=p=0 '" +
              whole.string() + "' | awk -F, '$1 == 1 {print $2}'") == "0.000000\n1.000000\n3.000000\n6.000000\n");
}

/// A shot's PNG is its first frame as drawn: the video's first frame, coded, is near it (PSNR in dB).
double first_frame_psnr(const fs::path& png, const fs::path& video) {
  const std::string out = shell("ffmpeg -v info -i '" + png.string() + "' -i '" + video.string() +
                                "' -lavfi '[0:v][1:v]scale2ref[a][b];[a][b]psnr' -frames:v 1 -f null - 2>&1 | "
                                "grep -o 'average:[0-9.inf]*' | cut -d: -f2");
  return out.empty() ? 0 : std::stod(out);
}
}  // namespace

TEST_CASE("storyboard then and intro: cards and scenes hold unless told, an intro loops the rest", "[lecture][present]") {
  const vibra::scenes::Storyboard board = vibra::scenes::parse_storyboard(read_file(kStoryFile), "story.toml");
  REQUIRE(board.shots.size() == 4);
  CHECK(board.shots[0].ending.then == ShotEnd::hold);
  CHECK(board.shots[1].ending.then == ShotEnd::next);
  CHECK(board.shots[2].ending.then == ShotEnd::loop);
  CHECK(board.shots[2].ending.intro == 1);
  CHECK(board.shots[3].ending.then == ShotEnd::loop);
  CHECK(board.shots[3].ending.intro == 0);
  const auto scene = vibra::scenes::parse_storyboard("[[shot]]\nscene = \"spring\"\n", "s.toml");
  CHECK(scene.shots[0].ending.then == ShotEnd::hold);
}

TEST_CASE("bad then and intro keys: one line at their line, exit 2, nothing written", "[lecture][present]") {
  struct Case {
    std::string story, expected;
  };
  const std::string head = "size = \"320x180\"\nfps = 10\n[[shot]]\n";
  const std::vector<Case> cases = {
      {head + "card = \"A\"\nthen = \"stay\"\n", "story.toml:5: shot 1, then: 'stay' is not an ending: must be \"hold\""},
      {head + "card = \"A\"\nthen = 3\n", "story.toml:5: shot 1, then: must be \"hold\" (stay on the last frame)"},
      {head + "card = \"A\"\nintro = -1\n", "story.toml:5: shot 1, intro: must be the seconds of video played once"},
      {head + "card = \"A\"\nintro = 1\nthen = \"hold\"\n",
       "story.toml:5: shot 1, intro: is played once before a loop, but then = \"hold\""},
      {head + "card = \"A\"\nseconds = 2\nintro = 2\n",
       "story.toml:6: shot 1, intro: = 2 leaves nothing to loop in a shot of 2 s"},
      {head + "scene = \"spring\"\nset = { T = 2 }\nthen = \"next\"\nintro = 1\n",
       "story.toml:7: shot 1, intro: is played once before a loop, but then = \"next\""},
      // Without seconds, the frames come from the pacing: a period in 2 s, so T = 2 is 7 frames at 10 fps.
      {head + "scene = \"spring\"\nset = { T = 2 }\nintro = 5\n",
       "story.toml: shot 1: intro = 5 leaves nothing to loop in a shot of 0.7 s"},
      {head + "scene = \"spring\"\nthenn = \"loop\"\n", "story.toml:5: shot 1, thenn: unknown key 'thenn'"},
  };
  for (const Case& c : cases) {
    SECTION(c.expected) {
      ScratchDirectory stories;
      write_file(stories / "story.toml", c.story);
      check_refused("lecture " + (stories / "story.toml") + " --present -o OUT.html", c.expected);
    }
  }
  ScratchDirectory stories;
  fs::copy_file(kStoryFile, stories.path / "story.toml");
  const std::string story = "lecture " + (stories / "story.toml");
  check_refused(story + " --present -o OUT.mp4", "--present makes a page of slides: give -o TALK.html");
  check_refused(story + " --present --shot 2 -o OUT.html", "--present takes every shot: drop --shot");
  check_refused(story + " --shots-dir OUT --segment 0/2 -o OUT.mp4", "--shots-dir takes every shot: drop --segment");
  check_refused(story + " --shots-dir . -o OUT.mp4", "--shots-dir .: name a folder of its own");
  check_refused(story + " --shots-dir OUT_files -o OUT.html", "is the page's own folder: choose another");
}

TEST_CASE("lecture --present: a video and a first frame a shot, frame for frame the one-file video's",
          "[lecture][present][video]") {
  ScratchDirectory dir;
  fs::copy_file(kStoryFile, dir.path / "story.toml");
  const auto r = run_vibra("lecture story.toml -o talk.html --present", "cd " + dir.path.string() + " && ");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::EndsWith("vibra: wrote talk.html and talk_files (4 slides, 65 frames, 6.5 s)\n"));
  const fs::path files = dir.path / "talk_files";
  CHECK(names_in(files) == shot_names({"talk.mp4", "talk.vtt"}));
  check_frame_for_frame(files, files / "talk.mp4");
  for (const std::string& stem : kStems) {
    INFO(stem);
    CHECK(vibra::test::png_size(files / (stem + ".png")) == std::pair<int, int>{320, 180});
    CHECK(first_frame_psnr(files / (stem + ".png"), files / (stem + ".mp4")) > 30);
  }
  CHECK(first_frame_psnr(files / "01-springs.png", files / "02-spring.mp4") < 20);  // another shot's is far

  const std::string html = read_file(dir / "talk.html");
  CHECK_THAT(html, Catch::Contains("poster=\"talk_files/02-spring.png\" data-src=\"talk_files/02-spring.mp4\""));
  vibra::test::check_in_order(html, {"\"then\":\"hold\"", "\"then\":\"next\"", "\"then\":\"loop\",\"intro\":1,",
                                     "\"then\":\"loop\",\"intro\":0,"});
  CHECK_THAT(html, Catch::Contains("\"notes\":[\"t = 0.5 to 1.5: halfway\"],\"clock\":{\"interval\":"));
  CHECK_THAT(html, Catch::Contains("<a href=\"talk_files/talk.mp4\" download>The whole lecture (MP4)</a>"));
  CHECK(html.find("http://") == std::string::npos);  // nothing from the network
  CHECK(html.find("https://") == std::string::npos);
}

TEST_CASE("lecture --shots-dir: each shot as its own video and PNG, index.md and beamer.tex, vibra's own folder",
          "[lecture][present][video]") {
  ScratchDirectory dir;
  fs::copy_file(kStoryFile, dir.path / "story.toml");
  const std::string in_dir = "cd " + dir.path.string() + " && ";
  REQUIRE(run_vibra("lecture story.toml -q -o lecture.mp4 --shots-dir shots/", in_dir).exit_code == 0);
  CHECK(names_in(dir.path / "shots") == shot_names({"beamer.tex", "index.md"}));
  check_frame_for_frame(dir.path / "shots", dir.path / "lecture.mp4");
  const std::string index = read_file(dir / "shots/index.md");
  CHECK_THAT(index, Catch::StartsWith("# Springs: the shots\n"));
  vibra::test::check_in_order(index, {"| 1 | Springs | [01-springs.mp4](01-springs.mp4) | ![shot 1](01-springs.png) | 1 | hold |\n",
                                      "| 2 | spring | [02-spring.mp4](02-spring.mp4) | ![shot 2](02-spring.png) | 2 | next |\n",
                                      "| 3 | spring | [03-spring.mp4](03-spring.mp4) | ![shot 3](03-spring.png) | 3 | loop |\n",
                                      "| 4 | The end | [04-the-end.mp4](04-the-end.mp4) | ![shot 4](04-the-end.png) | 0.5 | loop |\n"});
  const std::string beamer = read_file(dir / "shots/beamer.tex");
  CHECK_THAT(beamer, Catch::Contains("\\begin{frame}{The end}\n  \\centering\n  \\movie{\\includegraphics"
                                     "[width=0.9\\textwidth]{04-the-end.png}}{04-the-end.mp4}\n\\end{frame}\n"));

  // Its own folder is replaced; a folder of the user's is not, and then nothing is written.
  REQUIRE(run_vibra("lecture story.toml -q -o lecture.mp4 --shots-dir shots", in_dir).exit_code == 0);
  fs::create_directory(dir.path / "mine");
  write_file(dir / "mine/talk.odp", "my slides");
  const auto r = run_vibra("lecture story.toml -q -o other.mp4 --shots-dir mine", in_dir);
  CHECK(r.exit_code != 0);
  CHECK_THAT(r.err, Catch::Contains("'mine' exists and was not written by vibra"));
  CHECK(names_in(dir.path / "mine") == std::vector<std::string>{"talk.odp"});
  CHECK(read_file(dir / "mine/talk.odp") == "my slides");
  CHECK_FALSE(fs::exists(dir.path / "other.mp4"));
}

TEST_CASE("one run with --present and --shots-dir: the shots rendered once, the same files in both folders",
          "[lecture][present][video]") {
  ScratchDirectory dir;
  fs::copy_file(kStoryFile, dir.path / "story.toml");
  REQUIRE(run_vibra("lecture story.toml -q -o talk.html --present --shots-dir shots", "cd " + dir.path.string() + " && ")
              .exit_code == 0);
  for (const std::string& stem : kStems)
    for (const char* ext : {".mp4", ".png"}) {
      INFO(stem << ext);
      CHECK(read_file(dir.path / "shots" / (stem + ext)) == read_file(dir.path / "talk_files" / (stem + ext)));
    }
  check_frame_for_frame(dir.path / "shots", dir.path / "talk_files" / "talk.mp4");
}
