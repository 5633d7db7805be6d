// Tests of Parameters: expressions, angles and choices parsed, and near names suggested.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/input/parameters.hpp"

using namespace vibra;

TEST_CASE("parameters parse expressions, angles and choices", "[parameters]") {
  Parameters p("test", {{"dt", ValueKind::number, "2*pi/40", "", "", {}, {}},
                        {"Theta", ValueKind::angle, "70", "", "", {}, {}},
                        {"law", ValueKind::choice, "linear", "", "", {"linear", "quadratic"}, {}}});
  CHECK(p.number("dt") == Approx(2 * M_PI / 40));
  CHECK(p.angle("Theta") == Approx(70 * M_PI / 180));
  p.assign("Theta = 0.5rad");
  CHECK(p.angle("Theta") == 0.5);
  p.assign("Theta=45deg");
  CHECK(p.angle("Theta") == Approx(M_PI / 4));
  CHECK_THROWS_AS(p.assign("law=cubic"), UsageError);
  CHECK_THROWS_AS(p.assign("noequals"), UsageError);
  CHECK_THROWS_WITH(p.assign("Thta=1"), Catch::Contains("did you mean 'Theta'"));
  CHECK_THROWS_WITH(p.assign("xyz=1"), !Catch::Contains("did you mean"));
  // Refused when given (outside dt's range), and not kept.
  CHECK_THROWS_WITH(p.assign("dt=1/0"), Catch::Contains("dt=1/0 must be a finite positive number"));
  CHECK_THROWS_AS(p.assign("dt=sqrt(-1)"), UsageError);
  CHECK_THROWS_AS(p.assign("Theta=abc"), UsageError);
  CHECK_THROWS_WITH(p.assign("Theta=1e13"), Catch::Contains("Theta=1e13 must be a number"));
  CHECK(p.given_assignments() == std::vector<std::string>{"Theta=45deg"});
}

TEST_CASE("closest_match suggests near names only", "[parameters]") {
  CHECK(closest_match("pendulm", {"pendulum", "undamped"}) == "pendulum");
  CHECK(closest_match("foo", {"rho", "m"}) == "");
  // Two neighbours swapped is one slip, even in a short name.
  CHECK(closest_match("alpah", {"alpha", "Theta", "dt"}) == "alpha");
  CHECK(closest_match("Thtea", {"alpha", "Theta", "dt"}) == "Theta");
  CHECK(closest_match("td", {"dt", "T"}) == "dt");
}
