// Tests of VideoWriter: codecs, pixel formats, sizes and timing of the written videos.
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "render/encode/video_writer.hpp"
#include "render/output/output_error.hpp"

namespace fs = std::filesystem;
using vibra::render::OutputError;
using vibra::render::VideoOptions;
using vibra::render::VideoQuality;
using vibra::render::VideoWriter;

namespace {

/// A fresh directory under /tmp, removed with its contents at scope exit.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    char name[] = "/tmp/vibra-video-test-XXXXXX";
    REQUIRE(mkdtemp(name) != nullptr);
    path = name;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  bool empty() const { return fs::is_empty(path); }
};

/// Synthetic line art in Cairo's ARGB32 layout: white, a grey grid, a black
/// rod swinging from a pivot and a blue bob. Rows are padded, so the stride
/// differs from width * 4 as Cairo's may.
struct Frames {
  int width, height, stride;
  std::vector<std::uint32_t> pixels;

  Frames(int w, int h) : width(w), height(h), stride(w * 4 + 16), pixels(std::size_t(stride / 4) * h) {}

  void set(int x, int y, std::uint32_t argb) {
    if (x >= 0 && y >= 0 && x < width && y < height) pixels[std::size_t(y) * (stride / 4) + x] = argb;
  }

  const std::uint8_t* draw(int i) {
    std::fill(pixels.begin(), pixels.end(), 0xffffffffu);
    for (int y = 20; y < height - 20; y += 20)
      for (int x = 20; x < width - 20; ++x) set(x, y, 0xffc8c8c8u);
    const double angle = 0.8 * std::cos(0.25 * i), rod = 0.6 * height;
    const double px = width / 2.0, py = 10, bx = px + rod * std::sin(angle), by = py + rod * std::cos(angle);
    for (int s = 0; s <= 400; ++s) {
      const double t = s / 400.0;
      set(int(px + t * (bx - px)), int(py + t * (by - py)), 0xff000000u);
      set(int(px + t * (bx - px)) + 1, int(py + t * (by - py)), 0xff000000u);
    }
    for (int y = int(by) - 12; y <= int(by) + 12; ++y)
      for (int x = int(bx) - 12; x <= int(bx) + 12; ++x)
        if ((x - bx) * (x - bx) + (y - by) * (y - by) <= 144) set(x, y, 0xff3366ccu);
    return reinterpret_cast<const std::uint8_t*>(pixels.data());
  }
};

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// Runs a command and returns its standard output.
std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  REQUIRE(pclose(pipe) == 0);
  return out;
}

/// ffprobe's view of a file, decoding every frame, as flat `key=value` pairs
/// (e.g. streams.stream.0.codec_name -> h264). Decoder complaints land in
/// the "errors" entry.
std::map<std::string, std::string> probe(const fs::path& file) {
  const fs::path errors = file.string() + ".errors";
  const std::string out = run("ffprobe -v error -show_streams -show_format -count_frames -of flat " + quoted(file) +
                              " 2>" + quoted(errors));
  std::map<std::string, std::string> fields;
  std::size_t start = 0;
  for (std::size_t end; (end = out.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = out.substr(start, end - start);
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string value = line.substr(eq + 1);
    if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
    fields[line.substr(0, eq)] = value;
  }
  std::ifstream in(errors);
  fields["errors"] = std::string(std::istreambuf_iterator<char>(in), {});
  fs::remove(errors);
  return fields;
}

std::string stream(const std::map<std::string, std::string>& p, const std::string& key) {
  const auto it = p.find("streams.stream.0." + key);
  return it == p.end() ? "" : it->second;
}

/// The four-letter types of an MP4 file's top-level boxes, in file order.
std::vector<std::string> top_level_boxes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> boxes;
  const auto file_size = static_cast<std::uint64_t>(fs::file_size(file));
  std::uint64_t at = 0;
  while (at + 8 <= file_size) {
    unsigned char head[16];
    in.seekg(std::streamoff(at));
    in.read(reinterpret_cast<char*>(head), 8);
    std::uint64_t size = std::uint64_t(head[0]) << 24 | head[1] << 16 | head[2] << 8 | head[3];
    boxes.emplace_back(reinterpret_cast<char*>(head) + 4, 4);
    if (size == 1) {  // 64-bit size follows the type
      in.read(reinterpret_cast<char*>(head + 8), 8);
      size = 0;
      for (int k = 8; k < 16; ++k) size = size << 8 | head[k];
    }
    if (size < 8) break;  // 0 means "to the end of the file"
    at += size;
  }
  return boxes;
}

