// Segment renders through the real executable: frames byte-identical to the
// one-pass render's, lossless segments joined by `vibra concat` decoding to
// exactly the one-pass frames, lossy ones to the same count and duration,
// restarts with --skip-existing, and every refusal on one line.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::check_refusal;
using vibra::test::run_vibra;
using vibra::test::shell;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {
/// Every file of a directory by name, with its bytes.
std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".png") files[entry.path().filename().string()] = read_file(entry.path());
  return files;
}

/// Decoded frames with their timestamps, one MD5 per frame (ffmpeg's framemd5).
std::string frame_hashes(const std::string& video) {
  return shell("ffmpeg -v error -i '" + video + "' -f framemd5 - | grep -v '^#'");
}

std::string probe(const std::string& video, const std::string& entries) {
  return shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries " + entries + " -of csv=p=0 '" + video +
               "'");
}

void render_segments(const std::string& args, int count, const std::string& output) {
  for (int k = 0; k < count; ++k) {
    const auto r = run_vibra("render" + args + " --segment " + std::to_string(k) + "/" + std::to_string(count) + " -o " + output);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
}

std::string parts(const ScratchDirectory& dir, const std::string& stem, int count, const std::string& ext) {
  std::string list;
  for (int k = 0; k < count; ++k) {
    list += ' ';
    list += dir / (stem + ".seg-" + std::to_string(k) + "-of-" + std::to_string(count) + ext);
  }
  return list;
}

const std::string kSmall = " --size 320x180 --fps 10 --set periods=1 -q";  // 21 frames
}  // namespace

TEST_CASE("PNG segments are the one-pass render's frames, byte for byte, in one directory", "[render][segment]") {
  // The whole-run plots grow frame by frame, and a moving window is fed by
  // every solver step: both must be where the one-pass render has them. A
  // trail's older part is pasted from a layer and labels from kept images:
  // a frame's pixels must not depend on the frames drawn before it either.
  for (const std::string args : {" --layout fbd+plot", " --layout plot --window 0.3periods",
                                 " --layout fbd --set alpha=0.3", " orbit", " elastic_pendulum", " spring_dashpot"}) {
    INFO(args);
    ScratchDirectory whole, split;
    REQUIRE(run_vibra("render" + args + kSmall + " -o " + (whole / "f_%03d.png")).exit_code == 0);
    render_segments(args + kSmall, 3, split / "f_%03d.png");
    const auto expected = files_of(whole.path), got = files_of(split.path);
    REQUIRE(expected.size() >= 10);
    CHECK(got.size() == expected.size());
    for (const auto& [name, bytes] : expected) {
      INFO(name);
      CHECK((got.count(name) && got.at(name) == bytes));
    }
  }
}

TEST_CASE("lossless segments joined decode to exactly the one-pass frames: H.264 in MP4, VP9 in WebM", "[render][segment][video]") {
  for (const std::string ext : {".mp4", ".webm"}) {
    INFO(ext);
    ScratchDirectory dir;
    const std::string args = kSmall + " --quality lossless";
    REQUIRE(run_vibra("render" + args + " -o " + (dir / ("whole" + ext))).exit_code == 0);
    render_segments(args, 3, dir / ("lecture" + ext));
    // A segment starts with a key frame and carries its first frame's timestamp (frames 7..13 of 21).
    const std::string middle = dir / ("lecture.seg-1-of-3" + ext);
    const std::string first_frame = shell(
        "ffprobe -v error -select_streams v:0 -show_entries frame=key_frame,pts_time -read_intervals %+#1 -of default=nw=1 '" +
        middle + "'");
    CHECK_THAT(first_frame, Catch::Contains("key_frame=1") && Catch::Contains("pts_time=0.700000"));
    const auto joined = run_vibra("concat" + parts(dir, "lecture", 3, ext) + " -o " + (dir / ("joined" + ext)));
    INFO(joined.err);
    REQUIRE(joined.exit_code == 0);
    CHECK_THAT(joined.err, Catch::Contains("21 frames from 3 segments"));
    const std::string expected = frame_hashes(dir / ("whole" + ext));
    CHECK(std::count(expected.begin(), expected.end(), '\n') == 21);
    CHECK(frame_hashes(dir / ("joined" + ext)) == expected);
    if (ext == ".mp4") CHECK(probe(dir / ("whole" + ext), "stream=profile") == "High 4:4:4 Predictive\n");
  }
}

