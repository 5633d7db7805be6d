// The analysis figures' series, read from the Figure itself: which curve is which, in which colour, through which points.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "render/draw/color.hpp"
#include "scenes/figures/analysis_figures.hpp"

using namespace vibra;

TEST_CASE("a compared convergence study: each scheme's errors in its colour, its reference slope lighter in the same",
          "[figure][analysis]") {
  // Two schemes, orders 1 and 2, errors exactly C dt^order: each slope line
  // runs through half the finest error at the finest dt with the scheme's order.
  std::vector<ModelConvergence> studies;
  for (const auto& [scheme, order] : {std::pair{"forward-euler", 1}, std::pair{"crank-nicolson", 2}}) {
    ModelConvergence study{scheme, order, {}, true};
    for (double dt : {0.1, 0.05, 0.025}) study.levels.push_back({dt, 3 * std::pow(dt, order), double(order)});
    studies.push_back(study);
  }
  const render::Figure figure = scenes::convergence_figure(studies, "convergence", 800, 600);
  const auto& series = figure.series_of(0);
  REQUIRE(series.size() == 4);  // per scheme: its errors, then its slope
  for (size_t k = 0; k < 2; ++k) {
    INFO(studies[k].scheme);
    const render::Series& errors = *series[2 * k];
    const render::Series& slope = *series[2 * k + 1];
    const render::Color own = render::palette::series(k);
    CHECK(errors.style().color == own);
    CHECK(errors.style().markers);
    // The slope: the scheme's hue, drawn lighter than its data.
    CHECK(slope.style().color.r == own.r);
    CHECK(slope.style().color.g == own.g);
    CHECK(slope.style().color.b == own.b);
    CHECK(slope.style().color.a == Approx(0.75));
    CHECK(slope.label() == "slope " + std::to_string(studies[k].order) + ", the order of " + studies[k].scheme);
    std::vector<std::pair<double, double>> points;
    slope.for_each_point([&](double dt, double e) { points.emplace_back(dt, e); });
    REQUIRE(points.size() == 2);
    const double order = studies[k].order;
    CHECK(points[1].first == 0.025);
    CHECK(points[1].second == Approx(0.5 * 3 * std::pow(0.025, order)));
    CHECK(std::log(points[0].second / points[1].second) / std::log(points[0].first / points[1].first) == Approx(order));
  }
}
