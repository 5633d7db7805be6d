// The software stroke (render/draw/stroke_raster) against Cairo's own: the
// same pixels within antialiasing, exactly the same where it matters for
// frame truth (a stroke grown strip by strip), and Cairo's stroke wherever
// the software one does not apply.
#include <catch2/catch.hpp>
#include <cairo-svg.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "render/draw/stroke_raster.hpp"

using vibra::render::raster_stroke;

namespace {
constexpr int kSurfaceWidth = 160, kSurfaceHeight = 120;

/// A white ARGB32 surface and its context.
struct Surface {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSurfaceWidth, kSurfaceHeight);
  cairo_t* cr = cairo_create(surface);
  Surface() {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_GOOD);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);  // as the canvas draws
  }
  ~Surface() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Surface(const Surface&) = delete;
  std::uint32_t at(int x, int y) {
    cairo_surface_flush(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    return reinterpret_cast<const std::uint32_t*>(data + y * cairo_image_surface_get_stride(surface))[x];
  }
};

int channel(std::uint32_t pixel, int c) { return int((pixel >> (8 * c)) & 0xff); }

/// How two pictures differ: the largest difference of a channel, how many
/// pixels differ by more than 96 (more than antialiasing's approximations),
/// how many have ink, and the ink (255 - green, summed) of each.
struct Difference {
  int largest = 0, far_off = 0, inked = 0;
  double ink_a = 0, ink_b = 0;
};

Difference compare(Surface& a, Surface& b) {
  Difference d;
  for (int y = 0; y < kSurfaceHeight; ++y)
    for (int x = 0; x < kSurfaceWidth; ++x) {
      const std::uint32_t pa = a.at(x, y), pb = b.at(x, y);
      int largest = 0;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(channel(pa, c) - channel(pb, c)));
      d.largest = std::max(d.largest, largest);
      d.far_off += largest > 96;
      d.inked += pb != 0xffffffffu;
      d.ink_a += 255 - channel(pa, 1), d.ink_b += 255 - channel(pb, 1);
    }
  return d;
}

/// Strokes what `setup` prepares once in software and once by Cairo; the
/// software stroke must apply.
Difference both_ways(const std::function<void(cairo_t*)>& setup) {
  Surface ours, cairos;
  setup(ours.cr);
  setup(cairos.cr);
  REQUIRE(raster_stroke(ours.cr));
  CHECK_FALSE(cairo_has_current_point(ours.cr));  // the path is used up, as cairo_stroke leaves it
  cairo_stroke(cairos.cr);
  return compare(ours, cairos);
}

void polyline(cairo_t* cr, const std::vector<std::pair<double, double>>& points) {
  cairo_new_path(cr);
  for (const auto& [x, y] : points) cairo_line_to(cr, x, y);
}
}  // namespace

TEST_CASE("a software stroke matches Cairo's within antialiasing, for every cap, dash and width",
          "[render][stroke_raster]") {
  std::mt19937 random(20261126);
  std::uniform_real_distribution<double> x(-20, kSurfaceWidth + 20), y(-20, kSurfaceHeight + 20), unit(0, 1);
  int drawn = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::pair<double, double>> points(2 + random() % 10);
    for (auto& p : points) p = {x(random), y(random)};
    const double width = 1 + 7 * unit(random);
    const auto cap = static_cast<cairo_line_cap_t>(random() % 3);
    const bool closed = random() % 4 == 0, dashed = random() % 3 == 0;
    const double dashes[] = {2 + 10 * unit(random), 2 + 10 * unit(random), 1 + 5 * unit(random)};
    const int dash_count = 1 + int(random() % 3);
    const double offset = 30 * unit(random) - 10, alpha = trial % 2 ? 1 : 0.2 + 0.8 * unit(random);
    INFO("trial " << trial << ": " << points.size() << " points, width " << width << ", cap " << cap << ", closed "
                  << closed << ", dashes " << (dashed ? dash_count : 0));
    const Difference d = both_ways([&](cairo_t* cr) {
      polyline(cr, points);
      if (closed) cairo_close_path(cr);
      cairo_set_line_width(cr, width);
      cairo_set_line_cap(cr, cap);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      if (dashed) cairo_set_dash(cr, dashes, dash_count, offset);
      cairo_set_source_rgba(cr, 0.1, 0.3, 0.7, alpha);
    });
    // Coverage by distance differs from Cairo's by area at slanted edges and
    // line ends, by a fraction of a pixel's worth. Where these random paths
    // cross themselves or turn back, a pixel that two parts each cover in
    // part gets the larger part here and about their sum from Cairo: a few
    // pixels, at crossings. A missing or extra piece of line would be many.
    CHECK(d.far_off <= std::max(6, d.inked / 50));
    CHECK(std::abs(d.ink_a - d.ink_b) <= 0.03 * d.ink_b + 2 * 255);
    ++drawn;
  }
  CHECK(drawn == 300);
}

