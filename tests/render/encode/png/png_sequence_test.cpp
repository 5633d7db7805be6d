// Tests of PNG sequences: frame patterns, padding and the written frames.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "argb_image.hpp"
#include "cli_support.hpp"
#include "render/encode/png/png_sequence.hpp"
#include "render/output/output_error.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using vibra::render::encode_png;
using vibra::render::FramePattern;
using vibra::render::OutputError;
using vibra::render::pack_png_scanlines;
using vibra::render::parse_frame_pattern;
using vibra::render::PngScanlines;
using vibra::render::PngSequenceWriter;
using vibra::test::ScratchDirectory;

namespace {

using Image = vibra::test::ArgbImage;

std::uint32_t argb(unsigned a, unsigned r, unsigned g, unsigned b) { return a << 24 | r << 16 | g << 8 | b; }

/// An opaque frame whose colour depends on `seed`, with some structure to compress.
Image opaque_frame(int w, int h, unsigned seed) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = argb(255, (x * 7 + seed) & 255, (y * 13) & 255, (seed * 31) & 255);
  return image;
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Decodes with Cairo's own PNG reader, as an independent check.
Image decode(const fs::path& path) {
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  REQUIRE(cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS);
  Image image(cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface));
  const bool opaque = cairo_image_surface_get_format(surface) == CAIRO_FORMAT_RGB24;
  const std::uint8_t* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&image.at(0, y), data + size_t(y) * stride, size_t(image.width) * 4);
    if (opaque)  // RGB24 leaves the top byte unspecified
      for (int x = 0; x < image.width; ++x) image.at(x, y) |= 0xff000000;
  }
  cairo_surface_destroy(surface);
  return image;
}

Image round_trip(const ScratchDirectory& dir, const Image& image) {
  const std::vector<std::uint8_t> png = encode_png(image.bytes(), image.width, image.height, image.stride);
  const fs::path path = dir / "round_trip.png";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  return decode(path);
}

std::set<std::string> file_names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

/// Writes `frames` frames (frame k is opaque_frame(.., k)) and finishes.
void write_sequence(const std::string& pattern, int frames, int threads) {
  PngSequenceWriter writer(parse_frame_pattern(pattern, frames), 24, 16, threads);
  for (int k = 0; k < frames; ++k) writer.write(opaque_frame(24, 16, k).bytes(), 24 * 4);
  writer.finish();
  CHECK(writer.frames_written() == frames);
}

}  // namespace

TEST_CASE("frame pattern: a bare directory means DIR/tmp_%04d.png", "[png]") {
  ScratchDirectory dir;
  for (const std::string& user : {dir.path.string(), dir.path.string() + "/"}) {
    const FramePattern p = parse_frame_pattern(user, 10);
    CHECK(p.prefix == "tmp_");
    CHECK(p.suffix == ".png");
    CHECK(p.digits == 4);
    CHECK(p.name(7) == dir.path / "tmp_0007.png");
  }
}

TEST_CASE("frame pattern: %04d and %d", "[png]") {
  ScratchDirectory dir;
  const FramePattern four = parse_frame_pattern(dir / "f_%04d.png", 10);
  CHECK(four.directory == dir.path);
  CHECK(four.prefix == "f_");
  CHECK(four.digits == 4);
  CHECK(four.name(42) == dir.path / "f_0042.png");
  CHECK(parse_frame_pattern(dir / "f_%04d_left.PNG", 10).name(3) == dir.path / "f_0003_left.PNG");
  CHECK(parse_frame_pattern(dir / "%d.png", 10).name(7) == dir.path / "7.png");
  CHECK(parse_frame_pattern(dir / "%d.png", 100).name(7) == dir.path / "07.png");  // %d widens too
}

TEST_CASE("frame pattern: digits widen so names always sort", "[png]") {
  ScratchDirectory dir;
  CHECK(parse_frame_pattern(dir / "f_%04d.png", 10000).digits == 4);  // last index 9999
  const FramePattern wide = parse_frame_pattern(dir / "f_%04d.png", 10001);
  CHECK(wide.digits == 5);
  CHECK(wide.name(3) == dir.path / "f_00003.png");
  CHECK(parse_frame_pattern(dir.path.string(), 123456).digits == 6);
}

