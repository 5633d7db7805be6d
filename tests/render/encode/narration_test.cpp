// Narrated lectures: flite's speech and recorded takes decoded back from the MP4 and WebM (codec, rate, length, energy where each shot speaks, loudness), shots timed to their speech, and bad narration refused before any work.
#include <catch2/catch.hpp>

#include <csignal>
#include <chrono>
#include <cmath>
#include <thread>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "cli_support.hpp"
#include "stop_support.hpp"
#include "render/encode/audio/audio_source.hpp"
#include "render/encode/audio/loudness.hpp"
#include "scenes/lecture/narration.hpp"
#include "scenes/lecture/storyboard.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::write_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::shell;
namespace fs = std::filesystem;

namespace {

/// A 16-bit mono WAV of `samples` at `rate`.
void write_wav(const std::string& path, const std::vector<float>& samples, int rate) {
  const auto u32 = [](std::uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
  const auto u16 = [](std::uint16_t v) { return std::string{char(v), char(v >> 8)}; };
  std::string data;
  for (float s : samples) data += u16(std::uint16_t(std::int16_t(std::lround(s * 32767))));
  write_file(path, "RIFF" + u32(std::uint32_t(36 + data.size())) + "WAVEfmt " + u32(16) + u16(1) + u16(1) + u32(rate) +
                  u32(rate * 2) + u16(2) + u16(16) + "data" + u32(std::uint32_t(data.size())) + data);
}

std::vector<float> sine(double frequency, double amplitude, double seconds, int rate) {
  std::vector<float> out(std::size_t(seconds * rate));
  for (std::size_t n = 0; n < out.size(); ++n) out[n] = float(amplitude * std::sin(2 * M_PI * frequency * double(n) / rate));
  return out;
}

/// The file's sound decoded by ffmpeg: mono 48 kHz samples.
std::vector<float> decoded_sound(const std::string& file) {
  const std::string raw = shell("ffmpeg -v error -i '" + file + "' -map 0:a:0 -f f32le -ac 1 -ar 48000 -");
  std::vector<float> samples(raw.size() / sizeof(float));
  std::memcpy(samples.data(), raw.data(), samples.size() * sizeof(float));
  return samples;
}

/// Root mean square of the samples from `from` to `to` seconds.
double rms(const std::vector<float>& samples, double from, double to) {
  const std::size_t a = std::size_t(std::max(0.0, from) * 48000), b = std::min(samples.size(), std::size_t(to * 48000));
  double sum = 0;
  for (std::size_t i = a; i < b; ++i) sum += double(samples[i]) * samples[i];
  return b > a ? std::sqrt(sum / double(b - a)) : 0;
}

std::string probe(const std::string& file, const std::string& what) {
  return shell("ffprobe -v error " + what + " -of csv=p=0 '" + file + "'");
}

/// The chapters' end times, in seconds.
std::vector<double> chapter_ends(const std::string& file) {
  std::vector<double> ends;
  std::istringstream in(probe(file, "-show_entries chapter=end_time"));
  for (std::string line; std::getline(in, line);) ends.push_back(std::stod(line));
  return ends;
}

/// "00:00:01.685" -> 1.685
double vtt_seconds(const std::string& stamp) {
  return std::stoi(stamp.substr(0, 2)) * 3600 + std::stoi(stamp.substr(3, 2)) * 60 + std::stod(stamp.substr(6));
}

struct Cue {
  double start, end;
  std::string text;
};

std::vector<Cue> vtt_cues(const std::string& vtt) {
  std::vector<Cue> cues;
  std::istringstream in(vtt);
  for (std::string line; std::getline(in, line);)
    if (line.size() == 29 && line.find(" --> ") == 12) {
      std::string text;
      std::getline(in, text);
      cues.push_back({vtt_seconds(line.substr(0, 12)), vtt_seconds(line.substr(17, 12)), text});
    }
  return cues;
}

// Shot 1 speaks two sentences and lasts as long as they do; shot 2 is a
// silent card of 1 s; shot 3 runs T = 3 at speed 1 (41 frames, the last at
// 4.0 s, less its pause of 1 s at t = 1), so its note spoken at t = 1.5 starts
// 2.5 s into the shot.
const std::string kStory = R"(title = "Springs"
size = "320x180"
fps = 10
[[shot]]
card = "Springs"
say = "A spring. It swings."
[[shot]]
card = "Quiet"
seconds = 1
[[shot]]
scene = "spring"
set = { T = 3, dt = 0.05 }
seconds = 4.1
pause = [{ at = 1, seconds = 1 }]
notes = [{ at = "1.5-2", text = "it moves on", say = true }]
)";
}  // namespace

