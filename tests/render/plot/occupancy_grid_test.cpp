// The label placer's occupancy grid (render/labels/occupancy_grid.hpp):
// which cells a stroke takes, against the definition cell by cell, and
// placed labels' boxes counted, and a box's count the sum of its cells'.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/labels/occupancy_grid.hpp"
#include "render/labels/outline.hpp"

using namespace vibra::render;

namespace {
constexpr double kCell = 3, kClearance = 2.25;
const PixelRect kArea{10, 20, 300, 200};

/// A box inside cell (column, row) alone: taken() says whether that cell is.
PixelRect inside_cell(int column, int row) {
  return {kArea.x + (column + 0.25) * kCell, kArea.y + (row + 0.25) * kCell, 0.5 * kCell, 0.5 * kCell};
}
}  // namespace

TEST_CASE("occupancy grid: a stroke takes exactly the cells whose centre lies within its reach", "[labels]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(-40, 350), y(-20, 260), width(0, 6);
  const int columns = int(std::ceil(kArea.w / kCell)), rows = int(std::ceil(kArea.h / kCell));
  for (int trial = 0; trial < 200; ++trial) {
    OutlineShape shape;
    Point a(x(random), y(random)), b(x(random), y(random));
    if (trial % 10 == 0) b = Point(x(random), a.y());  // horizontal
    if (trial % 10 == 1) b = Point(a.x(), y(random));  // vertical
    if (trial % 10 == 2) b = a;                        // a dot
    shape.segments = {{a, b}};
    shape.half_width = width(random);
    shape.bounds = {std::min(a.x(), b.x()) - shape.half_width, std::min(a.y(), b.y()) - shape.half_width,
                    std::abs(a.x() - b.x()) + 2 * shape.half_width, std::abs(a.y() - b.y()) + 2 * shape.half_width};
    OccupancyGrid grid(kArea, kCell, kClearance);
    grid.add(shape);
    const double reach = shape.half_width + kClearance + 0.7072 * kCell;
    int mismatched = 0;
    for (int row = 0; row < rows; ++row)
      for (int column = 0; column < columns; ++column) {
        const Point centre(kArea.x + (column + 0.5) * kCell, kArea.y + (row + 0.5) * kCell);
        const double distance = distance_to_segment(centre, a, b);
        if (std::abs(distance - reach) < 1e-9) continue;  // on the edge: either answer
        const bool expected = distance < reach, got = grid.taken(inside_cell(column, row)) > 0;
        mismatched += expected != got;
      }
    INFO("trial " << trial << ": (" << a.x() << ", " << a.y() << ") to (" << b.x() << ", " << b.y() << ")");
    CHECK(mismatched == 0);
  }
}

TEST_CASE("occupancy grid: a placed label's box is taken with its clearance, and nothing else", "[labels]") {
  OccupancyGrid grid(kArea, kCell, kClearance);
  const PixelRect label{100, 100, 40, 15};
  CHECK(grid.taken(label) == 0);
  grid.add_box(label);
  CHECK(grid.taken(label) > 0);
  CHECK(grid.taken({label.x + label.w + kClearance - 1, label.y, 5, 5}) > 0);  // within the clearance
  CHECK(grid.taken({label.x + label.w + kClearance + kCell + 1, label.y, 5, 5}) == 0);  // beyond it
  CHECK(grid.taken({label.x, label.y - kClearance - kCell - 6, 30, 5}) == 0);
  CHECK(grid.taken({0, 0, 1000, 1000}) == grid.taken({kArea.x, kArea.y, kArea.w, kArea.h}));
}

