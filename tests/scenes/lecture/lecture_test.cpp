// vibra lecture: a storyboard's shots in one video, a chapter per shot,
// subtitles from cards and notes (a track in the video and OUT.vtt beside
// it), --shot, --segment per shot, the page, and bad storyboards refused
// before anything is written.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "render/output/output_error.hpp"
#include "render/output/place_together.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::check_refusal;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::shell;
namespace fs = std::filesystem;

namespace {
void write(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
}

// 10 fps: a shot of S seconds is round(10 S) frames. The card: 10 frames.
// The spring: 31 frames, the last at 3.0 s showing T = 2, so with its pause
// of 1 s it runs at speed 1 (frame k shows t = k/10 up to 1, then t = 1 held
// for frames 10..19, then t = k/10 - 1). The last card: 5. 46 frames, 4.6 s.
// "held here" is shown by frames, so it is drawn in the picture and is no
// subtitle; no frame shows a time in [1.02, 1.08] (frames show 1.0 and 1.1),
// so "between frames" is a subtitle from t = 1.02 (video 1 + 2.02 s) for the
// shortest note cue, 2 s, cut at the shot's end (4.1 s).
const std::string kStory = R"(title = "Springs"
size = "320x180"
fps = 10
[[shot]]
card = "Springs"
equation = "u'' + \\omega^2 u = 0"
seconds = 1
[[shot]]
scene = "spring"
set = { T = 2, dt = 0.05 }
seconds = 3.1
pause = [{ at = 1, seconds = 1 }]
notes = ["0.5-1.5: held here", "1.02-1.08: between frames"]
[[shot]]
card = "The end"
seconds = 0.5
)";

// Run from the storyboard's folder, the note names it as given: story.toml.
const std::string kCues = "WEBVTT\n\nNOTE written by vibra lecture story.toml\n\n"
                          "1\n00:00:00.000 --> 00:00:01.000\nSprings\nu\u2033 + \u03c9\u00b2u = 0\n\n"
                          "2\n00:00:03.020 --> 00:00:04.100\nbetween frames\n\n"
                          "3\n00:00:04.100 --> 00:00:04.600\nThe end\n";

const std::string kChapters = "-show_entries chapter=start_time,end_time:chapter_tags=title";

std::string probe(const std::string& file, const std::string& what) {
  return shell("ffprobe -v error " + what + " -of default=nw=1 '" + file + "'");
}

/// The times of the video's keyframes, one a line ("0.000000\n1.000000\n...").
std::string keyframe_times(const std::string& file) {
  return shell("ffprobe -v error -select_streams v:0 -show_entries frame=key_frame,pts_time -of csv=p=0 '" + file +
               "' | awk -F, '$1 == 1 {print $2}'");
}
}  // namespace

TEST_CASE("a lecture: a chapter per shot, subtitles from cards and notes, the frames of every shot",
          "[lecture][video]") {
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  for (const char* ext : {".mp4", ".webm"}) {
    SECTION(ext) {
      const std::string out = dir / (std::string("lecture") + ext);
      const auto r = run_vibra("lecture story.toml -q -o " + out, "cd " + dir.path.string() + " && ");
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      const std::string chapters = probe(out, kChapters);
      INFO(chapters);
      // Three chapters: frames [0, 10), [10, 41), [41, 46) at 10 fps.
      CHECK_THAT(chapters, Catch::Contains("start_time=0.000000\nend_time=1.000000\nTAG:title=Springs"));
      CHECK_THAT(chapters, Catch::Contains("start_time=1.000000\nend_time=4.100000\nTAG:title=spring"));
      CHECK_THAT(chapters, Catch::Contains("start_time=4.100000\nend_time=4.600000\nTAG:title=The end"));
      const std::string streams = probe(out, "-show_entries stream=codec_type,codec_name");
      CHECK_THAT(streams, Catch::Contains(ext == std::string(".mp4") ? "codec_name=mov_text" : "codec_name=webvtt"));
      CHECK_THAT(streams, Catch::Contains(ext == std::string(".mp4") ? "codec_name=h264" : "codec_name=vp9"));
      CHECK(probe(out, "-count_frames -select_streams v:0 -show_entries stream=nb_read_frames") == "nb_read_frames=46\n");
      // The subtitle track's cues, as ffmpeg reads them back.
      const std::string srt = shell("ffmpeg -v error -i '" + out + "' -map 0:s:0 -f srt -");
      CHECK_THAT(srt, Catch::Contains("00:00:03,020 --> 00:00:04,100\nbetween frames"));
      CHECK(srt.find("held here") == std::string::npos);  // drawn in the picture: not shown twice
      CHECK_THAT(srt, Catch::Contains("00:00:04,100 --> 00:00:04,600\nThe end"));
      CHECK(read_file(dir / "lecture.vtt") == kCues);
      // Every shot starts with a keyframe, so that a chapter's first frame
      // needs nothing before it (the shots share one encoder).
      const std::string keyframes = keyframe_times(out);
      INFO(keyframes);
      for (const char* start : {"0.000000\n", "\n1.000000\n", "\n4.100000\n"})
        CHECK_THAT(keyframes, Catch::Contains(start));
    }
  }
}