TEST_CASE("a narrated lecture: its speech decoded from the MP4 and the WebM, where and as loud as it should be",
          "[narration][video]") {
  ScratchDirectory dir;
  write_file(dir / "story.toml", kStory);
  for (const char* ext : {".mp4", ".webm"}) {
    SECTION(ext) {
      const std::string out = dir / (std::string("lecture") + ext);
      const auto r = run_vibra("lecture story.toml -q -o " + out, "cd " + dir.path.string() + " && ");
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      const bool mp4 = ext == std::string(".mp4");
      CHECK(probe(out, "-select_streams a -show_entries stream=codec_name,sample_rate,channels") ==
            (mp4 ? "aac,48000,1\n" : "opus,48000,1\n"));
      const std::vector<double> ends = chapter_ends(out);
      REQUIRE(ends.size() == 3);
      const std::vector<float> sound = decoded_sound(out);
      CHECK(double(sound.size()) / 48000 == Approx(ends[2]).margin(0.03));  // as long as the video
      // The spoken words are the subtitles, with the speech's timing: each
      // sentence from where the one before ends; the shot lasts its speech and a tail.
      const std::vector<Cue> cues = vtt_cues(read_file(dir / "lecture.vtt"));
      REQUIRE(cues.size() == 4);  // two sentences, the quiet card, the spoken note
      CHECK(cues[0].text == "A spring.");
      CHECK(cues[0].start == Approx(0.25));
      CHECK(cues[1].text == "It swings.");
      CHECK(cues[1].start == Approx(cues[0].end).margin(0.002));
      CHECK(ends[0] == Approx(cues[1].end + 0.75).margin(0.051));
      CHECK(cues[3].text == "it moves on");
      CHECK(cues[3].start == Approx(ends[1] + 2.5).margin(0.002));
      // Speech where the cues are, silence elsewhere.
      CHECK(rms(sound, cues[0].start, cues[1].end) > 0.02);
      CHECK(rms(sound, cues[3].start, cues[3].end) > 0.02);
      CHECK(rms(sound, cues[1].end + 0.05, ends[1] + 2.45) < 0.002);  // the tail, the quiet card, the scene until its note
      CHECK(rms(sound, cues[3].end + 0.05, ends[2]) < 0.002);
      const std::string loudness = shell("ffmpeg -nostats -i '" + out + "' -map 0:a -af ebur128 -f null - 2>&1 | "
                                         "awk '$1 == \"I:\" {i = $2} END {print i}'");
      INFO(loudness);
      CHECK(std::stod(loudness) == Approx(vibra::render::kSpeechLoudness).margin(1.5));
    }
  }
}

TEST_CASE("lecture --mute: the same shots and chapters without a sound track", "[narration][video]") {
  ScratchDirectory dir;
  write_file(dir / "story.toml", kStory);
  REQUIRE(run_vibra("lecture story.toml -q -o spoken.mp4", "cd " + dir.path.string() + " && ").exit_code == 0);
  REQUIRE(run_vibra("lecture story.toml -q --mute -o muted.mp4", "cd " + dir.path.string() + " && ").exit_code == 0);
  CHECK(probe(dir / "muted.mp4", "-select_streams a -show_entries stream=codec_name").empty());
  CHECK(chapter_ends(dir / "muted.mp4") == chapter_ends(dir / "spoken.mp4"));
}