TEST_CASE("lossy segments joined match the one-pass render's frame count and duration", "[render][segment][video]") {
  // x264's preset medium codes B-frames: decoding order differs from display
  // order, and the decoding timestamps must still rise across the seams.
  for (const std::string variant : {".mp4", ".mkv", ".webm", ".mp4 --preset medium", ".mkv --preset medium"}) {
    INFO(variant);
    ScratchDirectory dir;
    const std::size_t space = std::min(variant.find(' '), variant.size());
    const std::string container = variant.substr(0, space), args = kSmall + variant.substr(space);
    REQUIRE(run_vibra("render" + args + " -o " + (dir / ("whole" + container))).exit_code == 0);
    render_segments(args, 4, dir / ("lecture" + container));
    REQUIRE(run_vibra("concat -q" + parts(dir, "lecture", 4, container) + " -o " + (dir / ("joined" + container))).exit_code == 0);
    const std::string facts = "stream=nb_read_frames:format=duration";
    CHECK(probe(dir / ("joined" + container), facts) == probe(dir / ("whole" + container), facts));
    CHECK(probe(dir / ("joined" + container), "stream=nb_read_frames") == "21\n");
    CHECK(shell("ffmpeg -v error -i '" + (dir / ("joined" + container)) + "' -f null - 2>&1").empty());  // decodes cleanly
  }
}

TEST_CASE("concat names the part that is wrong and writes nothing", "[render][segment][video]") {
  ScratchDirectory dir;
  render_segments(kSmall, 3, dir / "a.mp4");
  render_segments(kSmall + " --set Theta=30", 3, dir / "theta.mp4");
  render_segments(kSmall + " --quality high", 3, dir / "high.mp4");
  render_segments(kSmall, 2, dir / "halves.mp4");
  REQUIRE(run_vibra("render" + kSmall + " -o " + (dir / "whole.mp4")).exit_code == 0);
  std::ofstream(dir / "junk.mp4") << "not a video";
  // The third segment's tag and timestamps in a smaller picture.
  shell("ffmpeg -v error -copyts -i '" + (dir / "a.seg-2-of-3.mp4") + "' -vf scale=160:90 -c:v libx264 -map_metadata 0 '" +
        (dir / "nocodec.seg-2-of-3.mp4") + "'");
  const std::string a0 = dir / "a.seg-0-of-3.mp4", a1 = dir / "a.seg-1-of-3.mp4", a2 = dir / "a.seg-2-of-3.mp4";
  const std::string out = dir / "out.mp4";
  struct Case {
    std::string parts, expected;
  };
  const Case cases[] = {
      {a0 + " " + a2, "segment 1/3 (frames 7-13) is missing before '" + a2 + "': render it with --segment 1/3"},
      {a0 + " " + a1, "segment 2/3 (frames 14-20) is missing after '" + a1 + "'"},
      {a0 + " " + a1 + " " + a1 + " " + a2, "is segment 1/3, as '" + a1 + "' is: give each segment once"},
      {a0 + " " + (dir / "theta.seg-1-of-3.mp4") + " " + a2, "theta.seg-1-of-3.mp4': it is from another render than '" + a0 + "' (other scene, parameters"},
      {a0 + " " + (dir / "high.seg-1-of-3.mp4") + " " + a2, "high.seg-1-of-3.mp4': it is from another render"},
      {a0 + " " + (dir / "halves.seg-1-of-2.mp4"), "it is segment 1/2 of 21 frames, but '" + a0 + "' is one of 3 segments"},
      {a0 + " " + a1 + " " + (dir / "nocodec.seg-2-of-3.mp4"), "nocodec.seg-2-of-3.mp4': it has size 160x90 instead of 320x180 (unlike '" + a0 + "')"},
      {a0 + " " + (dir / "whole.mp4"), "whole.mp4': it is not a segment (no segment tag)"},
      {a0 + " " + (dir / "junk.mp4"), "junk.mp4': it cannot be read"},
      {a0 + " " + (dir / "missing.mp4"), "missing.mp4': it cannot be read"},
  };
  for (const auto& c : cases) {
    INFO("vibra concat " << c.parts);
    const auto r = run_vibra("concat " + c.parts + " -o " + out);
    INFO(r.err);
    check_refusal(r, c.expected);
    CHECK_FALSE(fs::exists(out));
  }
  const auto gif = run_vibra("concat " + a0 + " " + a1 + " " + a2 + " -o " + (dir / "out.gif"));
  check_refusal(gif, "cannot hold h264 video: name it like the parts (.mp4)");
  // In any order, into another container.
  REQUIRE(run_vibra("concat -q " + a2 + " " + a0 + " " + a1 + " -o " + (dir / "any_order.mkv")).exit_code == 0);
  CHECK(probe(dir / "any_order.mkv", "stream=nb_read_frames") == "21\n");
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir.path))
    if (e.path().filename().string()[0] == '.') left.push_back(e.path().filename());
  CHECK(left.empty());  // no temporaries
}

