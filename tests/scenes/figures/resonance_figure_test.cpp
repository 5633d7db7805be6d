// Exercise 1.22's figure drawn from given points: one colour per beta, the exact curves dashed with their peaks where the formula puts them, the measured dots.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "render/draw/color.hpp"
#include "scenes/figures/resonance_figure.hpp"
#include "svg_shapes.hpp"

using vibra::test::same_colour;
using vibra::test::SvgShape;

namespace {
std::vector<SvgShape> drawn(const std::vector<vibra::ResonancePoint>& points) {
  const auto file = std::filesystem::temp_directory_path() / ("vibra_resonance_figure_" + std::to_string(getpid()) + ".svg");
  vibra::scenes::resonance_figure(points, 800, 500).write(file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(file);
  return vibra::test::svg_shapes(text.str());
}

struct Curve {
  double x0 = 1e9, x1 = -1e9, y_start = 0, peak_x = 0, peak_y = 1e9;  // SVG y grows downwards
  int dashed_paths = 0, markers = 0;
};

/// The dashed exact curve (drawn in pieces) and the dots of one colour.
Curve curve_of(const std::vector<SvgShape>& shapes, const vibra::render::Color& c) {
  Curve k;
  for (const auto& s : shapes) {
    if (s.curved && same_colour(s.fill, c)) ++k.markers;
    if (s.dasharray.empty() || !same_colour(s.stroke, c)) continue;
    ++k.dashed_paths;
    for (size_t i = 0; i < s.points(); ++i) {
      if (s.x(i) < k.x0) k.x0 = s.x(i), k.y_start = s.y(i);
      k.x1 = std::max(k.x1, s.x(i));
      if (s.y(i) < k.peak_y) k.peak_y = s.y(i), k.peak_x = s.x(i);
    }
  }
  return k;
}

/// Where 1/sqrt((1 - g^2)^2 + (beta g)^2) peaks, and its value there.
double peak_gamma(double beta) { return std::sqrt(1 - beta * beta / 2); }
double peak_amplitude(double beta) { return 1 / (beta * std::sqrt(1 - beta * beta / 4)); }
}  // namespace

TEST_CASE("the resonance figure draws each beta's exact curve dashed in its own colour, peaking where the formula says",
          "[resonance_figure]") {
  using namespace vibra::render::palette;
  // beta 0.1 first (blue), then 0.5 (vermillion); gamma up to 1.5, so the curves span 0 .. 1.65.
  const auto shapes = drawn({{0.1, 0.5, 1.3, 0}, {0.1, 1.0, 9.0, 0}, {0.1, 1.5, 0.8, 0}, {0.5, 0.5, 1.2, 0},
                             {0.5, 1.0, 2.0, 0}});
  const Curve sharp = curve_of(shapes, blue), broad = curve_of(shapes, vermillion);
  REQUIRE(sharp.dashed_paths > 0);
  REQUIRE(broad.dashed_paths > 0);
  // The measured dots, and one in the key for each beta.
  CHECK(sharp.markers == 3 + 1);
  CHECK(broad.markers == 2 + 1);
  // Both curves cover 0 .. 1.1 gamma_max.
  CHECK(sharp.x0 == Approx(broad.x0).margin(0.5));
  CHECK(sharp.x1 == Approx(broad.x1).margin(0.5));
  const auto gamma_at = [&](double x) { return 1.65 * (x - sharp.x0) / (sharp.x1 - sharp.x0); };
  CHECK(gamma_at(sharp.peak_x) == Approx(peak_gamma(0.1)).margin(0.008));
  CHECK(gamma_at(broad.peak_x) == Approx(peak_gamma(0.5)).margin(0.008));
  // A logarithmic amplitude axis: both start at 1, and the peaks' heights above it are in the ratio of their logs.
  CHECK(sharp.y_start == Approx(broad.y_start).margin(0.5));
  const double rise_ratio = (sharp.y_start - sharp.peak_y) / (broad.y_start - broad.peak_y);
  CHECK(rise_ratio == Approx(std::log(peak_amplitude(0.1)) / std::log(peak_amplitude(0.5))).epsilon(0.02));
}

