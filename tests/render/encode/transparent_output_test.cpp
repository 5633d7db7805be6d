// --transparent: no background. The alpha plane is decoded back from every
// format that carries it (PNG, VP9 in WebM, ProRes 4444 in MOV, SVG and PDF
// rasterised) and found transparent where nothing is drawn and opaque on the
// drawing; formats that cannot carry alpha refuse it, naming those that can.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "argb_image.hpp"
#include "cli_support.hpp"
#include "render/encode/pixels/yuva_converter.hpp"

using vibra::render::YuvaConverter;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {
// 640x360: the smallest frame that is not a thumbnail, where lines keep their
// full width (a thumbnail's are thinner than a pixel, never solid).
constexpr int kWidth = 640, kHeight = 360;
const std::string kShortTransparent = " --size 640x360 --set periods=0.25 -q --transparent ";

/// How much of a picture's alpha is empty, and whether anything is solid.
struct AlphaSummary {
  double transparent_fraction = 0;  ///< alpha <= 2%
  int opaque_pixels = 0;            ///< alpha >= 98%
  double corner = -1;               ///< alpha at the top-left pixel, 0..1
};

template <class AlphaAt>
AlphaSummary summarise(int width, int height, double full, AlphaAt alpha_at) {
  AlphaSummary s;
  long long clear = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double a = alpha_at(x, y) / full;
      clear += a <= 0.02;
      s.opaque_pixels += a >= 0.98;
    }
  s.transparent_fraction = double(clear) / (double(width) * height);
  s.corner = alpha_at(0, 0) / full;
  return s;
}

AlphaSummary png_alpha(const std::string& path) {
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> s(cairo_image_surface_create_from_png(path.c_str()),
                                                                   cairo_surface_destroy);
  REQUIRE(cairo_surface_status(s.get()) == CAIRO_STATUS_SUCCESS);
  REQUIRE(cairo_image_surface_get_format(s.get()) == CAIRO_FORMAT_ARGB32);  // RGB PNGs load as RGB24
  const unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get());
  return summarise(cairo_image_surface_get_width(s.get()), cairo_image_surface_get_height(s.get()), 255,
                   [&](int x, int y) { return double(data[y * stride + 4 * x + 3]); });
}

/// The drawing covers a part of the frame; the rest is see-through.
void check_overlay(const AlphaSummary& s) {
  CHECK(s.corner <= 0.02);
  CHECK(s.transparent_fraction > 0.5);
  CHECK(s.opaque_pixels > 150);  // thin lines at 640x360: a few hundred solid pixels
}
}  // namespace

TEST_CASE("YuvaConverter un-premultiplies and keeps alpha, 8-bit 4:2:0 and 10-bit 4:4:4", "[transparent]") {
  vibra::test::ArgbImage image(2, 2);
  image.at(0, 0) = 0x00000000;  // nothing drawn
  image.at(1, 0) = 0xffffffff;  // opaque white
  image.at(0, 1) = 0x80800000;  // half-covered red, premultiplied: straight red
  image.at(1, 1) = 0xff0000ff;  // opaque blue
  {
    std::uint8_t y[4], u[1], v[1], a[4];
    YuvaConverter(YuvaConverter::Layout::yuva420p, 2, 2).convert(image.bytes(), image.stride, {{y, u, v, a}, {2, 1, 1, 2}});
    CHECK(int(a[0]) == 0);
    CHECK(int(a[1]) == 255);
    CHECK(int(a[2]) == 128);
    CHECK(int(y[0]) == 16);   // empty: black
    CHECK(int(y[1]) == 235);  // white
    CHECK(int(y[2]) == 16 + int(0.2126 * 219 + 0.5));  // straight red, not darkened by its alpha
    // Chroma weighs colours by alpha: the empty pixel does not pull it to grey.
    CHECK(int(v[0]) > 128);
    CHECK(int(u[0]) > 128);
  }
  {
    std::uint16_t y[4], u[4], v[4], a[4];
    auto bytes = [](std::uint16_t* p) { return reinterpret_cast<std::uint8_t*>(p); };
    YuvaConverter(YuvaConverter::Layout::yuva444p10, 2, 2)
        .convert(image.bytes(), image.stride, {{bytes(y), bytes(u), bytes(v), bytes(a)}, {4, 4, 4, 4}});
    CHECK(a[0] == 0);
    CHECK(a[1] == 1023);
    CHECK(y[1] == 940);
    CHECK(u[1] == 512);
    CHECK(v[1] == 512);
    CHECK(v[2] == 512 + 448);  // pure red: the most red chroma
    CHECK(u[3] == 512 + 448);  // pure blue: the most blue chroma
  }
}

TEST_CASE("transparent PNG frames and stills have alpha: clear around, solid on the drawing", "[transparent][render]") {
  ScratchDirectory dir;
  REQUIRE(run_vibra("render" + kShortTransparent + "-o " + (dir / "f_%03d.png")).exit_code == 0);
  check_overlay(png_alpha(dir / "f_000.png"));
  check_overlay(png_alpha(dir / "f_007.png"));
  REQUIRE(run_vibra("render" + kShortTransparent + "--at 0.5 -o " + (dir / "still.png")).exit_code == 0);
  check_overlay(png_alpha(dir / "still.png"));
  REQUIRE(run_vibra("render --size 640x360 --set periods=0.25 -q --at 0.5 -o " + (dir / "opaque.png")).exit_code == 0);
  {  // without --transparent: opaque, as before
    std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> opaque(
        cairo_image_surface_create_from_png((dir / "opaque.png").c_str()), cairo_surface_destroy);
    CHECK(cairo_image_surface_get_format(opaque.get()) == CAIRO_FORMAT_RGB24);
  }
  REQUIRE(run_vibra("plot undamped --set periods=1 --size 640x360 -q --transparent -o " + (dir / "plot.png")).exit_code == 0);
  check_overlay(png_alpha(dir / "plot.png"));
}

