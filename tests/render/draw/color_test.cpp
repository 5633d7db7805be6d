// Colours: "#rrggbb" and "#rrggbbaa" read to the byte, every malformed one refused (a space or a sign too), and the series palette's order.
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "render/draw/color.hpp"

using namespace vibra::render;

TEST_CASE("a colour is read from #rrggbb or #rrggbbaa, each pair a byte of 255", "[color]") {
  CHECK(parse_color("#ff8000") == Color{1, 128 / 255.0, 0, 1});
  CHECK(parse_color("#0A0b0C") == Color{10 / 255.0, 11 / 255.0, 12 / 255.0, 1});
  CHECK(parse_color("#00000080") == Color{0, 0, 0, 128 / 255.0});
}

TEST_CASE("a malformed colour is refused, naming it and the forms it may take", "[color]") {
  for (const std::string bad : {"ff8000", "#ff80", "#ff80000", "#ff8000ff0", "#gg8000", "#f+8000", "#ff 000", "#-10000", "#+f0000", "x123456"}) {
    INFO(bad);
    try {
      parse_color(bad);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()) == "colour '" + bad + "' is not #rrggbb or #rrggbbaa");
    }
  }
}

TEST_CASE("the series palette takes its eight colours in order, then starts again", "[color]") {
  using namespace palette;
  const Color order[] = {blue, vermillion, green, purple, orange, ink, sky, yellow};
  for (size_t k = 0; k < 16; ++k) CHECK(series(k) == order[k % 8]);
}
