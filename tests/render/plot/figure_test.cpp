// Static figures: files of the requested size and format, data actually drawn
// in every panel, equal aspect, decimation in bounded memory, clean failures.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "render/draw/polyline/decimated_path.hpp"
#include "render/output/output_error.hpp"
#include "render/plot/axis.hpp"
#include "render/plot/figure.hpp"

using namespace vibra::render;
using vibra::test::ScratchDirectory;

namespace {
/// A decoded PNG and how many of its pixels in a row range are close to a colour.
struct Picture {
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface;
  explicit Picture(const std::string& path)
      : surface(cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy) {}
  int width() const { return cairo_image_surface_get_width(surface.get()); }
  int height() const { return cairo_image_surface_get_height(surface.get()); }

  /// Pixels of colour c in rows [y0, y1) (and columns [x0, x1), all by default).
  int count(const Color& c, int y0, int y1, int x0 = 0, int x1 = -1) const {
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    if (x1 < 0) x1 = width();
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const unsigned char* p = data + y * stride + 4 * x;  // BGRA on little-endian
        if (std::abs(p[2] - c.r * 255) < 30 && std::abs(p[1] - c.g * 255) < 30 && std::abs(p[0] - c.b * 255) < 30) ++n;
      }
    return n;
  }
};

std::string head_of(const std::string& path, size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  return bytes.substr(0, static_cast<size_t>(in.gcount()));
}

/// Two stacked panels: a streamed time series, and errors against dt on log-log axes.
Figure two_panel_figure(int width, int height) {
  Figure figure(width, height, "two panels");
  const int top = figure.add_panel({"<i>u</i>", "<i>t</i>", AxisScale::linear, AxisScale::linear, false, std::make_pair(0.0, 10.0)});
  Series& u = figure.add_curve(top, "", {palette::blue, 2.4}, 0, 10);
  for (int i = 0; i <= 100000; ++i) u.add(i * 1e-4, std::cos(2 * M_PI * i * 1e-4));
  const int bottom = figure.add_panel({"<i>E</i>", "Δ<i>t</i>", AxisScale::logarithmic, AxisScale::logarithmic});
  Series& e = figure.add_points(bottom, "error", {palette::vermillion, 2.4, false, true});
  for (double dt = 0.1; dt > 0.005; dt /= 2) e.add(dt, 3 * dt * dt);
  return figure;
}
}  // namespace

TEST_CASE("a PNG figure has the requested size and data drawn in every panel", "[figure]") {
  ScratchDirectory dir;
  two_panel_figure(900, 700).write(dir / "f.png");
  const Picture picture(dir / "f.png");
  REQUIRE(picture.width() == 900);
  REQUIRE(picture.height() == 700);
  // Each series has its own colour, so its pixels show where it was drawn.
  CHECK(picture.count(palette::blue, 0, 350) > 500);
  CHECK(picture.count(palette::blue, 350, 700) == 0);
  CHECK(picture.count(palette::vermillion, 350, 700) > 100);
  CHECK(picture.count(palette::vermillion, 0, 300) == 0);
}

TEST_CASE("SVG and PDF figures are vector files with their magic bytes", "[figure]") {
  ScratchDirectory dir;
  const Figure figure = two_panel_figure(800, 600);
  figure.write(dir / "f.svg");
  figure.write(dir / "f.PDF");
  CHECK(head_of(dir / "f.svg", 5) == "<?xml");
  CHECK(head_of(dir / "f.svg", 400).find("<svg") != std::string::npos);
  CHECK(head_of(dir / "f.PDF", 5) == "%PDF-");
}

TEST_CASE("a figure refuses other formats and leaves nothing behind when writing fails", "[figure]") {
  ScratchDirectory dir;
  const Figure figure = two_panel_figure(400, 300);
  CHECK_THROWS_WITH(figure.write(dir / "f.jpg"), Catch::Contains(".png, .svg or .pdf"));
  std::ofstream(dir / "file") << "in the way";
  CHECK_THROWS_AS(figure.write(dir / "file/f.png"), OutputError);
  std::filesystem::remove(dir / "file");
  std::filesystem::create_directory(dir / "taken.png");
  CHECK_THROWS_AS(figure.write(dir / "taken.png"), OutputError);
  std::filesystem::remove(dir / "taken.png");
  CHECK(dir.empty());
  figure.write(dir / "made/for/it/f.png");  // missing folders are made
  CHECK(std::filesystem::is_regular_file(dir / "made/for/it/f.png"));
  CHECK_THROWS_AS(Figure(0, 300), OutputError);
}