TEST_CASE("a software stroke's zero-length pieces with round caps are dots, as Cairo draws them",
          "[render][stroke_raster]") {
  // A dot (a path to its own start), a polyline through a repeated point and
  // a dotted line (dashes of length 0, round caps): each zero-length piece
  // is a disc of the line's width, not a square.
  const std::vector<std::pair<double, double>> dot = {{40.3, 40.6}, {40.3, 40.6}};
  const std::vector<std::pair<double, double>> repeated = {{20, 100}, {60.5, 60.5}, {60.5, 60.5}, {100, 100}};
  for (const double width : {3.0, 8.0, 14.0}) {
    INFO("width " << width);
    for (const auto* points : {&dot, &repeated}) {
      const Difference d = both_ways([&](cairo_t* cr) {
        polyline(cr, *points);
        cairo_set_line_width(cr, width);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        cairo_set_source_rgb(cr, 0, 0, 0);
      });
      INFO(points->size() << " points: ink " << d.ink_a << " against Cairo's " << d.ink_b);
      CHECK(d.far_off <= 2);
      CHECK(std::abs(d.ink_a - d.ink_b) <= 0.04 * d.ink_b + 255);
    }
    const Difference dotted = both_ways([&](cairo_t* cr) {
      polyline(cr, {{10, 60}, {150, 60.5}});
      const double dashes[] = {0, 3 * width};
      cairo_set_dash(cr, dashes, 2, 0);
      cairo_set_line_width(cr, width);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      cairo_set_source_rgb(cr, 0, 0, 0);
    });
    INFO("dotted: ink " << dotted.ink_a << " against Cairo's " << dotted.ink_b);
    CHECK(dotted.ink_b > 0);
    CHECK(dotted.far_off <= 4);
    CHECK(std::abs(dotted.ink_a - dotted.ink_b) <= 0.04 * dotted.ink_b + 255);
  }
}

TEST_CASE("a software stroke of smooth curves, as frames have them, is within antialiasing of Cairo's everywhere",
          "[render][stroke_raster]") {
  for (const auto cap : {CAIRO_LINE_CAP_BUTT, CAIRO_LINE_CAP_ROUND, CAIRO_LINE_CAP_SQUARE})
    for (const int dashes : {0, 2})
      for (const double width : {1.0, 2.4, 5.0}) {
        INFO("cap " << cap << ", dashes " << dashes << ", width " << width);
        const Difference d = both_ways([&](cairo_t* cr) {
          cairo_new_path(cr);  // a damped wave, sampled every 2 px
          for (int i = 0; i <= 70; ++i) cairo_line_to(cr, 8 + 2 * i, 60 - 45 * std::exp(-0.02 * i) * std::cos(0.15 * i));
          cairo_new_sub_path(cr);  // and a wheel's rim
          cairo_arc(cr, 110, 80, 18, 0, 2 * M_PI);
          cairo_close_path(cr);
          const double pattern[] = {7, 7};
          cairo_set_dash(cr, pattern, dashes, 3);
          cairo_set_line_width(cr, width);
          cairo_set_line_cap(cr, cap);
          cairo_set_source_rgba(cr, 0.0, 0.45, 0.7, 0.9);
        });
        // Dash ends on the rim may sit a pixel apart: Cairo measures a
        // curve's dashes along its own flattening of the arc.
        CHECK(d.largest <= (dashes ? 255 : 72));
        CHECK(d.far_off <= (dashes ? 12 : 0));
        CHECK(std::abs(d.ink_a - d.ink_b) <= 0.02 * d.ink_b);
      }
}

