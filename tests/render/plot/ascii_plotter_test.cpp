// Tests of the ASCII plotter: ranges, overlapping series, symbols and the y = 0 axis.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "render/plot/ascii_plotter.hpp"

using vibra::render::AsciiPlotter;
using vibra::render::AsciiPlotterOptions;

namespace {
std::string plot(AsciiPlotter& p, std::vector<double> values) { return std::string(p.line(values)); }
}  // namespace

// Bounds and values below are chosen so that (y - ymin) / (ymax - ymin) * width
// is exact in binary floating point; the comments give that product.

TEST_CASE("ascii plot: one series, and both ends of the range", "[ascii]") {
  AsciiPlotter p({.ymin = 0, .ymax = 8, .width = 8});
  CHECK(plot(p, {3}) == "   *     ");      // 3
  CHECK(plot(p, {0, 8}) == "*       o");    // 0 and 8: the range is closed
  CHECK(plot(p, {}) == "         ");       // width + 1 columns, always
}

TEST_CASE("ascii plot: later series overwrite earlier ones and symbols cycle", "[ascii]") {
  AsciiPlotter p({.ymin = 0, .ymax = 8, .width = 8});
  CHECK(plot(p, {3, 3}) == "   o     ");
  AsciiPlotter ab({.ymin = 0, .ymax = 8, .width = 8, .symbols = "ab"});
  CHECK(plot(ab, {1, 2, 3}) == " aba     ");
}

TEST_CASE("ascii plot: the y = 0 axis overwrites symbols", "[ascii]") {
  AsciiPlotter p({.ymin = -4, .ymax = 4, .width = 8});  // axis: 4
  CHECK(plot(p, {0, -4, 4}) == "o   |   +");            // 4 (under the axis), 0, 8
  CHECK(plot(p, {-1}) == "   *|    ");                  // 3
  AsciiPlotter no_axis({.ymin = 0, .ymax = 4, .width = 4});
  CHECK(plot(no_axis, {0}) == "*    ");  // zero at an end of the range: no axis
}

TEST_CASE("ascii plot: halves round away from zero", "[ascii]") {
  // Banker's rounding (Python 3) or truncation would give the even/lower column.
  AsciiPlotter positive({.ymin = 0, .ymax = 4, .width = 8});
  CHECK(plot(positive, {0.25}) == " *       ");  // 0.25 / 4 * 8 = 0.5 -> 1
  CHECK(plot(positive, {1.25}) == "   *     ");  // 1.25 / 4 * 8 = 2.5 -> 3

  AsciiPlotter both({.ymin = -4, .ymax = 4, .width = 16});  // axis: 4 / 8 * 16 = 8
  CHECK(plot(both, {-2.75, 1.25}) == "   *    |  o     ");  // 1.25/8*16 = 2.5 -> 3; 5.25/8*16 = 10.5 -> 11
  CHECK(plot(both, {-0.75, 0.25}) == "       *|o       ");  // 3.25/8*16 = 6.5 -> 7; 4.25/8*16 = 8.5 -> 9
}

TEST_CASE("ascii plot: out-of-range values are appended as ' %.1E'", "[ascii]") {
  AsciiPlotter p({.ymin = -1, .ymax = 1, .width = 4});  // axis: 2
  CHECK(plot(p, {1.5, -20, 0.5}) == "  |+  1.5E+00 -2.0E+01");  // 0.5: 1.5 / 2 * 4 = 3
  CHECK(plot(p, {-1, 1}) == "* | o");
  CHECK(plot(p, {std::nextafter(1.0, 2.0)}) == "  |   1.0E+00");
  CHECK(plot(p, {-1234.5, 0.000125}) == "  |   -1.2E+03");  // 0.000125 is drawn, then hidden by the axis
}