TEST_CASE("a recorded take comes through as recorded, resampled to 48 kHz", "[narration]") {
  ScratchDirectory dir;
  write_wav(dir / "take.wav", sine(440, 0.5, 1.5, 44100), 44100);
  const vibra::render::AudioClip take = vibra::render::read_take(dir / "take.wav");
  CHECK(take.seconds() == Approx(1.5).margin(0.001));
  const std::vector<float> expected = sine(440, 0.5, 1.5, 48000);
  double worst = 0;
  for (std::size_t n = 4800; n + 4800 < std::min(take.samples.size(), expected.size()); ++n)
    worst = std::max(worst, std::abs(double(take.samples[n]) - expected[n]));
  CHECK(worst < 0.005);  // 16-bit samples, resampled: no gain, no delay
  SECTION("in a lecture, it sets the shot's length and is heard at 440 Hz") {
    write_file(dir / "story.toml", "size = \"320x180\"\nfps = 10\n[[shot]]\ncard = \"A tone\"\naudio = \"take.wav\"\nsay = \"A tone.\"\n");
    REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " -q -o " + (dir / "tone.mp4")).exit_code == 0);
    CHECK(chapter_ends(dir / "tone.mp4") == std::vector<double>{2.5});  // 0.25 + 1.5 + 0.75
    const std::vector<float> sound = decoded_sound(dir / "tone.mp4");
    CHECK(rms(sound, 0.35, 1.65) == Approx(0.5 / std::sqrt(2)).epsilon(0.05));
    int crossings = 0;
    for (std::size_t n = std::size_t(0.35 * 48000); n < std::size_t(1.65 * 48000); ++n)
      crossings += (sound[n] < 0) != (sound[n + 1] < 0);
    CHECK(crossings == Approx(2 * 440 * 1.3).epsilon(0.01));
    CHECK_THAT(read_file(dir / "tone.vtt"), Catch::Contains("00:00:00.250 --> 00:00:01.750\nA tone."));
  }
}

TEST_CASE("a shot's words are said sentence by sentence: split after . ! or ? and a space, an ellipsis kept with its sentence",
          "[narration]") {
  // Each sentence is its own piece (and its own subtitle), said right after the one before.
  const auto board = vibra::scenes::parse_storyboard(
      "size = \"320x180\"\n[[shot]]\ncard = \"A\"\nsay = \"Does it swing? Yes! It slows... down. Wait. ... e.g.3 stays whole.\"\n",
      "story.toml");
  const auto narration = vibra::scenes::narrate_lecture(board);
  REQUIRE(narration.size() == 1);
  const auto& said = narration[0].said;
  std::vector<std::string> texts;
  for (const auto& piece : said) texts.push_back(piece.text);
  CHECK(texts == std::vector<std::string>{"Does it swing?", "Yes!", "It slows...", "down.", "Wait. ...", "e.g.3 stays whole."});
  for (std::size_t i = 1; i < said.size(); ++i) {
    INFO("piece " << i);
    CHECK(said[i].clip.seconds() > 0);
    CHECK(said[i].start == Approx(said[i - 1].start + said[i - 1].clip.seconds()));
  }
}