TEST_CASE("a software stroke's edges: a one-pixel line fills its row and no more, a wider one rows in part",
          "[render][stroke_raster]") {
  Surface s;
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  cairo_set_line_width(s.cr, 1);
  cairo_set_line_cap(s.cr, CAIRO_LINE_CAP_ROUND);
  polyline(s.cr, {{10, 20.5}, {150, 20.5}});
  REQUIRE(raster_stroke(s.cr));
  CHECK(channel(s.at(80, 20), 1) == 0);
  CHECK(channel(s.at(80, 19), 1) == 255);
  CHECK(channel(s.at(80, 21), 1) == 255);
  // A round cap is a half disc beyond the end point: 39% of column 9.
  CHECK(channel(s.at(9, 20), 1) == Approx(255 * (1 - M_PI / 8)).margin(8));
  CHECK(channel(s.at(8, 20), 1) == 255);

  // 2.4 pixels wide about y = 60.5: rows 59 and 61 are 70% covered.
  cairo_set_line_width(s.cr, 2.4);
  cairo_set_line_cap(s.cr, CAIRO_LINE_CAP_BUTT);
  polyline(s.cr, {{10.5, 60.5}, {150, 60.5}});
  REQUIRE(raster_stroke(s.cr));
  CHECK(channel(s.at(80, 60), 1) == 0);
  CHECK(channel(s.at(80, 59), 1) == Approx(255 * 0.3).margin(1));
  CHECK(channel(s.at(80, 61), 1) == Approx(255 * 0.3).margin(1));
  CHECK(channel(s.at(80, 58), 1) == 255);
  CHECK(channel(s.at(10, 60), 1) == Approx(127).margin(2));  // a butt end across a pixel's middle
  CHECK(channel(s.at(9, 60), 1) == 255);
}

TEST_CASE("a software stroke grown strip by strip is the whole stroke, byte for byte", "[render][stroke_raster]") {
  // As GrowingPolyline grows a curve on a video's layer: each frame strokes
  // the path from a point well left of its strip, clipped to the strip.
  std::vector<std::pair<double, double>> curve;
  for (int i = 0; i <= 300; ++i) curve.push_back({5 + i * 0.5, 60 + 40 * std::sin(i * 0.07) * std::cos(i * 0.013)});
  for (const bool dashed : {false, true}) {
    auto style = [&](cairo_t* cr) {
      cairo_set_line_width(cr, 2.4);
      cairo_set_source_rgba(cr, 0.8, 0.2, 0.1, 0.8);
      const double dash[] = {6, 4};
      if (dashed) cairo_set_dash(cr, dash, 2, 0);
    };
    Surface whole, grown;
    style(whole.cr);
    polyline(whole.cr, curve);
    REQUIRE(raster_stroke(whole.cr));
    for (int strip = 0; strip < kSurfaceWidth; strip += 7) {
      std::size_t first = 0;  // the last point left of the strip by more than the line reaches
      while (first + 1 < curve.size() && curve[first + 1].first < strip - 4) ++first;
      double along = 0;  // the dash phase the whole path has at `first`
      for (std::size_t i = 0; i < first; ++i)
        along += vibra::render::stroked_distance(curve[i].first, curve[i].second, curve[i + 1].first, curve[i + 1].second);
      cairo_save(grown.cr);
      cairo_rectangle(grown.cr, strip, 0, 7, kSurfaceHeight);
      cairo_clip(grown.cr);
      style(grown.cr);
      const double dash[] = {6, 4};
      if (dashed) cairo_set_dash(grown.cr, dash, 2, along);
      polyline(grown.cr, {curve.begin() + first, curve.end()});
      REQUIRE(raster_stroke(grown.cr));
      cairo_restore(grown.cr);
    }
    INFO("dashed " << dashed);
    int differing = 0;
    for (int y = 0; y < kSurfaceHeight; ++y)
      for (int x = 0; x < kSurfaceWidth; ++x) differing += whole.at(x, y) != grown.at(x, y);
    CHECK(differing == 0);
  }
}