TEST_CASE("lecture --shot N renders one shot alone with its chapter and its subtitles", "[lecture][video]") {
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --shot 2 -q -o " + (dir / "two.mp4")).exit_code == 0);
  CHECK(probe(dir / "two.mp4", "-count_frames -select_streams v:0 -show_entries stream=nb_read_frames") ==
        "nb_read_frames=31\n");
  CHECK_THAT(probe(dir / "two.mp4", kChapters), Catch::Contains("end_time=3.100000\nTAG:title=spring"));
  CHECK_THAT(read_file(dir / "two.vtt"), Catch::Contains("1\n00:00:02.020 --> 00:00:03.100\nbetween frames\n"));
  CHECK(read_file(dir / "two.vtt").find("held here") == std::string::npos);
  check_refused("lecture " + (dir / "story.toml") + " --shot 4 -o OUT.mp4", "has shots 1..3");
}

TEST_CASE("lecture --segment renders whole shots into shot files that the join reuses", "[lecture][video]") {
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  const std::string out = dir / "lecture.mp4";
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --segment 0/2 -q -o " + out).exit_code == 0);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --segment 1/2 -q -o " + out).exit_code == 0);
  for (const char* name : {"lecture.shot-1.mp4", "lecture.shot-2.mp4", "lecture.shot-3.mp4"})
    CHECK(fs::is_regular_file(dir / name));
  CHECK_FALSE(fs::exists(out));
  const std::string shot2 = read_file(dir / "lecture.shot-2.mp4");
  const auto joined = run_vibra("lecture story.toml -o " + out, "cd " + dir.path.string() + " && ");
  INFO(joined.err);
  REQUIRE(joined.exit_code == 0);
  CHECK(joined.err.find("shot 2/3") == std::string::npos);  // not rendered again: no progress of it
  CHECK(read_file(dir / "lecture.shot-2.mp4") == shot2);
  CHECK(probe(out, "-count_frames -select_streams v:0 -show_entries stream=nb_read_frames") == "nb_read_frames=46\n");
  CHECK(read_file(dir / "lecture.vtt") == kCues);
  CHECK(keyframe_times(out) == "0.000000\n1.000000\n4.100000\n");  // each shot file's first frame
  // A changed shot is not taken from an old shot file.
  std::string changed = kStory;
  changed.replace(changed.find("\"The end\""), 9, "\"Fin\"");
  write(dir / "story.toml", changed);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " -q -o " + out).exit_code == 0);
  CHECK_THAT(probe(out, kChapters), Catch::Contains("TAG:title=Fin"));
  // Nor is a shot rendered at another size, whatever else the shot shares
  // (the size comes first in what the shot file's tag is made from).
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --segment 0/2 -q -o " + out).exit_code == 0);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --segment 1/2 -q -o " + out).exit_code == 0);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " --size 160x90 -q -o " + out).exit_code == 0);
  CHECK(probe(out, "-select_streams v:0 -show_entries stream=width,height") == "width=160\nheight=90\n");
}