TEST_CASE("a transparent segment is from another render than an opaque one", "[render][segment][video]") {
  ScratchDirectory dir;
  render_segments(kSmall, 2, dir / "opaque.webm");
  render_segments(kSmall + " --transparent", 2, dir / "clear.webm");
  const auto r = run_vibra("concat " + (dir / "opaque.seg-0-of-2.webm") + " " + (dir / "clear.seg-1-of-2.webm") + " -o " +
                           (dir / "out.webm"));
  check_refusal(r, "clear.seg-1-of-2.webm': it is from another render");
  CHECK(run_vibra("concat -q " + (dir / "clear.seg-0-of-2.webm") + " " + (dir / "clear.seg-1-of-2.webm") + " -o " +
                  (dir / "clear.webm"))
            .exit_code == 0);
}

TEST_CASE("skip-existing: a complete segment costs nothing, another segment's file is rendered again", "[render][segment]") {
  ScratchDirectory dir;
  const std::string args = "render --size 320x180 --fps 10 --set periods=1 --skip-existing --segment 1/3 -o " + (dir / "a.mp4");
  REQUIRE(run_vibra(args).exit_code == 0);
  const std::string segment = dir / "a.seg-1-of-3.mp4";
  const auto written = fs::last_write_time(segment);
  const auto again = run_vibra(args);
  CHECK(again.exit_code == 0);
  CHECK(again.err == "vibra: " + segment + " is already complete: skipped\n");
  CHECK(fs::last_write_time(segment) == written);
  // A file of the same name that holds other frames is no reason to skip.
  fs::copy_file(dir / "a.seg-1-of-3.mp4", dir / "b.seg-0-of-3.mp4");
  const auto other = run_vibra("render" + kSmall + " --skip-existing --segment 0/3 -o " + (dir / "b.mp4"));
  CHECK(other.exit_code == 0);
  CHECK_THAT(shell("ffprobe -v error -show_entries format_tags=description -of csv=p=0 '" + (dir / "b.seg-0-of-3.mp4") + "'"),
             Catch::Contains("vibra segment 0/3: frames 0-6 of 21, render "));
  // PNG frames: skipped when every frame of the segment is there.
  const std::string png = "render" + kSmall + " --skip-existing --segment 2/3 -o " + (dir / "f_%02d.png");
  REQUIRE(run_vibra(png).exit_code == 0);
  CHECK(fs::exists(dir / "f_14.png"));
  CHECK(fs::exists(dir / "f_20.png"));
  CHECK_FALSE(fs::exists(dir / "f_13.png"));
  fs::remove(dir / "f_17.png");
  REQUIRE(run_vibra(png).exit_code == 0);
  CHECK(fs::exists(dir / "f_17.png"));
  CHECK(run_vibra(png.substr(0, png.find(" -q")) + png.substr(png.find(" -q") + 3)).err.find("already complete") !=
        std::string::npos);
}