TEST_CASE("a software stroke lands in a group at the group's own offset", "[render][stroke_raster]") {
  const Difference d = both_ways([](cairo_t* cr) {
    cairo_rectangle(cr, 30, 20, 80, 60);
    cairo_clip(cr);
    cairo_push_group(cr);  // a group as large as the clip, its pixels offset by (30, 20)
    cairo_set_source_rgb(cr, 0, 0.5, 0);
    cairo_set_line_width(cr, 3);
    polyline(cr, {{20, 30}, {70, 50}, {140, 40}});
  });
  CHECK(d.largest <= 96);
  CHECK(d.ink_a == 0);  // nothing on the surface yet: the group holds it
  Surface ours, cairos;
  for (Surface* s : {&ours, &cairos}) {
    cairo_rectangle(s->cr, 30, 20, 80, 60);
    cairo_clip(s->cr);
    cairo_push_group(s->cr);
    cairo_set_source_rgb(s->cr, 0, 0.5, 0);
    cairo_set_line_width(s->cr, 3);
    polyline(s->cr, {{20, 30}, {70, 50}, {140, 40}});
    if (s == &ours) REQUIRE(raster_stroke(s->cr));
    else cairo_stroke(s->cr);
    cairo_pop_group_to_source(s->cr);
    cairo_paint_with_alpha(s->cr, 0.5);
  }
  const Difference painted = compare(ours, cairos);
  CHECK(painted.largest <= 48);
  CHECK(painted.ink_a > 1000);
  CHECK(std::abs(painted.ink_a - painted.ink_b) <= 0.03 * painted.ink_b);
}

TEST_CASE("a software stroke leaves to Cairo what it does not draw, path and all", "[render][stroke_raster]") {
  auto declined = [](const std::function<void(cairo_t*)>& setup) {
    Surface s;
    cairo_set_source_rgb(s.cr, 0, 0, 0);
    setup(s.cr);
    const bool taken = raster_stroke(s.cr);
    const bool path_kept = cairo_has_current_point(s.cr);
    return !taken && path_kept;
  };
  auto line = [](cairo_t* cr) { polyline(cr, {{10, 10}, {100, 80}}); };
  CHECK(declined([&](cairo_t* cr) {  // a clip that is not whole pixels
    cairo_rectangle(cr, 10.5, 10, 50, 50);
    cairo_clip(cr);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // two rectangles
    cairo_rectangle(cr, 0, 0, 20, 20);
    cairo_rectangle(cr, 40, 40, 20, 20);
    cairo_clip(cr);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // a gradient
    cairo_pattern_t* gradient = cairo_pattern_create_linear(0, 0, 100, 0);
    cairo_pattern_add_color_stop_rgb(gradient, 0, 1, 0, 0);
    cairo_pattern_add_color_stop_rgb(gradient, 1, 0, 0, 1);
    cairo_set_source(cr, gradient);
    cairo_pattern_destroy(gradient);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // a scaled or rotated transform
    cairo_scale(cr, 2, 2);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // another operator
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // no antialiasing
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    line(cr);
  }));
  CHECK(declined([&](cairo_t* cr) {  // a sharp mitred corner
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    polyline(cr, {{10, 10}, {100, 10}, {100, 80}});
  }));
  CHECK(declined([&](cairo_t* cr) {  // dashes far finer than a pixel
    const double fine[] = {0.003, 0.003};
    cairo_set_dash(cr, fine, 2, 0);
    polyline(cr, {{0, 10}, {150, 10}, {150, 100}, {0, 100}});
  }));
  CHECK(declined([&](cairo_t* cr) {  // a square dot: Cairo picks its direction
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
    polyline(cr, {{50, 50}, {50, 50}});
  }));

  // A vector surface is Cairo's alone.
  cairo_surface_t* svg = cairo_svg_surface_create_for_stream(
      [](void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; }, nullptr, 100, 100);
  cairo_t* cr = cairo_create(svg);
  polyline(cr, {{10, 10}, {50, 50}});
  CHECK_FALSE(raster_stroke(cr));
  CHECK(cairo_has_current_point(cr));
  cairo_destroy(cr);
  cairo_surface_destroy(svg);

  // A gentle mitred bend looks as a round one: drawn.
  Surface s;
  cairo_set_line_join(s.cr, CAIRO_LINE_JOIN_MITER);
  polyline(s.cr, {{10, 10}, {100, 20}, {150, 40}});
  CHECK(raster_stroke(s.cr));
}