void encode(const fs::path& file, const VideoOptions& options, int count) {
  Frames frames(options.width, options.height);
  VideoWriter writer(file, options);
  for (int i = 0; i < count; ++i) writer.write(frames.draw(i), frames.stride);
  writer.finish();
  CHECK(writer.frames_written() == count);
}

VideoOptions small(int fps = 30) {
  VideoOptions o;
  o.width = 320;
  o.height = 240;
  o.fps = fps;
  return o;
}

std::size_t index_of(const std::vector<std::string>& v, const std::string& s) {
  return static_cast<std::size_t>(std::find(v.begin(), v.end(), s) - v.begin());
}

}  // namespace

// The default codes in 4x4 transforms only, so x264 writes Main; a --preset
// of the user's is x264's own (medium: 8x8 transforms, High).
TEST_CASE("MP4 is H.264 Main, BT.709 limited range, exactly 1/fps per frame, index first", "[video]") {
  ScratchDir dir;
  const fs::path file = dir.path / "pendulum.mp4";
  VideoOptions options = small(30);
  options.metadata = {{"title", "Pendulum"}, {"comment", "vibra test"}};
  encode(file, options, 45);

  const auto p = probe(file);
  CHECK(stream(p, "codec_name") == "h264");
  CHECK(stream(p, "profile") == "Main");
  CHECK(stream(p, "pix_fmt") == "yuv420p");
  CHECK(stream(p, "width") == "320");
  CHECK(stream(p, "height") == "240");
  CHECK(stream(p, "color_range") == "tv");
  CHECK(stream(p, "color_space") == "bt709");
  CHECK(stream(p, "color_primaries") == "bt709");
  CHECK(stream(p, "color_transfer") == "bt709");
  CHECK(stream(p, "nb_frames") == "45");
  CHECK(stream(p, "nb_read_frames") == "45");
  CHECK(stream(p, "avg_frame_rate") == "30/1");
  CHECK(std::stod(stream(p, "duration")) == Approx(1.5).margin(0.001));
  CHECK(std::stod(p.at("format.duration")) == Approx(1.5).margin(0.001));
  CHECK(p.at("format.tags.title") == "Pendulum");
  CHECK(p.at("format.tags.comment") == "vibra test");
  CHECK(p.at("errors").empty());

  const auto boxes = top_level_boxes(file);
  INFO("boxes: " << boxes.size());
  REQUIRE(index_of(boxes, "mdat") < boxes.size());
  CHECK(index_of(boxes, "moov") < index_of(boxes, "mdat"));
  CHECK(std::vector<fs::path>(fs::directory_iterator(dir.path), {}) == std::vector<fs::path>{file});
}

TEST_CASE("a --preset of the user's is x264's own: medium codes 8x8 transforms, High", "[video]") {
  ScratchDir dir;
  const fs::path file = dir.path / "medium.mp4";
  VideoOptions options = small(30);
  options.preset = "medium";
  encode(file, options, 10);
  CHECK(stream(probe(file), "profile") == "High");
}

TEST_CASE("H.264 pads an odd size to even by repeating the edge, with a note", "[video]") {
  ScratchDir dir;
  const fs::path file = dir.path / "odd.mp4";
  VideoOptions options = small();
  options.width = 321;
  options.height = 241;
  options.quality = VideoQuality::high;
  Frames frames(321, 241);
  VideoWriter writer(file, options);
  REQUIRE(writer.notes().size() == 1);
  CHECK(writer.notes()[0] == "H.264 needs even sizes: 321x241 encoded as 322x242");
  for (int i = 0; i < 45; ++i) writer.write(frames.draw(i), frames.stride);
  writer.finish();

  const auto p = probe(file);
  CHECK(stream(p, "width") == "322");
  CHECK(stream(p, "height") == "242");
  CHECK(stream(p, "nb_read_frames") == "45");
  CHECK(p.at("errors").empty());
  // The frames' edges are white; padding with anything but the edge would show as a dark line.
  const std::string luma =
      run("ffmpeg -v error -i " + quoted(file) + " -frames:v 1 -f rawvideo -pix_fmt gray -");
  REQUIRE(luma.size() == 322u * 242u);
  int darkest = 255;
  for (int y = 0; y < 242; ++y) darkest = std::min(darkest, int(static_cast<unsigned char>(luma[y * 322 + 321])));
  for (int x = 0; x < 322; ++x) darkest = std::min(darkest, int(static_cast<unsigned char>(luma[241 * 322 + x])));
  CHECK(darkest > 200);
}