TEST_CASE("ascii plot: width 1", "[ascii]") {
  AsciiPlotter p({.ymin = 0, .ymax = 1, .width = 1});
  CHECK(plot(p, {0.4}) == "* ");
  CHECK(plot(p, {0.5}) == " *");
  AsciiPlotter axis({.ymin = -1, .ymax = 1, .width = 1});  // axis: 0.5 -> 1
  CHECK(plot(axis, {-1}) == "*|");
  CHECK(plot(axis, {1}) == " |");
}

TEST_CASE("ascii plot: NaN and infinities are not drawn but appended", "[ascii]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  AsciiPlotter p({.ymin = 0, .ymax = 1, .width = 4});
  CHECK(plot(p, {nan, 0.5}) == "  o   NAN");
  CHECK(plot(p, {-nan, 0.5}) == "  o   NAN");  // the sign of a NaN is noise: never shown
  CHECK(plot(p, {inf, -inf}) == "      INF -INF");
}

TEST_CASE("ascii plot: bad options throw", "[ascii]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(AsciiPlotter({.ymin = 1, .ymax = 1}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = 2, .ymax = 1}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = 0, .ymax = 1, .width = 0}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = 0, .ymax = 1, .symbols = ""}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = std::nan(""), .ymax = 1}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = 0, .ymax = inf}), std::invalid_argument);
  CHECK_THROWS_AS(AsciiPlotter({.ymin = -1e308, .ymax = 1e308}), std::invalid_argument);  // ymax - ymin overflows
}

TEST_CASE("ascii plot: lines reuse one buffer", "[ascii]") {
  AsciiPlotter p({.ymin = -1, .ymax = 1});
  const std::vector<double> in_range = {0.1, 0.2}, out_of_range = {-1e300, 1e300};
  const char* first = p.line(in_range).data();
  CHECK(p.line(out_of_range).data() == first);
  CHECK(p.line(in_range).data() == first);
}

TEST_CASE("ascii plot: matches scitools avplotter's documented example", "[ascii]") {
  // avplotter's doctest: Plotter(-1.2, 1.2, width=50) over two periods of
  // y = (1 + 0.2 sin(t/2)) sin t at t = linspace(0, 4 pi, 45).
  const char* expected =
      "                         |                         \n"
      "                         |     *                   \n"
      "                         |           *             \n"
      "                         |                *        \n"
      "                         |                    *    \n"
      "                         |                      *  \n"
      "                         |                       * \n"
      "                         |                     *   \n"
      "                         |                  *      \n"
      "                         |            *            \n"
      "                         |      *                  \n"
      "                         |                         \n"
      "                  *      |                         \n"
      "            *            |                         \n"
      "      *                  |                         \n"
      "   *                     |                         \n"
      " *                       |                         \n"
      "  *                      |                         \n"
      "    *                    |                         \n"
      "        *                |                         \n"
      "             *           |                         \n"
      "                   *     |                         \n"
      "                         |                         \n"
      "                         |     *                   \n"
      "                         |          *              \n"
      "                         |             *           \n"
      "                         |                *        \n"
      "                         |                 *       \n"
      "                         |                 *       \n"
      "                         |               *         \n"
      "                         |            *            \n"
      "                         |        *                \n"
      "                         |    *                    \n"
      "                         |                         \n"
      "                    *    |                         \n"
      "                *        |                         \n"
      "            *            |                         \n"
      "         *               |                         \n"
      "       *                 |                         \n"
      "       *                 |                         \n"
      "        *                |                         \n"
      "           *             |                         \n"
      "              *          |                         \n"
      "                   *     |                         \n"
      "                         |                         \n";
  AsciiPlotter p({.ymin = -1.2, .ymax = 1.2, .width = 50});
  std::istringstream lines(expected);
  std::string want;
  const int n = 45;
  const double stop = 4 * M_PI, step = stop / (n - 1);  // as numpy.linspace computes it
  for (int i = 0; i < n; ++i) {
    const double t = i == n - 1 ? stop : i * step;
    const double y = (1 + 0.2 * std::sin(0.5 * t)) * std::sin(t);
    REQUIRE(std::getline(lines, want));
    INFO("t = " << t);
    CHECK(plot(p, {y}) == want);
  }
}
