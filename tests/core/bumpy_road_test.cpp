// The vehicle on a bumpy road (section 1.12.8): the road's curvature from
// its heights, the sine road's steady amplitude, and bad roads refused.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "core/models/road_profile.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
/// Writes a road file into a scratch directory of this test process's own
/// (removed at exit), never to a fixed name that another suite might share.
std::filesystem::path write_road(const std::string& name, const std::string& text) {
  static const vibra::test::ScratchDirectory dir;
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("road: h'' from sampled heights is the analytic h'' to O(dx^2)", "[models][bumpy-road]") {
  const double A = 0.05, wavelength = 2;
  double previous_error = 0;
  for (double dx : {0.04, 0.02, 0.01}) {
    // Through a file, as a user would give measured heights.
    std::string text;
    for (int i = 0; i * dx <= 20 + 1e-9; ++i) text += str(A * std::sin(2 * M_PI * i * dx / wavelength)) + "\n";
    const RoadProfile road = RoadProfile::from_file(write_road("vibra_road_test.txt", text).string(), dx);
    double error = 0;
    const double k = 2 * M_PI / wavelength;
    // Away from the ends, where the one-sided copies q_0 = q_1 are first order.
    for (double x = 1; x < 19; x += 0.0137) error = std::max(error, std::abs(road.curvature(x) + A * k * k * std::sin(k * x)));
    if (previous_error > 0) CHECK(std::log2(previous_error / error) == Approx(2).margin(0.15));
    previous_error = error;
  }
}

TEST_CASE("road: a parabola's curvature is its constant 2c everywhere, the ends included", "[models][bumpy-road]") {
  // The second difference is exact for a quadratic, and the ends copy their
  // neighbours: h = c x^2 + b x + a has h'' = 2c at every x, between samples too.
  const double c = 0.3, b = -0.7, a = 0.1, dx = 0.25;
  std::vector<double> heights;
  for (int i = 0; i <= 12; ++i) heights.push_back(c * (i * dx) * (i * dx) + b * i * dx + a);
  const RoadProfile road(heights, dx);
  for (double x : {0.0, 0.1, dx, 1.0, 2.9, 3.0, 5.0, -1.0})
    CHECK(road.curvature(x) == Approx(2 * c).epsilon(1e-9));
  // Heights in between are the linear interpolation of the samples.
  CHECK(road.height(0) == Approx(a));
  CHECK(road.height(0.5 * dx) == Approx(0.5 * (heights[0] + heights[1])));
  CHECK(road.height(3.0) == Approx(heights[12]));
}

TEST_CASE("road: a sine road's steady amplitude is m A w^2 / sqrt((k - m w^2)^2 + (b w)^2)", "[models][bumpy-road]") {
  const double m = 60, k = 60000, b = 600, A = 0.05, wavelength = 2;
  for (double speed : {5.0, 10.0, 20.0}) {
    const double w = 2 * M_PI * speed / wavelength;
    const double expected = m * A * w * w / std::sqrt(std::pow(k - m * w * w, 2) + std::pow(b * w, 2));
    auto r = rows(*trajectory("bumpy-road", {"speed=" + str(speed), "scheme=rk4", "steps_per_period=200",
                                             "periods=150", "dx=0.002"}));
    double largest = 0;
    for (size_t i = r.size() * 3 / 4; i < r.size(); ++i) largest = std::max(largest, std::abs(r[i][1]));
    INFO("speed " << speed);
    CHECK(largest == Approx(expected).epsilon(0.01));
    // x = s t and h = h(x) in the output.
    CHECK(r.back()[3] == Approx(speed * r.back()[0]));
    CHECK(r.back()[4] == Approx(A * std::sin(2 * M_PI * r.back()[3] / wavelength)).margin(1e-5));
  }
}

TEST_CASE("road: bumps are the same for the same seed, different for another", "[models][bumpy-road]") {
  const RoadProfile a = RoadProfile::bumps(0.05, 2, 100, 0.02, 7), b = RoadProfile::bumps(0.05, 2, 100, 0.02, 7),
                    c = RoadProfile::bumps(0.05, 2, 100, 0.02, 8);
  CHECK(a.heights() == b.heights());
  CHECK(a.heights() != c.heights());
  double highest = 0;
  for (double h : a.heights()) highest = std::max(highest, h);
  CHECK(highest <= 0.05 * 1.5);
  CHECK(highest > 0.01);
}

TEST_CASE("road: bad roads get one line naming the problem", "[models][bumpy-road]") {
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"road=" + write_road("vibra_empty_road.txt", "\n# nothing\n").string(), "dx=0.1"}),
                    Catch::Contains("has no heights"));
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"road=" + write_road("vibra_bad_road.txt", "0\n0.1\nbump\n0\n").string(), "dx=0.1"}),
                    Catch::Contains("vibra_bad_road.txt:3") && Catch::Contains("'bump'"));
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"road=" + write_road("vibra_short_road.txt", "0\n0.1\n0\n0.1\n").string(), "dx=0.1"}),
                    Catch::Contains("shorten T or give a longer road"));
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"road=" + write_road("vibra_nodx_road.txt", "0\n0.1\n0\n").string()}),
                    Catch::Contains("give their spacing dx"));
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"dx=-1"}), Catch::Contains("dx"));
  CHECK_THROWS_WITH(trajectory("bumpy-road", {"road=/no/such/road.txt", "dx=0.1"}), Catch::Contains("cannot read the road file"));
}