TEST_CASE("an equal-aspect panel draws a circle as round", "[figure]") {
  ScratchDirectory dir;
  Figure figure(1200, 500);
  const int p = figure.add_panel({"<i>y</i>", "<i>x</i>", AxisScale::linear, AxisScale::linear, true});
  Series& circle = figure.add_path(p, "", {palette::green, 2});
  for (int i = 0; i <= 2000; ++i) circle.add(std::cos(i * 2 * M_PI / 2000), std::sin(i * 2 * M_PI / 2000));
  figure.write(dir / "circle.png");
  CHECK(vibra::test::colour_aspect(dir / "circle.png", palette::green) == Approx(1).epsilon(0.03));
}

TEST_CASE("a streamed curve is decimated to the picture's columns", "[figure]") {
  Series curve(Series::Kind::curve, "", {}, 1000, 0, 1);
  for (int i = 0; i < 1'000'000; ++i) curve.add(i * 1e-6, std::sin(1000 * i * 1e-6));
  const auto lines = curve.polylines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].size() <= 4 * 1000);
  double lo = 1, hi = -1;
  for (const Point& p : lines[0]) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
  CHECK(lo == Approx(-1).margin(1e-6));  // the envelope keeps every peak
  CHECK(hi == Approx(1).margin(1e-6));
}

TEST_CASE("a path retraced many times costs what one trace costs", "[figure]") {
  auto trace = [](int turns) {
    DecimatedPath path;
    for (long long i = 0; i <= 10'000LL * turns; ++i) path.add(std::cos(i * 2 * M_PI / 10'000), std::sin(i * 2 * M_PI / 10'000));
    return path.segments();
  };
  const size_t once = trace(1), often = trace(200);
  CHECK(once > 1000);  // fine enough to look round
  CHECK(often <= once * 11 / 10);
}

TEST_CASE("a path that fills an area stays within its segment budget", "[figure]") {
  DecimatedPath path;
  // A Lissajous figure with incommensurate frequencies fills its square.
  for (long long i = 0; i < 3'000'000; ++i) path.add(std::sin(1e-2 * i), std::sin(std::sqrt(2.0) * 1e-2 * i));
  CHECK(path.segments() <= (1u << 19) + 1);
  CHECK(path.bounds().sizes().x() == Approx(2).epsilon(1e-3));
}

TEST_CASE("log axes label decades, linear axes of large values use powers of ten", "[figure]") {
  Axis decades(AxisScale::logarithmic);
  decades.fit(1e-3, 1e-1);
  std::vector<std::string> labels;
  for (const auto& t : decades.ticks(6))
    if (!t.label.empty()) labels.push_back(t.label);
  CHECK(labels == std::vector<std::string>{"0.001", "0.01", "0.1"});

  Axis wide(AxisScale::logarithmic);
  wide.fit(1e-9, 1e3);
  bool power = false;
  for (const auto& t : wide.ticks(6)) power |= t.label == "10<sup>\u22126</sup>";
  CHECK(power);

  Axis narrow(AxisScale::logarithmic);  // less than a decade: 2x and 5x are labelled
  narrow.fit(0.0125, 0.05);
  labels.clear();
  for (const auto& t : narrow.ticks(6))
    if (!t.label.empty()) labels.push_back(t.label);
  CHECK(labels == std::vector<std::string>{"0.02", "0.05"});

  Axis one_decade(AxisScale::logarithmic);  // one power of ten in view: 2x and 5x labelled beside it
  one_decade.fit(0.04, 0.3);
  labels.clear();
  for (const auto& t : one_decade.ticks(6))
    if (!t.label.empty()) labels.push_back(t.label);
  CHECK(labels == std::vector<std::string>{"0.05", "0.1", "0.2"});

  // A figure's tiny linear ticks each carry their power of ten, but zero is
  // plain 0: 0×10^-9 would read as a different number.
  Axis tiny;
  tiny.fit(-2e-9, 2e-9);
  int zeros = 0;
  for (const auto& t : tiny.ticks(6)) {
    INFO(t.value << " " << t.label);
    if (std::abs(t.value) < 1e-20) {
      CHECK(t.label == "0");
      ++zeros;
    } else {
      CHECK(t.label.find("×10<sup>−9</sup>") != std::string::npos);
    }
  }
  CHECK(zeros == 1);

  Axis large;
  large.fit(0, 1.2e8);
  bool scientific = false;
  for (const auto& t : large.ticks(6)) scientific |= t.label.find("×10<sup>8</sup>") != std::string::npos;
  CHECK(scientific);
  CHECK(large.fraction(large.lo()) == Approx(0));
  CHECK(large.fraction(large.hi()) == Approx(1));
}