TEST_CASE("a shot's length: a card 3 s unless given, a speaking shot its speech and 0.75 s, a speed its own pace",
          "[narration]") {
  using vibra::scenes::kSpeechLead;
  using vibra::scenes::kSpeechTail;
  auto board = vibra::scenes::parse_storyboard("size = \"320x180\"\n"
                                               "[[shot]]\ncard = \"A\"\n"                      // 1: the default
                                               "[[shot]]\ncard = \"B\"\nseconds = 5\n"          // 2: as given
                                               "[[shot]]\ncard = \"C\"\n"                      // 3: speaks
                                               "[[shot]]\nscene = \"spring\"\n"                // 4: speaks
                                               "[[shot]]\nscene = \"spring\"\nspeed = 2\n"      // 5: speaks, paced
                                               "[[shot]]\nscene = \"bumpy_road\"\nvideo_speed = 2\n"  // 6: the same
                                               "[[shot]]\nscene = \"spring\"\nframe_per_step = true\n",  // 7
                                               "story.toml");
  REQUIRE(board.shots.size() == 7);
  CHECK(board.shots[0].seconds == 3.0);
  CHECK(board.shots[1].seconds == 5.0);
  for (int i : {4, 5, 6}) {
    INFO("shot " << i + 1);
    CHECK(board.shots[i].timed);  // paced by its own keys: speech does not set its length
    CHECK_FALSE(board.shots[i].seconds);
  }
  CHECK_FALSE(board.shots[3].timed);
  // Two seconds of speech for shots 3 to 6 (made by hand: no voice needed).
  std::vector<vibra::scenes::ShotNarration> narration(7);
  for (int i : {2, 3, 4, 5})
    narration[i].said.push_back({kSpeechLead, {std::vector<float>(2 * vibra::render::AudioClip::kRate, 0.1f)}, "Words."});
  vibra::scenes::fit_shots_to_speech(board, narration);
  CHECK(board.shots[2].seconds == Approx(kSpeechLead + 2 + kSpeechTail));
  CHECK(board.shots[3].seconds == Approx(kSpeechLead + 2 + kSpeechTail));
  CHECK_FALSE(board.shots[4].seconds);  // its speed paces it; the speech is checked when placed
  CHECK_FALSE(board.shots[5].seconds);
  CHECK(kSpeechTail == 0.75);
  // A pace and seconds together are refused, whichever name the speed has.
  for (const char* pace : {"speed = 2", "video_speed = 2"}) {
    INFO(pace);
    CHECK_THROWS_WITH(vibra::scenes::parse_storyboard(
                          std::string("[[shot]]\nscene = \"bumpy_road\"\nseconds = 3\n") + pace + "\n", "story.toml"),
                      Catch::Contains("both set the shot's pace"));
  }
}

TEST_CASE("loudness as BS.1770 measures it, and speech brought to -16 LUFS", "[narration]") {
  using namespace vibra::render;
  AudioClip tone{sine(997, 1.0, 3, AudioClip::kRate)};
  CHECK(integrated_loudness(tone) == Approx(-3.01).margin(0.05));  // BS.1770's full-scale 997 Hz sine
  AudioClip quiet{sine(997, 0.1, 3, AudioClip::kRate)};
  CHECK(integrated_loudness(quiet) == Approx(-23.01).margin(0.05));
  CHECK(std::isinf(integrated_loudness(AudioClip{std::vector<float>(48000)})));
  normalize_loudness(quiet);
  CHECK(integrated_loudness(quiet) == Approx(kSpeechLoudness).margin(0.01));
  const AudioClip speech = speak("The drag opposes the motion.", "slt");
  CHECK(speech.seconds() > 1);
  CHECK(integrated_loudness(speech) == Approx(kSpeechLoudness).margin(0.1));
  CHECK(speak("Each swing is lower.", "kal").seconds() != Approx(speak("Each swing is lower.", "awb").seconds()));
}

TEST_CASE("loudness gates blocks of 400 ms that start every 100 ms (BS.1770's 75% overlap)", "[narration]") {
  using namespace vibra::render;
  // 100 ms of a full-scale 997 Hz sine at 0.45 s in 1 s of silence. Of the
  // seven blocks (starting at 0, 0.1, ..., 0.6 s) five hold the tone, for
  // 1/8, 1/4, 1/4, 1/4 and 1/8 of their length: all pass both gates and
  // their mean power is 1/5 of the tone's, so the loudness is the tone's
  // -3.01 LUFS plus 10 log10(1/5) = -6.99 dB. Blocks every 200 ms would
  // hold it for 1/4 twice: -9.03.
  AudioClip burst{std::vector<float>(AudioClip::kRate)};
  const std::vector<float> tone = sine(997, 1.0, 0.1, AudioClip::kRate);
  std::copy(tone.begin(), tone.end(), burst.samples.begin() + AudioClip::kRate * 45 / 100);
  CHECK(integrated_loudness(burst) == Approx(-10.0).margin(0.05));
}