TEST_CASE("a lecture page: the video, its chapters as links, the subtitles as a track", "[lecture][page]") {
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  REQUIRE(run_vibra("lecture story.toml -q -o talk.html", "cd " + dir.path.string() + " && ").exit_code == 0);
  const std::string html = read_file(dir / "talk.html");
  CHECK_THAT(html, Catch::Contains("<track kind=\"subtitles\" label=\"Notes\" srclang=\"en\" src=\"talk_files/talk.vtt\""));
  CHECK_THAT(html, Catch::Contains("<ol id=\"chapters\">"));
  CHECK_THAT(html, Catch::Contains("data-start=\"1\">spring</a>"));
  CHECK_THAT(html, Catch::Contains("data-start=\"4.0999999999999996\">The end</a>"));
  for (const char* name : {"talk.mp4", "talk.webm", "talk.vtt"}) CHECK(fs::is_regular_file(dir.path / "talk_files" / name));
  CHECK(read_file(dir.path / "talk_files" / "talk.vtt") == kCues);
  CHECK_THAT(probe(dir.path / "talk_files" / "talk.webm", kChapters), Catch::Contains("TAG:title=The end"));
}

TEST_CASE("bad storyboards: one line naming the file, shot and key, exit 2, nothing written", "[lecture]") {
  struct Case {
    std::string story, expected;
  };
  const std::string head = "size = \"320x180\"\nfps = 10\n";
  const std::vector<Case> cases = {
      {head + "[[shot]]\ncard = \"A\"\ncolour = 3\n", "shot 1, colour: is not a key of a title card"},
      {head + "[[shot]]\nscene = \"pendulum\"\nThetaa = 40\n", "shot 1, Thetaa: unknown key 'Thetaa' (did you mean 'Theta'?)"},
      {head + "[[shot]]\ncard = \"A\"\n[[shot]]\nscene = \"pendullum\"\n", "shot 2, scene: no scene 'pendullum'"},
      {head + "[[shot]]\nscene = \"pendulum\"\nset = { alpha = \"x\" }\n", "shot 1, alpha"},
      {head + "[[shot]]\nscene = \"pendulum\"\nseconds = -1\n", "shot 1, seconds: must be a number of seconds above 0"},
      {head + "[[shot]]\nscene = \"pendulum\"\nseconds = 2\nspeed = 1\n", "shot 1, seconds: and speed both set"},
      {head + "[[shot]]\nscene = \"pendulum\"\nnotes = [\"later\"]\n", "shot 1, notes: note 'later' does not start with a time range"},
      {head + "[[shot]]\nscene = \"spring\"\nset = { T = 2 }\nnotes = [\"1-3: late\"]\n", "shot 1: note 1-3 reaches past the run's end"},
      {head + "[[shot]]\nscene = \"spring\"\nset = { T = 2 }\npause = [{ at = 5, seconds = 1 }]\n", "shot 1: pause 5:1 lies past the run's end"},
      {head + "[[shot]]\nscene = \"spring\"\nslow = [\"2-4:0\"]\n", "shot 1, slow: slow motion '2-4:0': the factor must be above 0"},
      {head + "[[shot]]\nscene = \"spring\"\npause = [{ at = 1 }]\n", "shot 1, pause: each pause is"},
      {head + "[[shot]]\nscene = \"spring\"\nfps = 25\n", "shot 1, fps: is the lecture's, not a shot's"},
      {head + "[[shot]]\nscene = \"spring\"\nset = { T = 2 }\nseconds = 2\npause = [\"1:3\"]\n", "shot 1: seconds = 2 leaves no time"},
      {head + "[[shot]]\nequation = \"x\"\nscene = \"spring\"\n", "shot 1, scene: is not a key of a title card"},
      {head + "[[shot]]\ncard = \"A\"\n[[shot]]\nset = { T = 2 }\n", "shot 2, scene: is missing"},
      {head + "colour = 1\n[[shot]]\ncard = \"A\"\n", "story.toml:3: colour: is not a key of a storyboard"},
      {head, "shot: no shots"},
      {"size = \"320x\"\n[[shot]]\ncard = \"A\"\n", "story.toml:1: size: size '320x' is not WxH"},
      {"fps = 0\n[[shot]]\ncard = \"A\"\n", "story.toml:1: fps: must be a whole number"},
      {"fps = 29.97\n[[shot]]\ncard = \"A\"\n", "story.toml:1: fps: must be a whole number of frames per second, 1..240"},
      {"fps = 241\n[[shot]]\ncard = \"A\"\n", "story.toml:1: fps: must be a whole number of frames per second, 1..240"},
      {head + "[[shot]]\ncard = \"A\"\nseconds = \"long\"\n", "shot 1, seconds: must be a number"},
      {head + "[[shot\n", "story.toml:3:"},
      // Cards are typeset: bad LaTeX is refused at its line, before any work.
      {head + "[[shot]]\ncard = \"Drag $\\\\alpha\"\n", "story.toml:4: shot 1, card: text 'Drag $\\alpha': a $ opens math that is never closed"},
      {head + "[[shot]]\nequation = \"\\\\frac{a}{b\"\n", "story.toml:4: shot 1, equation: formula '\\frac{a}{b': a { is never closed"},
      {"title = \"$x^}$\"\n[[shot]]\ncard = \"A\"\n", "story.toml:1: title: "},
      {head + "shot = 3\n", "shot: no shots"},
  };
  for (const Case& c : cases) {
    SECTION(c.expected) {
      ScratchDirectory stories;
      write(stories / "story.toml", c.story);
      check_refused("lecture " + (stories / "story.toml") + " -o OUT.mp4", c.expected);
    }
  }
  check_refused("lecture /nonexistent/story.toml -o OUT.mp4", "no storyboard");
  ScratchDirectory stories;
  write(stories / "story.toml", kStory);
  check_refused("lecture " + (stories / "story.toml") + " -o OUT.gif", "a lecture is written as .mp4, .webm or .html");
  check_refused("lecture " + (stories / "story.toml") + " --segment 0/2 -o OUT.html", "--segment renders shot files");
}