TEST_CASE("frame pattern: bad patterns throw OutputError", "[png]") {
  ScratchDirectory dir;
  for (const char* bad : {"f.png", "f_%04d.jpg", "f_%04d.png.txt", "f_%04d_%04d.png", "f_%5d.png", "f_%04x.png",
                          "f_%s.png", "f_%.png", "f_%0d.png", "f_%019d.png", "f_%%.png"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_frame_pattern(dir / bad, 10), OutputError);
  }
  CHECK_THROWS_AS(parse_frame_pattern(dir / "%04d/f.png", 10), OutputError);  // % in the directory
  CHECK_THROWS_AS(parse_frame_pattern("", 10), OutputError);
  CHECK_THROWS_WITH(parse_frame_pattern(dir / "f.png", 10), Contains("%d"));
}

TEST_CASE("frame pattern: a missing directory is for the sink to create, a file in its place throws", "[png]") {
  ScratchDirectory dir;
  CHECK(parse_frame_pattern(dir / "missing/f_%04d.png", 10).directory == dir.path / "missing");
  CHECK(parse_frame_pattern(dir / "missing", 10).name(3) == dir.path / "missing/tmp_0003.png");
  CHECK(dir.empty());  // parsing creates nothing
  std::ofstream(dir / "file") << "x";
  CHECK_THROWS_WITH(parse_frame_pattern(dir / "file/f_%04d.png", 10), Contains("not a directory"));
  CHECK_THROWS_WITH(parse_frame_pattern(dir / "file", 10), Contains("not a directory"));
}

TEST_CASE("encode_png: an opaque image decodes to the same pixels, as RGB", "[png]") {
  ScratchDirectory dir;
  Image image(37, 23, 3);  // padded rows: the stride is honoured
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) image.at(x, y) = argb(255, x * 7, y * 11, (x * y) & 255);
  const std::vector<std::uint8_t> png = encode_png(image.bytes(), image.width, image.height, image.stride);
  CHECK(png[25] == 2);  // IHDR colour type: truecolour, no alpha
  const Image back = round_trip(dir, image);
  REQUIRE(back.width == image.width);
  REQUIRE(back.height == image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) REQUIRE(back.at(x, y) == image.at(x, y));
}

TEST_CASE("pack_png_scanlines: every width from 1 to 19 packs R, G, B in order, and one translucent pixel anywhere makes RGBA",
          "[png]") {
  for (int width = 1; width <= 19; ++width) {
    Image image(width, 2, 1);
    for (int x = 0; x < width; ++x) image.at(x, 0) = image.at(x, 1) = argb(255, 10 + x, 100 + x, 200 + x);
    PngScanlines packed;
    pack_png_scanlines(image.bytes(), width, 2, image.stride, packed);
    INFO("width " << width);
    REQUIRE(packed.opaque);
    REQUIRE(packed.bytes.size() == 2 * (3 * std::size_t(width) + 1));
    for (int y = 0; y < 2; ++y) {
      const std::uint8_t* row = packed.bytes.data() + y * (3 * width + 1);
      CHECK(row[0] == 0);  // filter None
      for (int x = 0; x < width; ++x) CHECK((row[1 + 3 * x] == 10 + x && row[2 + 3 * x] == 100 + x && row[3 + 3 * x] == 200 + x));
    }
    for (int at = 0; at < width; ++at) {  // the alpha check sees every pixel, the vector loop's and the tail's
      Image translucent = image;
      translucent.at(at, 1) = argb(128, 5, 50, 100);
      pack_png_scanlines(translucent.bytes(), width, 2, translucent.stride, packed);
      INFO("translucent pixel at " << at);
      CHECK_FALSE(packed.opaque);
      CHECK(packed.bytes.size() == 2 * (4 * std::size_t(width) + 1));
    }
  }
}