TEST_CASE("shots timed to their speech: seconds too short refused with both durations, or stretched",
          "[narration]") {
  ScratchDirectory dir;
  const std::string head = "size = \"320x180\"\nfps = 10\n[[shot]]\ncard = \"A\"\nseconds = 0.5\n";
  const std::string words = "say = \"The pendulum swings and drag slows it down.\"\n";
  write_file(dir / "story.toml", head + words);
  check_refused("lecture " + (dir / "story.toml") + " -o OUT.mp4", "story.toml:6: shot 1, say: the speech lasts ");
  check_refused("lecture " + (dir / "story.toml") + " -o OUT.mp4", " but the shot 0.50 s: give seconds = ");
  write_file(dir / "story.toml", head + words + "fit = \"stretch\"\n");
  REQUIRE(run_vibra("lecture " + (dir / "story.toml") + " -q -o " + (dir / "long.mp4")).exit_code == 0);
  const std::vector<Cue> cues = vtt_cues(read_file(dir / "long.vtt"));
  REQUIRE(cues.size() == 1);
  CHECK(chapter_ends(dir / "long.mp4").front() == Approx(cues[0].end + 0.75).margin(0.051));
  // A scene shot stretched: its run of T = 2 slowed to last the speech, not refused.
  write_file(dir / "scene.toml", "size = \"320x180\"\nfps = 10\n[[shot]]\nscene = \"spring\"\nset = { T = 2 }\n"
                            "seconds = 0.5\nfit = \"stretch\"\n" + words);
  REQUIRE(run_vibra("lecture " + (dir / "scene.toml") + " -q -o " + (dir / "scene.mp4")).exit_code == 0);
  const double end = chapter_ends(dir / "scene.mp4").front();
  CHECK(end == Approx(vtt_cues(read_file(dir / "scene.vtt")).front().end + 0.75).margin(0.051));
  CHECK(probe(dir / "scene.mp4", "-count_frames -select_streams v:0 -show_entries stream=nb_read_frames") ==
        std::to_string(std::lround(end * 10)) + "\n");
}

TEST_CASE("bad narration: one line naming the file, shot and key, exit 2, nothing written", "[narration]") {
  ScratchDirectory takes;
  write_wav(takes / "silent.wav", std::vector<float>(48000), 48000);
  write_file(takes / "notes.wav", "not a recording");
  const std::string head = "size = \"320x180\"\nfps = 10\n";
  const std::string spring = "[[shot]]\nscene = \"spring\"\nset = { T = 3 }\nseconds = 4\n";
  struct Case {
    std::string story, expected;
  };
  const std::vector<Case> cases = {
      {"voice = \"hal\"\n" + head + "[[shot]]\ncard = \"A\"\n", "story.toml:1: voice: unknown voice 'hal': flite speaks slt, kal"},
      {head + "[[shot]]\ncard = \"A\"\nsay = \"Hi\"\nvoice = \"hal\"\n", "story.toml:6: shot 1, voice: unknown voice 'hal'"},
      {head + "[[shot]]\ncard = \"A\"\nsay = \"...\"\n", "story.toml:5: shot 1, say: flite cannot speak \"...\": it has no words"},
      {head + "[[shot]]\ncard = \"A\"\nsay = \"  \"\n", "story.toml:5: shot 1, say: is empty"},
      {head + "[[shot]]\ncard = \"A\"\nsay = \"Hi\"\nfit = \"squeeze\"\n", "shot 1, fit: must be \"stretch\""},
      {head + "[[shot]]\ncard = \"A\"\naudio = \"missing.wav\"\n", "shot 1, audio: no recording '"},
      {head + "[[shot]]\ncard = \"A\"\naudio = \"" + (takes / "silent.wav") + "\"\n", "silent.wav' is silent"},
      {head + "[[shot]]\ncard = \"A\"\naudio = \"" + (takes / "notes.wav") + "\"\n", "notes.wav' cannot be read"},
      {head + spring + "notes = [{ at = \"1-2\", text = \"one\", say = true }, { at = \"1-2\", text = \"two\", say = true }]\n",
       "shot 1, notes: speech from 1.28 s overlaps the speech from 1.28 s to"},
      {head + spring + "notes = [{ at = \"2.9-3\", text = \"far too late to say all this\", say = true }]\n",
       "runs past the shot's end at 4.00 s"},
      {head + spring + "notes = [{ at = \"1-2\", words = \"x\" }]\n", "shot 1, notes: a note takes at, text and say, not 'words'"},
      {head + "[[shot]]\ncard = \"A\"\nsay = 3\n", "shot 1, say: must be a string"},
      {head + "[[shot]]\ncard = \"A\"\nsay = \"" + std::string(1001, 'a') + "\"\n",
       "story.toml:5: shot 1, say: a sentence of 1001 characters is more than flite speaks at once (1000)"},
  };
  for (const Case& c : cases) {
    SECTION(c.expected) {
      ScratchDirectory stories;
      write_file(stories / "story.toml", c.story);
      check_refused("lecture " + (stories / "story.toml") + " -o OUT.mp4", c.expected);
    }
  }
}

