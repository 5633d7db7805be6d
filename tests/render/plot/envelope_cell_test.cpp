// A curve decimated to pixel columns is drawn through its samples' own x:
// steep curves stay slopes, peaks stay, and the order is the order of time.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "render/plot/column_envelope.hpp"
#include "render/plot/envelope_cell.hpp"
#include "render/plot/rolling_envelope.hpp"

using vibra::render::ColumnEnvelope;
using vibra::render::EnvelopeCell;
using vibra::render::Point;
using vibra::render::RollingEnvelope;

namespace {
std::vector<Point> visited(const EnvelopeCell& cell) {
  std::vector<Point> out;
  cell.visit_in_order([&](double x, double y) { out.emplace_back(x, y); });
  return out;
}

Point identity(double x, double y) { return {x, y}; }
}  // namespace

TEST_CASE("a column's points: first, the extremes in the order they happened, last, each once", "[envelope]") {
  EnvelopeCell rising;
  for (int i = 0; i < 10; ++i) rising.add(0.1 * i, 2.0 * i);
  // Monotone: the extremes are the first and last samples, at their own x.
  CHECK(visited(rising) == std::vector<Point>{{0.0, 0.0}, {0.9, 18.0}});

  EnvelopeCell peak_then_dip;
  for (auto [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {1, 5}, {2, -3}, {3, 1}}) peak_then_dip.add(x, y);
  CHECK(visited(peak_then_dip) == std::vector<Point>{{0, 0}, {1, 5}, {2, -3}, {3, 1}});

  EnvelopeCell dip_then_peak;
  for (auto [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {1, -2}, {2, 4}, {3, 4}}) dip_then_peak.add(x, y);
  CHECK(visited(dip_then_peak) == std::vector<Point>{{0, 0}, {1, -2}, {2, 4}, {3, 4}});

  EnvelopeCell one;
  one.add(0.25, 7);
  CHECK(visited(one) == std::vector<Point>{{0.25, 7}});
  CHECK(visited(EnvelopeCell{}).empty());
}

TEST_CASE("a steep curve over many columns is a slope through its samples, not a staircase", "[envelope]") {
  // u = 50 t over 10 columns, 20 samples a column: every point lies on the
  // line and no two consecutive points share an x (a vertical stroke).
  ColumnEnvelope whole(10, 0, 1);
  RollingEnvelope recent(0.1, 12);
  for (int i = 0; i < 200; ++i) {
    const double t = (i + 0.5) / 200;
    whole.add(t, 50 * t);
    recent.add(t, 50 * t);
  }
  for (const auto& points : {whole.polyline(9, identity), recent.polyline(0, 9, identity)}) {
    REQUIRE(points.size() == 20);  // first and last sample of each column
    for (size_t k = 0; k < points.size(); ++k) {
      CHECK(points[k].y() == Approx(50 * points[k].x()));
      if (k) CHECK(points[k].x() > points[k - 1].x());
    }
    CHECK(points.front().x() == Approx(0.0025));
    CHECK(points.back().x() == Approx(0.9975));
  }
}

TEST_CASE("a spike inside a column survives, at its own time", "[envelope]") {
  ColumnEnvelope e(4, 0, 4);
  for (int i = 0; i < 400; ++i) {
    const double t = i / 100.0;
    e.add(t, i == 123 ? 9.0 : std::sin(t));
  }
  const auto points = e.polyline(3, identity);
  bool spike = false;
  for (const Point& p : points) spike = spike || (p.x() == 1.23 && p.y() == 9.0);
  CHECK(spike);
  for (size_t k = 1; k < points.size(); ++k) CHECK(points[k].x() >= points[k - 1].x());
}

TEST_CASE("a coarsened envelope merges each run of columns in time order over the x range they cover", "[envelope]") {
  ColumnEnvelope fine(10, 0, 10);
  for (int i = 0; i < 10; ++i) fine.add(i + 0.5, i % 2 ? -i : i);  // 0, -1, 2, -3, ... one sample a column
  fine.add(4.2, std::nan(""));                                        // not a number: left out
  const ColumnEnvelope coarse = fine.coarsened(3);
  REQUIRE(coarse.columns() == 4);
  CHECK(coarse.x0() == 0);
  CHECK(coarse.x1() == 12);  // four whole columns of 3: the last reaches past the data
  CHECK(coarse.column_of(8.9) == 2);
  // Each cell's extremes in the order they happened: 0, -1, 2 (min first); -3, 4, -5 (max first); 6, -7, 8.
  CHECK(coarse.extremes_in_order(0) == std::pair{-1.0, 2.0});
  CHECK(coarse.extremes_in_order(1) == std::pair{4.0, -5.0});
  CHECK(coarse.extremes_in_order(2) == std::pair{-7.0, 8.0});
  CHECK(coarse.extremes_in_order(3) == std::pair{-9.0, -9.0});  // the last column holds 9.5 alone
}

TEST_CASE("an envelope finds the last used column before one, clears, and widens an empty x range", "[envelope]") {
  ColumnEnvelope e(8, 0, 8);
  e.add(1.5, 1), e.add(4.5, 2);
  CHECK(e.used_before(4) == 1);
  CHECK(e.used_before(5) == 4);
  CHECK(e.used_before(1) == -1);
  CHECK(e.used_before(100) == 4);  // past the end: the last used
  e.clear();
  CHECK(e.used_before(8) == -1);
  CHECK_FALSE(e.extremes_in_order(4));
  const ColumnEnvelope point(4, 5, 5);
  CHECK(point.x1() == 6);
  CHECK(point.column_of(5.6) == 2);
  CHECK(point.column_of(-1e9) == 0);
  CHECK(point.column_of(1e9) == 3);  // far past the range: the last column, not an overflowed int
}