TEST_CASE("a software stroke clipped to nothing, or reaching far beyond the picture, draws only what shows",
          "[render][stroke_raster]") {
  Surface s;
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  cairo_save(s.cr);
  cairo_rectangle(s.cr, 0, 0, 0, 0);
  cairo_clip(s.cr);
  polyline(s.cr, {{10, 10}, {100, 80}});
  CHECK(raster_stroke(s.cr));
  CHECK_FALSE(cairo_has_current_point(s.cr));
  cairo_restore(s.cr);
  for (int y = 0; y < kSurfaceHeight; ++y)
    for (int x = 0; x < kSurfaceWidth; ++x) REQUIRE(s.at(x, y) == 0xffffffffu);

  // A line a thousand million pixels long across the picture: its row, in
  // no more time than the picture's width.
  cairo_set_line_width(s.cr, 1);
  polyline(s.cr, {{-1e9, 50.5}, {1e9, 50.5}});
  REQUIRE(raster_stroke(s.cr));
  for (int x = 0; x < kSurfaceWidth; ++x) {
    CHECK(channel(s.at(x, 50), 1) == 0);
    CHECK(channel(s.at(x, 49), 1) == 255);
  }
  // Far off to one side: nothing.
  polyline(s.cr, {{1e300, 1e300}, {2e300, 1e300}});
  REQUIRE(raster_stroke(s.cr));
  CHECK(channel(s.at(kSurfaceWidth - 1, kSurfaceHeight - 1), 1) == 255);
}

TEST_CASE("a software stroke joins a closed outline's dashes through its start, as Cairo does",
          "[render][stroke_raster]") {
  for (const double offset : {0.0, 3.0, 9.5, 17.0}) {
    INFO("offset " << offset);
    const Difference d = both_ways([&](cairo_t* cr) {
      cairo_new_path(cr);
      cairo_rectangle(cr, 20.5, 20.5, 100, 70);
      cairo_arc(cr, 80, 60, 25, 0, 2 * M_PI);
      cairo_close_path(cr);
      const double dash[] = {7, 5};
      cairo_set_dash(cr, dash, 2, offset);
      cairo_set_line_width(cr, 2.4);
      cairo_set_source_rgb(cr, 0.9, 0.4, 0);
    });
    CHECK(d.far_off <= 12);  // dash ends on the arc: see above
    CHECK(std::abs(d.ink_a - d.ink_b) <= 0.03 * d.ink_b);
  }
}

namespace {
/// Strokes of short and long pieces at every angle: random ends, widths from
/// 0.6 to 9 px, each cap, some dashed, drawn one after another in software.
std::uint64_t random_strokes_hash(Surface& s) {
  std::mt19937 random(2026);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (random() / 4294967296.0); };
  const cairo_line_cap_t caps[3] = {CAIRO_LINE_CAP_BUTT, CAIRO_LINE_CAP_ROUND, CAIRO_LINE_CAP_SQUARE};
  for (int k = 0; k < 300; ++k) {
    // One draw a statement: the order a call's arguments are evaluated in is the compiler's to choose.
    const double red = uniform(0, 1), green = uniform(0, 1), blue = uniform(0, 1), alpha = uniform(0.3, 1);
    cairo_set_source_rgba(s.cr, red, green, blue, alpha);
    cairo_set_line_width(s.cr, uniform(0.6, 9));
    cairo_set_line_cap(s.cr, caps[k % 3]);
    const double dash[2] = {uniform(2, 9), uniform(1, 6)};
    cairo_set_dash(s.cr, dash, k % 4 == 0 ? 2 : 0, 0);
    const double x = uniform(-10, kSurfaceWidth + 10), y = uniform(-10, kSurfaceHeight + 10), length = k % 2 ? uniform(0, 4) : uniform(4, 90);
    const double angle = k % 10 == 0 ? (k % 20 == 0 ? 0 : M_PI / 2) : uniform(0, 2 * M_PI);  // level and upright ones too
    polyline(s.cr, {{x, y}, {x + length * std::cos(angle), y + length * std::sin(angle)}, {x + length, y + 3}});
    REQUIRE(raster_stroke(s.cr));
  }
  std::uint64_t hash = 14695981039346656037ull;
  for (int y = 0; y < kSurfaceHeight; ++y)
    for (int x = 0; x < kSurfaceWidth; ++x) hash = (hash ^ s.at(x, y)) * 1099511628211ull;
  return hash;
}
}  // namespace

TEST_CASE("a software stroke of 300 random pieces, every angle, cap and width, is the held picture",
          "[render][stroke_raster]") {
  // A tripwire for a change of the stroke's arithmetic (a faster loop must
  // leave every pixel as it was). When it trips, the pairs that say what is
  // right are "within antialiasing of Cairo's" and "grown strip by strip" above.
  Surface s;
  char held[32];
  std::snprintf(held, sizeof held, "0x%016llx", static_cast<unsigned long long>(random_strokes_hash(s)));
  CHECK(std::string(held) == "0x9e8ce426a08b3a3b");
}