TEST_CASE("lecture --script: each shot's number, start, length, title and words, and nothing rendered",
          "[narration]") {
  ScratchDirectory dir;
  write_file(dir / "story.toml", kStory);
  const auto r = run_vibra("lecture story.toml --script", "cd " + dir.path.string() + " && ");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("# Springs: the narration script"));
  CHECK_THAT(r.out, Catch::Contains("\nshot 1  at 0:00.0, "));
  CHECK_THAT(r.out, Catch::Contains("  Springs\n  A spring. It swings.\n"));
  CHECK_THAT(r.out, Catch::Contains("\nshot 2  at 0:0"));
  CHECK_THAT(r.out, Catch::Contains(", 1.0 s  Quiet\n  (silent)\n"));
  CHECK_THAT(r.out, Catch::Contains(", 4.1 s  spring\n  (at t = 1.5) it moves on\n"));
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);  // the storyboard alone
}

TEST_CASE("a narrated lecture's page plays its sound: the video is not muted", "[narration][page]") {
  ScratchDirectory dir;
  write_file(dir / "story.toml", kStory);
  REQUIRE(run_vibra("lecture story.toml -q -o page.html", "cd " + dir.path.string() + " && ").exit_code == 0);
  const std::string html = read_file(dir / "page.html");
  const std::string video = html.substr(html.find("<video"), html.find('>', html.find("<video")) - html.find("<video"));
  CHECK(video.find("muted") == std::string::npos);
  for (const char* file : {"page_files/page.mp4", "page_files/page.webm"})
    CHECK_FALSE(probe(dir / file, "-select_streams a -show_entries stream=codec_name").empty());
}

TEST_CASE("Ctrl-C while the speech is made stops the lecture at once, and nothing is written", "[narration][signals]") {
  ScratchDirectory dir, logs;
  std::string story = "size = \"320x180\"\nfps = 10\n";
  for (int shot = 1; shot <= 400; ++shot)  // about 50 ms of flite a shot: 10 s of speech to make on two cores
    story += "[[shot]]\ncard = \"Card\"\nsay = \"Shot " + std::to_string(shot) + " says a sentence of some length.\"\n";
  write_file(dir / "story.toml", story);
  const auto [code, seconds] = vibra::test::stopped_after({"lecture", dir / "story.toml", "-q", "-o", dir / "talk.mp4"},
                                                          logs, SIGINT, 1.5);
  INFO(read_file(logs / "err"));
  CHECK(code == 128 + SIGINT);
  CHECK(seconds < 5);  // a bound for a hang on a loaded machine: the speech stops within a sentence
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);  // the storyboard alone
}