/// Sets environment variables for the commands a test runs, and removes them after.
struct Environment {
  std::vector<std::string> names;
  Environment(std::initializer_list<std::pair<const char*, const char*>> variables) {
    for (const auto& [name, value] : variables) ::setenv(name, value, 1), names.push_back(name);
  }
  ~Environment() {
    for (const auto& name : names) ::unsetenv(name.c_str());
  }
};

TEST_CASE("segment auto takes K and N from a Slurm array or an indexed job", "[render][segment]") {
  ScratchDirectory dir;
  {
    // --array=3-7:2 is tasks 3, 5, 7: task 5 is segment 1 of 3.
    Environment slurm{{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "3"}, {"SLURM_ARRAY_TASK_STEP", "2"},
                      {"SLURM_ARRAY_TASK_COUNT", "3"}};
    REQUIRE(run_vibra("render" + kSmall + " --segment auto -o " + (dir / "s.mp4")).exit_code == 0);
  }
  CHECK(fs::exists(dir / "s.seg-1-of-3.mp4"));
  {
    Environment kubernetes{{"JOB_COMPLETION_INDEX", "3"}};
    REQUIRE(run_vibra("render" + kSmall + " --segment auto/4 -o " + (dir / "k.webm")).exit_code == 0);
  }
  CHECK(fs::exists(dir / "k.seg-3-of-4.webm"));
}

TEST_CASE("bad --segment, --quality lossless and concat requests are refused on one line", "[render][segment]") {
  for (const char* name : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "JOB_COMPLETION_INDEX"}) ::unsetenv(name);
  const std::string small = "render --size 320x180 --fps 10 --set periods=1 ";
  check_refused(small + "--segment 1/3 --at 1 -o OUT.png", "--segment splits a video or frame sequence; --at renders one still");
  check_refused(small + "--segment 1/3 -o OUT.html", "--segment cannot split a page (.html)");
  check_refused(small + "--segment 3/3 -o OUT.mp4", "--segment 3/3 gives segment 3 of 3: K must be 0..N-1");
  check_refused(small + "--segment 1/0 -o OUT.mp4", "K must be 0..N-1 and N 1..");
  check_refused(small + "--segment x -o OUT.mp4", "--segment x is not K/N, auto or auto/N");
  check_refused(small + "--segment -1/3 -o OUT.mp4", "is not K/N, auto or auto/N");
  check_refused(small + "--segment auto -o OUT.mp4",
                "--segment auto takes K and N from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT, which are not set");
  check_refused(small + "--segment auto/4 -o OUT.mp4",
                "takes K from JOB_COMPLETION_INDEX (an indexed job) or SLURM_ARRAY_TASK_ID, and neither is set");
  check_refused(small + "--segment 0/2 -o OUT.gif", "--segment needs a video that keeps timestamps");
  check_refused(small + "--segment 0/2 -o - --format y4m", "--segment writes files for vibra concat to join");
  check_refused(small + "--segment 0/30 -o OUT.mp4", "segment 0/30 has no frames: the render has only 21");
  check_refused(small + "--quality lossless -o OUT.ogv", "--quality lossless needs H.264 or VP9, not Theora");
  check_refused(small + "--quality lossless --crf 10 -o OUT.mp4", "--quality lossless and --crf exclude each other");
  check_refused("concat -o OUT.mp4", "PART is required");
  check_refused("concat OUT.mp4", "--output is required");
}