TEST_CASE("occupancy grid: a box's count is the sum of its cells', across every word boundary of the bit rows",
          "[labels]") {
  // 100 columns: rows of two 64-bit words, so boxes start and end on both
  // sides of column 64 and at the row's last column.
  const int columns = int(std::ceil(kArea.w / kCell)), rows = int(std::ceil(kArea.h / kCell));
  REQUIRE(columns > 64);
  OccupancyGrid grid(kArea, kCell, kClearance);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(0, 320), y(10, 230);
  for (int k = 0; k < 12; ++k) {
    OutlineShape shape;
    const Point a(x(random), y(random)), b(x(random), y(random));
    shape.segments = {{a, b}};
    shape.half_width = 0.5;
    shape.bounds = {std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::abs(a.x() - b.x()) + 1, std::abs(a.y() - b.y()) + 1};
    grid.add(shape);
  }
  std::vector<int> taken(static_cast<size_t>(columns) * rows);
  for (int row = 0; row < rows; ++row)
    for (int column = 0; column < columns; ++column) taken[row * columns + column] = grid.taken(inside_cell(column, row)) > 0;
  for (int first : {0, 1, 62, 63, 64, 65, 90})
    for (int last : {first, 63, 64, 65, 98, columns - 1}) {
      if (last < first) continue;
      long long expected = 0;
      for (int row = 5; row <= 40; ++row)
        for (int column = first; column <= last; ++column) expected += taken[row * columns + column];
      const PixelRect box{kArea.x + (first + 0.25) * kCell, kArea.y + 5.25 * kCell, (last - first + 0.5) * kCell, 35.5 * kCell};
      INFO("columns " << first << " to " << last);
      CHECK(grid.taken(box) == expected);
    }
}

TEST_CASE("occupancy grid: a polygon's inside takes, on each row, the cells from each odd crossing to the next",
          "[labels]") {
  // Even-odd along each row's centre line: an edge crosses it when one end is
  // above and the other not; the cells holding the crossings are taken, and
  // all between. Concave, crossing themselves, with level edges, and a road
  // (a point a column, down to a flat bottom), partly outside the grid.
  const int columns = int(std::ceil(kArea.w / kCell)), rows = int(std::ceil(kArea.h / kCell));
  std::mt19937 random(21);
  std::uniform_real_distribution<double> x(-30, 340), y(0, 240), unit(0, 1);
  for (int trial = 0; trial < 120; ++trial) {
    std::vector<Point> polygon;
    if (trial % 4 == 3) {
      for (double px = -20; px <= 330; px += 1 + 2 * unit(random)) polygon.emplace_back(px, 120 + 30 * std::sin(px / 17));
      polygon.emplace_back(polygon.back().x(), 230), polygon.emplace_back(polygon.front().x(), 230);
    } else {
      // Half the corners on a row's centre line, where an edge starts or ends exactly on the row.
      auto on_a_row = [&](double v) { return kArea.y + (std::floor((v - kArea.y) / kCell) + 0.5) * kCell; };
      for (int k = 3 + int(random() % 9); k > 0; --k)
        polygon.emplace_back(x(random), trial % 4 == 2 && k % 2 ? on_a_row(150) : k % 2 ? on_a_row(y(random)) : y(random));
    }
    OutlineShape shape;
    shape.polygons = {polygon};
    shape.bounds = {-40, -10, 400, 270};
    OccupancyGrid grid(kArea, kCell, kClearance);
    grid.add(shape, false);
    int mismatched = 0;
    for (int row = 0; row < rows; ++row) {
      const double cy = kArea.y + (row + 0.5) * kCell;
      std::vector<double> crossings;
      for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point &p = polygon[i], &q = polygon[j];
        if ((p.y() > cy) != (q.y() > cy)) crossings.push_back(p.x() + (cy - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
      }
      std::sort(crossings.begin(), crossings.end());
      for (int column = 0; column < columns; ++column) {
        bool expected = false;
        for (size_t k = 0; k + 1 < crossings.size(); k += 2)
          expected |= std::floor((crossings[k] - kArea.x) / kCell) <= column &&
                      column <= std::floor((crossings[k + 1] - kArea.x) / kCell);
        mismatched += expected != (grid.taken(inside_cell(column, row)) > 0);
      }
    }
    INFO("trial " << trial << ", " << polygon.size() << " points");
    CHECK(mismatched == 0);
  }
}