TEST_CASE("transparent WebM is VP9 with an alpha plane that decodes", "[transparent][render][video]") {
  ScratchDirectory dir;
  const std::string webm = dir / "overlay.webm";
  REQUIRE(run_vibra("render" + kShortTransparent + "-o " + webm).exit_code == 0);
  // FFmpeg's own VP9 decoder drops alpha; libvpx reads the alpha track.
  const std::string frame = vibra::test::shell("ffmpeg -v error -c:v libvpx-vp9 -i '" + webm +
                                        "' -frames:v 1 -pix_fmt yuva420p -f rawvideo -");
  const std::size_t luma = kWidth * kHeight, chroma = (kWidth / 2) * (kHeight / 2);
  REQUIRE(frame.size() == 2 * luma + 2 * chroma);
  const auto* alpha = reinterpret_cast<const std::uint8_t*>(frame.data()) + luma + 2 * chroma;
  check_overlay(summarise(kWidth, kHeight, 255, [&](int x, int y) { return double(alpha[y * kWidth + x]); }));
}

TEST_CASE("transparent MOV is ProRes 4444 with a 10-bit alpha plane", "[transparent][render][video]") {
  ScratchDirectory dir;
  const std::string mov = dir / "overlay.mov";
  REQUIRE(run_vibra("render" + kShortTransparent + "-o " + mov).exit_code == 0);
  const std::string probe = vibra::test::shell("ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,profile,pix_fmt "
                                        "-of flat=s=_ '" + mov + "'");
  // Encoded from yuva444p10le; FFmpeg's ProRes decoder reports 4444 as 12-bit.
  CHECK_THAT(probe, Catch::Contains("codec_name=\"prores\"") && Catch::Contains("profile=\"4444\"") &&
                        Catch::Contains("pix_fmt=\"yuva444p1"));
  const std::string frame = vibra::test::shell("ffmpeg -v error -i '" + mov + "' -frames:v 1 -pix_fmt yuva444p10le -f rawvideo -");
  const std::size_t plane = kWidth * kHeight * 2;
  REQUIRE(frame.size() == 4 * plane);
  const auto* alpha = reinterpret_cast<const std::uint16_t*>(frame.data() + 3 * plane);
  check_overlay(summarise(kWidth, kHeight, 1023, [&](int x, int y) { return double(alpha[y * kWidth + x]); }));
}

TEST_CASE("transparent SVG and PDF have no background rectangle", "[transparent][render]") {
  ScratchDirectory dir;
  for (const char* ext : {".svg", ".pdf"}) {
    INFO(ext);
    const std::string clear = dir / ("clear" + std::string(ext)), paper = dir / ("paper" + std::string(ext));
    REQUIRE(run_vibra("render" + kShortTransparent + "--at 0.5 -o " + clear).exit_code == 0);
    REQUIRE(run_vibra("render --size 640x360 --set periods=0.25 -q --at 0.5 -o " + paper).exit_code == 0);
    // Rasterised with a transparent page, as an editor places it.
    for (const auto& [file, transparent] : {std::pair{clear, true}, std::pair{paper, false}}) {
      const std::string png = file + ".png";
      const std::string command = std::string(ext) == ".svg"
                                      ? "true"  // cairo cannot read SVG: see the text check below
                                      : "pdftocairo -png -transp -singlefile -r 72 '" + file + "' '" + file + "'";
      REQUIRE(std::system(command.c_str()) == 0);
      if (std::string(ext) == ".pdf") {
        const AlphaSummary s = png_alpha(png);
        if (transparent)
          check_overlay(s);
        else
          CHECK(s.transparent_fraction < 0.01);
      }
    }
  }
  // Cairo paints the background as a rectangle covering the page; without
  // it, no element fills the whole 640x360 page.
  std::ifstream in(dir / "clear.svg");
  const std::string svg{std::istreambuf_iterator<char>(in), {}};
  std::ifstream in_paper(dir / "paper.svg");
  const std::string paper_svg{std::istreambuf_iterator<char>(in_paper), {}};
  const std::string page_fill = "<rect x=\"0\" y=\"0\" width=\"640\" height=\"360\"";
  CHECK(paper_svg.find(page_fill) != std::string::npos);
  CHECK(svg.find(page_fill) == std::string::npos);
  CHECK(svg.size() < paper_svg.size());
}

TEST_CASE("formats without alpha refuse --transparent, naming those with it", "[transparent][cli]") {
  for (const char* args : {"render --transparent -o OUT.mp4", "render --transparent -o OUT.gif",
                           "render --transparent -o OUT.mkv", "render --transparent --codec vp8 -o OUT.webm",
                           "render --transparent -o OUT.html"}) {
    INFO(args);
    vibra::test::check_refused(args, ".webm");
  }
  vibra::test::check_refused("render --transparent -o OUT.mp4", "cannot be transparent");
  vibra::test::check_refused("render --transparent -o OUT.mp4", ".mov");
  vibra::test::check_refused("render --transparent -o - --format nut", "cannot go to standard output");
}