TEST_CASE("WebM is constant-quality VP9 with exact timing and metadata", "[video]") {
  ScratchDir dir;
  const fs::path file = dir.path / "pendulum.webm";
  VideoOptions options = small(24);
  options.metadata = {{"title", "Pendulum"}};
  encode(file, options, 45);

  const auto p = probe(file);
  CHECK(stream(p, "codec_name") == "vp9");
  CHECK(stream(p, "pix_fmt") == "yuv420p");
  CHECK(stream(p, "color_range") == "tv");
  CHECK(stream(p, "color_space") == "bt709");
  CHECK(stream(p, "nb_read_frames") == "45");
  CHECK(stream(p, "avg_frame_rate") == "24/1");
  CHECK(std::stod(p.at("format.duration")) == Approx(45.0 / 24).margin(0.001));
  CHECK(p.at("format.tags.title") == "Pendulum");
  CHECK(p.at("errors").empty());
}

TEST_CASE("other formats hold the right codec and every frame", "[video]") {
  struct Case {
    const char* name;
    const char* codec;
    const char* expected;
  };
  const Case cases[] = {{"a.mkv", "", "h264"},      {"b.webm", "vp8", "vp8"}, {"c.ogv", "", "theora"},
                        {"d.gif", "", "gif"},       {"e.flv", "", "flv1"},    {"f.mkv", "vp9", "vp9"},
                        {"odd.webm", "", "vp9"},    {"odd.gif", "", "gif"}};
  ScratchDir dir;
  for (const Case& c : cases) {
    INFO(c.name);
    VideoOptions options = small();
    options.codec = c.codec;
    if (std::string(c.name).rfind("odd", 0) == 0) options.width = 321, options.height = 241;
    encode(dir.path / c.name, options, 45);
    const auto p = probe(dir.path / c.name);
    CHECK(stream(p, "codec_name") == c.expected);
    CHECK(stream(p, "width") == std::to_string(options.width));
    CHECK(stream(p, "nb_read_frames") == "45");
    CHECK(p.at("errors").empty());
  }
}

TEST_CASE("GIF keeps a colour of its 6x6x6 cube exactly, white as white and a light grey as a grey", "[video]") {
  // The fixed palette: every channel a multiple of 51, plus 40 greys. The
  // bob (51, 102, 204) is in the cube; the grid's (200, 200, 200) is not, and
  // its nearest colour is a grey within 4 levels (199, one of the 40).
  ScratchDir dir;
  encode(dir.path / "d.gif", small(), 3);
  const std::string rgb = run("ffmpeg -v error -i " + quoted(dir.path / "d.gif") +
                              " -frames:v 1 -f rawvideo -pix_fmt rgb24 -");
  REQUIRE(rgb.size() == 320 * 240 * 3);
  const auto pixel = [&](int x, int y) {
    const std::size_t at = (std::size_t(y) * 320 + x) * 3;
    return std::array<int, 3>{std::uint8_t(rgb[at]), std::uint8_t(rgb[at + 1]), std::uint8_t(rgb[at + 2])};
  };
  // Frame 0's bob is centred at (160 + 144 sin 0.8, 10 + 144 cos 0.8) = (263.3, 110.3).
  CHECK(pixel(263, 110) == std::array<int, 3>{51, 102, 204});
  CHECK(pixel(5, 5) == std::array<int, 3>{255, 255, 255});
  const std::array<int, 3> grid = pixel(40, 20);
  CHECK((grid[0] == grid[1] && grid[1] == grid[2]));
  CHECK(std::abs(grid[0] - 200) <= 4);
}