TEST_CASE("encode_png: premultiplied alpha round-trips within 1", "[png]") {
  ScratchDirectory dir;
  // Every alpha (row) with every valid premultiplied channel value c <= alpha.
  Image image(256, 256);
  for (unsigned a = 0; a < 256; ++a)
    for (unsigned c = 0; c < 256; ++c) {
      const unsigned v = std::min(c, a);
      image.at(int(c), int(a)) = argb(a, v, v / 2, a - v);
    }
  const std::vector<std::uint8_t> png = encode_png(image.bytes(), image.width, image.height, image.stride);
  CHECK(png[25] == 6);  // IHDR colour type: truecolour with alpha
  const Image back = round_trip(dir, image);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int shift : {0, 8, 16, 24}) {
        const int want = int(image.at(x, y) >> shift & 255), got = int(back.at(x, y) >> shift & 255);
        INFO("x " << x << " y " << y << " shift " << shift);
        REQUIRE(std::abs(got - want) <= (shift == 24 ? 0 : 1));
      }
}

TEST_CASE("png sequence: every frame goes to its own name", "[png]") {
  ScratchDirectory dir;
  write_sequence(dir / "f_%03d.png", 5, 2);
  CHECK(file_names(dir.path) == std::set<std::string>{"f_000.png", "f_001.png", "f_002.png", "f_003.png", "f_004.png"});
  for (int k = 0; k < 5; ++k) {
    const Image want = opaque_frame(24, 16, k), got = decode(dir.path / ("f_00" + std::to_string(k) + ".png"));
    CHECK(got.words == want.words);
  }
}

TEST_CASE("png sequence: identical bytes for any thread count", "[png]") {
  ScratchDirectory one, two;
  write_sequence(one / "f_%04d.png", 6, 1);
  write_sequence(two / "f_%04d.png", 6, 2);
  for (int k = 0; k < 6; ++k) {
    const std::string name = "f_000" + std::to_string(k) + ".png";
    const Image frame = opaque_frame(24, 16, k);
    const std::vector<std::uint8_t> bytes = read_bytes(one.path / name);
    CHECK(bytes == encode_png(frame.bytes(), 24, 16, 24 * 4));
    CHECK(bytes == read_bytes(two.path / name));
  }
}

TEST_CASE("png sequence: an unfinished writer removes the frames it wrote, and leaves earlier ones", "[png]") {
  ScratchDirectory dir;
  std::ofstream(dir / "f_009.png") << "an earlier run's frame";  // not this run's: stays
  std::ofstream(dir / "f_000.png") << "an earlier run's frame 0";  // replaced only by a finished run
  auto files = [&] {
    size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir.path)) n += e.is_regular_file();
    return n;
  };
  {
    PngSequenceWriter writer(parse_frame_pattern(dir / "f_%03d.png", 10), 24, 16, 2);
    for (int k = 0; k < 4; ++k) writer.write(opaque_frame(24, 16, k).bytes(), 24 * 4);
    // Let at least one frame reach the disk, so the cleanup has work to do.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (files() == 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    REQUIRE(files() > 2);
    CHECK(vibra::test::read_file(dir.path / "f_000.png") == "an earlier run's frame 0");
  }
  CHECK(file_names(dir.path) == std::set<std::string>{"f_000.png", "f_009.png"});
  CHECK(vibra::test::read_file(dir.path / "f_000.png") == "an earlier run's frame 0");
}

TEST_CASE("png sequence: a write failure surfaces as OutputError and nothing remains", "[png]") {
  ScratchDirectory dir;
  fs::create_directory(dir / "frames");
  {
    PngSequenceWriter writer(parse_frame_pattern(dir / "frames/f_%03d.png", 3), 24, 16, 2);
    fs::remove_all(dir / "frames");  // the directory vanishes mid-run
    const Image frame = opaque_frame(24, 16, 0);
    CHECK_THROWS_AS(
        [&] {
          for (int k = 0; k < 3; ++k) writer.write(frame.bytes(), 24 * 4);
          writer.finish();
        }(),
        OutputError);
  }
  CHECK(dir.empty());
}
