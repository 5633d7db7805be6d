// A scene's static outline marked once into the label placer's grid (render/labels/static_marks.hpp): the same
// cells as marking every shape each frame, the same spots for the labels, and a quick free() that agrees with taken().
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"
#include "render/labels/label_placer.hpp"
#include "render/labels/occupancy_grid.hpp"
#include "render/labels/static_marks.hpp"

using namespace vibra::render;

namespace {
constexpr double kMarksCell = 2, kMarksClearance = 1.5;
const PixelRect kMarksArea{0, 0, 320, 180};

/// An outline of `count` random strokes and boxes, the same for a seed.
Outline random_outline(unsigned seed, int count) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(-20, 340), y(-20, 200), size(1, 40);
  Outline outline;
  for (int i = 0; i < count; ++i) {
    if (i % 3 == 2) {
      outline.add_box({x(random), y(random), size(random), size(random)}, OutlineKind::body);
      continue;
    }
    const Point a(x(random), y(random));
    outline.add_polygon({a, a + Point(size(random), 0), a + Point(0, size(random))}, OutlineKind::drawing);
  }
  return outline;
}

/// Whether two grids have the same taken cells, cell by cell.
bool same_cells_taken(const OccupancyGrid& a, const OccupancyGrid& b) {
  for (double y = kMarksArea.y + 0.5; y < kMarksArea.y + kMarksArea.h; y += kMarksCell)
    for (double x = kMarksArea.x + 0.5; x < kMarksArea.x + kMarksArea.w; x += kMarksCell)
      if (a.taken({x, y, 0.5, 0.5}) != b.taken({x, y, 0.5, 0.5})) return false;
  return true;
}
}  // namespace

TEST_CASE("static marks: a grid of the static shapes copied, the rest marked, is the grid of every shape", "[labels]") {
  Outline outline = random_outline(3, 30);
  const Outline moving = random_outline(4, 12);
  outline.append(moving);
  OccupancyGrid every(kMarksArea, kMarksCell, kMarksClearance);
  for (const OutlineShape& shape : outline.shapes()) every.add(shape);

  StaticMarks marks;
  marks.reset(30);
  for (int frame = 0; frame < 2; ++frame) {  // marked at the first frame, copied at the second
    OccupancyGrid grid(kMarksArea, kMarksCell, kMarksClearance);
    const size_t first = marks.mark_into(grid, outline);
    REQUIRE(first == 30);
    for (size_t i = first; i < outline.shapes().size(); ++i) grid.add(outline.shapes()[i]);
    CHECK(same_cells_taken(grid, every));
  }
  // Only the static shapes came from the marks: without the moving ones, cells are missing.
  OccupancyGrid static_only(kMarksArea, kMarksCell, kMarksClearance);
  marks.mark_into(static_only, outline);
  CHECK_FALSE(same_cells_taken(static_only, every));
}

TEST_CASE("static marks: another area or scale is marked afresh, an outline shorter than the static part not at all",
          "[labels]") {
  const Outline outline = random_outline(5, 20);
  StaticMarks marks;
  marks.reset(20);
  OccupancyGrid small(kMarksArea, kMarksCell, kMarksClearance);
  REQUIRE(marks.mark_into(small, outline) == 20);
  const PixelRect wider{0, 0, 640, 360};
  OccupancyGrid large(wider, 2 * kMarksCell, 2 * kMarksClearance), expected(wider, 2 * kMarksCell, 2 * kMarksClearance);
  REQUIRE(marks.mark_into(large, outline) == 20);
  for (const OutlineShape& shape : outline.shapes()) expected.add(shape);
  for (double y = 1; y < wider.h; y += 2 * kMarksCell)
    for (double x = 1; x < wider.w; x += 2 * kMarksCell) REQUIRE(large.taken({x, y, 1, 1}) == expected.taken({x, y, 1, 1}));

  OccupancyGrid untouched(kMarksArea, kMarksCell, kMarksClearance);
  CHECK(marks.mark_into(untouched, random_outline(5, 10)) == 0);
  CHECK(untouched.taken(kMarksArea) == 0);
  marks.reset(0);
  CHECK(marks.mark_into(untouched, outline) == 0);
}