TEST_CASE("raw YUV holds the very frames the encoders get, and H.264 reproduces them", "[video]") {
  ScratchDir dir;
  VideoOptions options = small();
  encode(dir.path / "frames.yuv", options, 30);
  const std::size_t frame_bytes = 320 * 240 * 3 / 2;
  REQUIRE(fs::file_size(dir.path / "frames.yuv") == 30 * frame_bytes);
  encode(dir.path / "frames.mp4", options, 30);
  // Decoded H.264 against the raw frames: lossy, but close (PSNR in dB).
  const std::string log = run("ffmpeg -v info -i " + quoted(dir.path / "frames.mp4") +
                              " -f rawvideo -pix_fmt yuv420p -s 320x240 -r 30 -i " + quoted(dir.path / "frames.yuv") +
                              " -lavfi psnr -f null - 2>&1");
  const auto at = log.find("average:");
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(log.substr(at + 8)) > 40);
}

TEST_CASE("quality presets and crf set the size, bad values are refused", "[video]") {
  ScratchDir dir;
  VideoOptions options = small();
  options.quality = VideoQuality::draft;
  encode(dir.path / "draft.mp4", options, 45);
  options.quality = VideoQuality::high;
  encode(dir.path / "high.mp4", options, 45);
  options.crf = 40;  // overrides the quality
  encode(dir.path / "crf40.mp4", options, 45);
  CHECK(fs::file_size(dir.path / "draft.mp4") < fs::file_size(dir.path / "high.mp4"));
  CHECK(fs::file_size(dir.path / "crf40.mp4") < fs::file_size(dir.path / "draft.mp4"));

  options.crf = 52;
  CHECK_THROWS_WITH(VideoWriter(dir.path / "x.mp4", options), Catch::Contains("0..51"));
  options.crf = -1;
  options.preset = "quick";
  CHECK_THROWS_WITH(VideoWriter(dir.path / "x.mp4", options), Catch::Contains("veryfast"));
  options.preset = "";
  options.codec = "gif";
  CHECK_THROWS_WITH(VideoWriter(dir.path / "x.mp4", options), Catch::Contains("cannot hold GIF"));
  options.codec = "av1";
  CHECK_THROWS_AS(VideoWriter(dir.path / "x.mp4", options), OutputError);
  CHECK(std::distance(fs::directory_iterator(dir.path), {}) == 3);
}

TEST_CASE("the extension picks the codec, unknown ones are refused with the list", "[video]") {
  CHECK(VideoWriter::codec_for_path("a.mp4") == "h264");
  CHECK(VideoWriter::codec_for_path("dir/a.MKV") == "h264");
  CHECK(VideoWriter::codec_for_path("a.webm") == "vp9");
  CHECK(VideoWriter::codec_for_path("a.ogv") == "theora");
  CHECK(VideoWriter::codec_for_path("a.gif") == "gif");
  CHECK(VideoWriter::codec_for_path("a.flv") == "flv");
  CHECK(VideoWriter::codec_for_path("a.yuv") == "raw");
  CHECK(VideoWriter::is_video_path("x/a.WebM"));
  CHECK_FALSE(VideoWriter::is_video_path("a.png"));
  CHECK_THROWS_AS(VideoWriter::codec_for_path("a.avi"), OutputError);
  CHECK_THROWS_WITH(VideoWriter::codec_for_path("a"), Catch::Contains(".mp4") && Catch::Contains(".webm"));
  ScratchDir dir;
  CHECK_THROWS_AS(VideoWriter(dir.path / "a.avi", small()), OutputError);
  CHECK(dir.empty());
}

TEST_CASE("bad sizes and frame rates are refused", "[video]") {
  ScratchDir dir;
  const std::array<std::array<int, 3>, 5> cases = {{{0, 240, 30}, {320, 0, 30}, {8193, 240, 30}, {320, 240, 0}, {320, 240, 241}}};
  for (auto [w, h, fps] : cases) {
    VideoOptions o = small(fps);
    o.width = w;
    o.height = h;
    CHECK_THROWS_AS(VideoWriter(dir.path / "x.mp4", o), OutputError);
  }
  CHECK(dir.empty());
}