TEST_CASE("subtitles beside a video replace only vibra's own", "[lecture]") {
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  write(dir / "lecture.vtt", "WEBVTT\n\nmy own notes\n");
  const auto r = run_vibra("lecture " + (dir / "story.toml") + " -q -o " + (dir / "lecture.mp4"));
  check_refusal(r, "was not written by vibra lecture");
  CHECK_FALSE(fs::exists(dir / "lecture.mp4"));
  CHECK(read_file(dir / "lecture.vtt") == "WEBVTT\n\nmy own notes\n");
}

TEST_CASE("a shot of S seconds is round(S * fps) frames: the video's frames and chapters add up", "[lecture][video]") {
  // 10 fps: 0.74 s -> 7 frames, 2.42 s -> 24, 1.53 s -> 15 (one more each
  // when a shot counted its end frame beyond S * fps): 46 frames.
  ScratchDirectory dir;
  write(dir / "story.toml", R"(size = "160x90"
fps = 10
[[shot]]
card = "A"
seconds = 0.74
[[shot]]
scene = "spring"
set = { T = 2, dt = 0.01 }
seconds = 2.42
slow = ["0.5-1:3"]
[[shot]]
scene = "spring"
set = { T = 2, dt = 0.01 }
seconds = 1.53
pause = [{ at = 2, seconds = 0.3 }]
)");
  const std::string out = dir / "lecture.mp4";
  const auto r = run_vibra("lecture " + (dir / "story.toml") + " -q -o " + out);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const long long frames[] = {7, 24, 15};
  CHECK(probe(out, "-count_frames -select_streams v:0 -show_entries stream=nb_read_frames") == "nb_read_frames=46\n");
  std::string expected;
  long long start = 0;
  char line[96];
  for (long long n : frames) {
    std::snprintf(line, sizeof line, "start_time=%.6f\nend_time=%.6f\n", start / 10.0, (start + n) / 10.0);
    expected += line;
    start += n;
  }
  CHECK(probe(out, "-show_entries chapter=start_time,end_time") == expected);
}