TEST_CASE("occupancy grid: free() says taken() == 0, for placed boxes and marked cells alike", "[labels]") {
  OccupancyGrid grid(kMarksArea, kMarksCell, kMarksClearance);
  const Outline outline = random_outline(6, 15);
  for (const OutlineShape& shape : outline.shapes()) grid.add(shape);
  grid.add_box({100, 60, 30, 12});
  std::mt19937 random(8);
  std::uniform_real_distribution<double> x(-30, 330), y(-30, 190), size(0.5, 60);
  int free_boxes = 0, taken_boxes = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const PixelRect box{x(random), y(random), size(random), size(random)};
    const bool free = grid.free(box);
    REQUIRE(free == (grid.taken(box) == 0));
    (free ? free_boxes : taken_boxes)++;
  }
  CHECK(free_boxes > 100);  // both answers were asked for
  CHECK(taken_boxes > 100);
  CHECK_FALSE(grid.free({105, 62, 2, 2}));  // inside the placed box alone
}

TEST_CASE("label placer: with the static shapes' marks, the labels take the same spots", "[labels]") {
  Canvas canvas = Canvas::image(640, 360);
  std::vector<LabelRequest> requests;
  for (int i = 0; i < 6; ++i)
    requests.push_back({"label " + std::to_string(i), {16, palette::ink}, Point(60 + 90 * i, 150 + 20 * (i % 3)),
                        Point(i % 2 ? 1 : -1, 0.3), 5});
  Outline base = random_outline(9, 60);
  base.append(random_outline(10, 20));
  StaticMarks marks;
  marks.reset(60);
  for (int frame = 0; frame < 2; ++frame) {
    Outline with_marks = base, without = base;
    const auto a = place_labels(canvas, requests, with_marks, {0, 0, 640, 360}, nullptr, &marks);
    const auto b = place_labels(canvas, requests, without, {0, 0, 640, 360});
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      CHECK(a[i].spot == b[i].spot);
      CHECK(a[i].free == b[i].free);
    }
  }
}

TEST_CASE("occupancy grid: shapes sharing a path are marked once, the same cells as each marked alone", "[labels]") {
  // A filled triangle and the stroke of its outline, an arrow's shaft on its
  // casing, equal widths twice over, a narrower stroke after a wider one, and
  // a path that differs by a bit from its neighbour's.
  std::mt19937 random(12);
  std::uniform_real_distribution<double> x(0, 320), y(0, 180);
  std::vector<OutlineShape> shapes;
  auto path = [&](double half_width, const std::vector<Point>& points, bool filled) {
    OutlineShape s;
    for (size_t i = 0; i + 1 < points.size(); ++i) s.segments.push_back({points[i], points[i + 1]});
    s.half_width = half_width;
    if (filled) s.polygons = {points};
    s.bounds = {-10, -10, 340, 200};
    shapes.push_back(s);
  };
  for (int trial = 0; trial < 40; ++trial) {
    const Point a(x(random), y(random)), b(x(random), y(random)), c(x(random), y(random));
    const std::vector<Point> p = {a, b, c, a};
    switch (trial % 5) {
      case 0: path(0, p, true), path(1.2, p, false); break;                 // fill, then its outline
      case 1: path(2.5, {a, b}, false), path(1, {a, b}, false); break;      // casing, then shaft
      case 2: path(1, {a, b}, false), path(1, {a, b}, false), path(1, {a, b}, false); break;
      case 3: path(1, {a, c}, false), path(3, {a, c}, false), path(2, {a, c}, false); break;
      default: path(2, {a, b}, false), path(1, {a, Point(b.x() + 1e-12, b.y())}, false); break;
    }
  }
  OccupancyGrid together(kMarksArea, kMarksCell, kMarksClearance), alone(kMarksArea, kMarksCell, kMarksClearance);
  together.add_shapes(shapes, 3);
  for (size_t i = 3; i < shapes.size(); ++i) alone.add(shapes[i]);
  CHECK(same_cells_taken(together, alone));
  // Without its edges a lone shape marks only its inside.
  OccupancyGrid inside(kMarksArea, kMarksCell, kMarksClearance);
  inside.add(shapes[0], false);
  OccupancyGrid whole(kMarksArea, kMarksCell, kMarksClearance);
  whole.add(shapes[0]);
  CHECK(inside.taken(kMarksArea) > 0);
  CHECK(inside.taken(kMarksArea) < whole.taken(kMarksArea));
}