TEST_CASE("an unwritable directory is refused: a missing one is made, and removed when abandoned", "[video]") {
  ScratchDir dir;
  CHECK_THROWS_AS(VideoWriter("/proc/nonexistent/x.mp4", small()), OutputError);
  {
    VideoWriter writer(dir.path / "missing" / "x.mp4", small());
    CHECK(fs::is_directory(dir.path / "missing"));
  }
  CHECK(dir.empty());
}

TEST_CASE("an unfinished writer leaves neither a temporary nor a video", "[video]") {
  ScratchDir dir;
  Frames frames(320, 240);
  {
    VideoWriter writer(dir.path / "abandoned.mp4", small());
    for (int i = 0; i < 10; ++i) writer.write(frames.draw(i), frames.stride);
    CHECK_FALSE(dir.empty());  // the temporary exists while writing
  }
  CHECK(dir.empty());
}

namespace {
/// Lowers the file size limit (as a full disk would, writes fail; EFBIG
/// instead of ENOSPC) and restores it at scope exit. SIGXFSZ is ignored so
/// the failing write returns an error instead of killing the process.
struct FileSizeLimit {
  rlimit saved{};
  struct sigaction old_action {};
  explicit FileSizeLimit(rlim_t bytes) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGXFSZ, &ignore, &old_action);
    getrlimit(RLIMIT_FSIZE, &saved);
    rlimit lower = saved;
    lower.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &lower);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved);
    sigaction(SIGXFSZ, &old_action, nullptr);
  }
};
}  // namespace

TEST_CASE("a write failure mid-video is reported and removes the temporary", "[video]") {
  // A real full disk needs a small file system (mounting needs privileges);
  // final path /dev/full does not work either: the temporary goes beside it,
  // in /dev. A file size limit makes the writes fail the same way.
  ScratchDir dir;
  const fs::path file = dir.path / "noise.mp4";
  std::vector<std::uint8_t> noise(320 * 240 * 4);
  std::mt19937 random(7);
  std::string message;
  bool from_write = false;
  {
    FileSizeLimit limit(64 * 1024);
    try {
      VideoWriter writer(file, small());
      for (int i = 0; i < 45; ++i) {
        for (auto& byte : noise) byte = static_cast<std::uint8_t>(random());
        from_write = true;
        writer.write(noise.data(), 320 * 4);
      }
      from_write = false;
      writer.finish();
    } catch (const OutputError& e) {
      message = e.what();
    }
  }
  INFO(message);
  CHECK(from_write);  // the worker's error surfaced at the next write(), not only at finish()
  CHECK(message.find("noise.mp4") != std::string::npos);
  CHECK(message.find("size limit") != std::string::npos);
  CHECK(message.find('\n') == std::string::npos);
  CHECK(dir.empty());
}

TEST_CASE("the encoder's threads give way to the drawing thread, which keeps its priority", "[video]") {
  // Drawing is the one thread that cannot be split: with the encoder's
  // threads lower in priority, it runs whenever it has a frame to draw.
  auto nice_of = [](const std::string& thread) {
    std::ifstream stat("/proc/self/task/" + thread + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    // Fields after the command's closing parenthesis: state is field 3, nice field 19.
    std::istringstream rest(text.substr(text.rfind(')') + 2));
    std::string field;
    for (int i = 3; i <= 19; ++i) rest >> field;
    return std::stoi(field);
  };
  const std::string self = std::to_string(getpid());  // the main thread, which draws
  const int before = nice_of(self);
  REQUIRE(before < 19);  // else nothing could be lower
  const fs::path file = fs::temp_directory_path() / ("vibra_priority_" + std::to_string(getpid()) + ".mp4");
  {
    Frames frames(320, 240);
    VideoWriter writer(file, small());
    writer.write(frames.draw(0), frames.stride);
    int encoder_threads = 0;
    for (const auto& task : fs::directory_iterator("/proc/self/task")) {
      const std::string id = task.path().filename().string();
      if (id == self) continue;
      CHECK(nice_of(id) == std::min(19, before + 5));
      ++encoder_threads;
    }
    CHECK(encoder_threads >= 1);  // at least the thread that feeds x264
    CHECK(nice_of(self) == before);
    writer.finish();
  }
  CHECK(nice_of(self) == before);
  fs::remove(file);
}