TEST_CASE("a note is shown once: drawn when a frame shows its time, else a subtitle", "[lecture]") {
  // A scene file's notes and the storyboard's alike. At 10 fps and speed 1
  // (T = 2 in 2.1 s: 21 frames, t = k / 10) frames show t = 0.5 .. 1.5 but
  // none of [1.02, 1.08] or [1.73, 1.76].
  ScratchDirectory dir;
  write(dir / "spring_notes.toml", "model = \"vibration\"\ndiagram = \"oscillator\"\nT = 2\ndt = 0.01\nnotes = [\"0.5-1.5: drawn\", \"1.73-1.76: in between\"]\n");
  write(dir / "story.toml", R"(size = "160x90"
fps = 10
[[shot]]
scene = "spring_notes.toml"
seconds = 2.1
notes = ["0.2-0.4: also drawn", "1.02-1.08: a subtitle"]
)");
  const auto r = run_vibra("lecture story.toml -q -o n.mp4", "cd " + dir.path.string() + " && ");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  // 1.02 s for 2 s, cut where the next starts (1.73 s); 1.73 s to the shot's end, 2.1 s.
  CHECK(read_file(dir / "n.vtt") == "WEBVTT\n\nNOTE written by vibra lecture story.toml\n\n"
                                    "1\n00:00:01.020 --> 00:00:01.730\na subtitle\n\n"
                                    "2\n00:00:01.730 --> 00:00:02.100\nin between\n");
}

TEST_CASE("outputs are placed together or not at all: a failed placement puts the earlier ones back",
          "[lecture][output]") {
  using vibra::render::Placement;
  ScratchDirectory dir;
  write(dir / "out.mp4", "earlier video");
  fs::create_directories(dir.path / "out.vtt" / "inside");  // a folder where the subtitles go
  write(dir / ".new.mp4", "new video");
  write(dir / ".new.vtt", "new subtitles");
  CHECK_THROWS_AS(vibra::render::place_together({{dir.path / ".new.mp4", dir.path / "out.mp4"},
                                                 {dir.path / ".new.vtt", dir.path / "out.vtt"}}),
                  vibra::render::OutputError);
  CHECK(read_file(dir / "out.mp4") == "earlier video");
  CHECK(fs::is_directory(dir.path / "out.vtt" / "inside"));
  CHECK(read_file(dir / ".new.mp4") == "new video");  // the temporaries still hold the new, for their owners
  // Placed: the earlier outputs wait under the temporary names, for their owners to remove.
  fs::remove_all(dir.path / "out.vtt");
  write(dir / "out.vtt", "earlier subtitles");
  vibra::render::place_together({{dir.path / ".new.mp4", dir.path / "out.mp4"}, {dir.path / ".new.vtt", dir.path / "out.vtt"}});
  CHECK(read_file(dir / "out.mp4") == "new video");
  CHECK(read_file(dir / "out.vtt") == "new subtitles");
  CHECK(read_file(dir / ".new.mp4") == "earlier video");
}

TEST_CASE("a lecture whose subtitles cannot be placed leaves the earlier video and subtitles as they were",
          "[lecture][output]") {
  // The subtitles' path is a mount point (a file bound over itself): it passes
  // every check before the work, and only the final rename fails (EBUSY).
  if (shell("unshare -m true 2>/dev/null && echo yes") != "yes\n") {
    WARN("skipped: no mount namespace here (unshare -m needs CAP_SYS_ADMIN)");
    return;
  }
  ScratchDirectory dir;
  write(dir / "story.toml", kStory);
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " -q -o " + (dir / "lecture.mp4")).exit_code == 0);
  const std::string video = read_file(dir / "lecture.mp4"), subtitles = read_file(dir / "lecture.vtt");
  std::string changed = kStory;
  changed.replace(changed.find("\"The end\""), 9, "\"Fin\"");
  write(dir / "story.toml", changed);
  const std::string vtt = dir / "lecture.vtt";
  const auto r = run_vibra("lecture " + (dir / "story.toml") + " -q -o " + (dir / "lecture.mp4"),
                           "unshare -m sh -c 'mount --bind \"" + vtt + "\" \"" + vtt + "\" && exec \"$0\" \"$@\"' ");
  check_refusal(r, "lecture.vtt");
  CHECK(read_file(dir / "lecture.mp4") == video);
  CHECK(read_file(dir / "lecture.vtt") == subtitles);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir.path)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"lecture.mp4", "lecture.vtt", "story.toml"});
}