TEST_CASE("a stroke's mask is blended as source IN mask OVER the pixels, eight at a time as one at a time",
          "[render][stroke_raster]") {
  // pixman's rounding of x * a / 255 is round to nearest (x * a / 255 is never a half).
  auto times = [](std::uint32_t x, std::uint32_t a) { return (2 * x * a + 255) / 510; };
  std::mt19937 random(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const int width = 1 + int(random() % 40), first = int(random() % width), last = first + int(random() % (width - first));
    // A premultiplied source: each colour channel at most its alpha.
    const std::uint32_t alpha = random() % 256;
    std::uint32_t source = alpha << 24;
    for (int c = 0; c < 3; ++c) source |= std::uint32_t(alpha ? random() % (alpha + 1) : 0) << (8 * c);
    std::vector<std::uint32_t> pixels(width), expected;
    std::vector<std::uint8_t> masks(width + 7);
    for (auto& p : pixels) {
      const std::uint32_t a = random() % 256;
      p = a << 24;
      for (int c = 0; c < 3; ++c) p |= std::uint32_t(random() % (a + 1)) << (8 * c);
    }
    for (auto& m : masks) m = trial % 3 == 0 && random() % 3 == 0 ? 0 : std::uint8_t(random());
    expected = pixels;
    for (int x = first; x <= last; ++x) {
      std::uint32_t out = 0;
      const std::uint32_t in_alpha = times(alpha, masks[x]);
      for (int c = 0; c < 4; ++c) {
        const std::uint32_t s = times((source >> (8 * c)) & 0xff, masks[x]), d = (pixels[x] >> (8 * c)) & 0xff;
        out |= (s + times(d, 255 - in_alpha)) << (8 * c);
      }
      expected[x] = out;
    }
    for (const bool one_at_a_time : {true, false}) {
      std::vector<std::uint32_t> got = pixels;
      std::vector<std::uint8_t> left = masks;
      vibra::render::blend_span(got.data(), left.data(), first, last, source, one_at_a_time);
      INFO("trial " << trial << ", one at a time " << one_at_a_time << ", columns " << first << ".." << last);
      REQUIRE(got == expected);
      for (int x = 0; x < width + 7; ++x) REQUIRE(int(left[x]) == (x >= first && x <= last ? 0 : int(masks[x])));
    }
  }
}

TEST_CASE("a software stroke's vector loops draw the bytes its one-pixel-at-a-time loops draw", "[render][stroke_raster]") {
  // Every cap, dashes (pieces with cut ends), closed outlines, translucent
  // colours over what the strokes before drew, thin and wide lines.
  std::mt19937 random(20261128);
  std::uniform_real_distribution<double> x(-20, kSurfaceWidth + 20), y(-20, kSurfaceHeight + 20), unit(0, 1);
  Surface vector, scalar;
  int cut = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<std::pair<double, double>> points(2 + random() % 10);
    for (auto& p : points) p = {x(random), y(random)};
    const double width = 0.6 + 8 * unit(random), alpha = trial % 3 ? 0.15 + 0.85 * unit(random) : 1;
    const auto cap = static_cast<cairo_line_cap_t>(random() % 3);
    const bool closed = random() % 4 == 0, dashed = random() % 2 == 0;
    const double dashes[] = {1 + 9 * unit(random), 1 + 9 * unit(random)}, offset = 20 * unit(random);
    const double colour[] = {unit(random), unit(random), unit(random)};
    cut += dashed || cap != CAIRO_LINE_CAP_ROUND;
    for (Surface* s : {&vector, &scalar}) {
      polyline(s->cr, points);
      if (closed) cairo_close_path(s->cr);
      cairo_set_line_width(s->cr, width);
      cairo_set_line_cap(s->cr, cap);
      cairo_set_dash(s->cr, dashes, dashed ? 2 : 0, offset);
      cairo_set_source_rgba(s->cr, colour[0], colour[1], colour[2], alpha);
      REQUIRE(vibra::render::raster_stroke(s->cr, s == &scalar));
    }
  }
  CHECK(cut > 200);
  int differ = 0;
  for (int row = 0; row < kSurfaceHeight; ++row)
    for (int column = 0; column < kSurfaceWidth; ++column) differ += vector.at(column, row) != scalar.at(column, row);
  CHECK(differ == 0);
}