TEST_CASE("a full disk while a narrated lecture is joined names the lecture and leaves nothing", "[narration]") {
  ScratchDirectory at;
  write_file(at / "talk.toml", "size = \"640x360\"\n[[shot]]\ncard = \"A\"\nsay = \"A card that speaks.\"\n"
                          "[[shot]]\nscene = \"pendulum\"\nseconds = 20\nsay = \"The pendulum swings.\"\n");
  const auto r = run_vibra("lecture talk.toml -q -o talk.mp4", "cd '" + at.path.string() + "' && trap '' XFSZ && ulimit -f 100 && ");
  vibra::test::check_refusal(r, "cannot write video to 'talk.mp4'");
  CHECK(r.err.find("vibra-tmp") == std::string::npos);
  CHECK(std::distance(fs::directory_iterator(at.path), fs::directory_iterator()) == 1);  // the storyboard alone
}

TEST_CASE("a spoken note that no frame shows is one subtitle, timed as it is spoken", "[narration]") {
  ScratchDirectory dir;
  // At 10 fps and speed 1, frames show t = 1.0 and 1.1: none shows 1.02-1.08, so the note is a subtitle.
  write_file(dir / "story.toml", "size = \"320x180\"\nfps = 10\n[[shot]]\nscene = \"spring\"\nset = { T = 3, dt = 0.05 }\n"
                            "seconds = 3.1\nnotes = [{ at = \"1.02-1.08\", text = \"between frames\", say = true }]\n");
  REQUIRE(run_vibra("lecture story.toml -q -o talk.mp4", "cd " + dir.path.string() + " && ").exit_code == 0);
  const std::vector<Cue> cues = vtt_cues(read_file(dir / "talk.vtt"));
  REQUIRE(cues.size() == 1);
  CHECK(cues[0].text == "between frames");
  CHECK(cues[0].start == Approx(1.02).margin(0.002));
  const std::vector<float> sound = decoded_sound(dir / "talk.mp4");
  CHECK(rms(sound, cues[0].start, cues[0].end) > 0.02);
}

TEST_CASE("a narrated presentation: each slide that speaks plays its own part of the speech, a silent one none",
          "[narration][present]") {
  ScratchDirectory dir;
  write_file(dir / "story.toml", kStory);
  const auto r = run_vibra("lecture story.toml -q -o talk.html --present --shots-dir shots", "cd " + dir.path.string() + " && ");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::vector<Cue> cues = vtt_cues(read_file(dir / "talk_files/talk.vtt"));
  REQUIRE(cues.size() == 4);  // two sentences, the quiet card, the spoken note
  const std::vector<double> ends = chapter_ends(dir / "talk_files/talk.mp4");
  REQUIRE(ends.size() == 3);
  const std::string spoken = dir / "talk_files/01-springs.mp4", quiet = dir / "talk_files/02-quiet.mp4",
                    scene = dir / "talk_files/03-spring.mp4";
  for (const std::string& file : {spoken, scene, std::string(dir / "shots/01-springs.mp4")}) {
    INFO(file);
    CHECK(probe(file, "-select_streams a -show_entries stream=codec_name,sample_rate,channels") == "aac,48000,1\n");
  }
  CHECK(probe(quiet, "-select_streams a -show_entries stream=codec_name").empty());
  // Each shot's sound from its own start: the card's two sentences, the scene's note 2.5 s in.
  const std::vector<float> first = decoded_sound(spoken), third = decoded_sound(scene);
  CHECK(double(first.size()) / 48000 == Approx(ends[0]).margin(0.03));
  CHECK(rms(first, cues[0].start, cues[1].end) > 0.02);
  CHECK(rms(first, cues[1].end + 0.05, ends[0]) < 0.002);
  CHECK(rms(third, 0, 2.45) < 0.002);
  CHECK(rms(third, 2.5, 2.5 + (cues[3].end - cues[3].start)) > 0.02);
  // The page plays the speaking slides unmuted, the silent one muted.
  const std::string html = read_file(dir / "talk.html");
  auto video_tag = [&](const std::string& file) {
    const std::size_t at = html.rfind("<video", html.find("data-src=\"talk_files/" + file + "\""));
    return html.substr(at, html.find('>', at) - at);
  };
  CHECK(video_tag("01-springs.mp4").find("muted") == std::string::npos);
  CHECK(video_tag("02-quiet.mp4").find("muted") != std::string::npos);
  CHECK(video_tag("03-spring.mp4").find("muted") == std::string::npos);
}
