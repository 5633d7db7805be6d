// The error column (--panels error): e^n = u^n - u_e(t_n) at every sample and between samples, against the exact solution written out here.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/error_column.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::trajectory;

namespace {
// undamped with I = 1.5, V = 0, w = 2: u_e(t) = 1.5 cos(2t) (equation (1.1)'s solution).
const std::vector<std::string> kUndamped = {"I=1.5", "w=2", "dt=0.1", "T=3", "scheme=centered"};
double exact(double t) { return 1.5 * std::cos(2 * t); }
}  // namespace

TEST_CASE("the error column is u^n - I cos(w t_n) at every step, added after the run's columns", "[error_column]") {
  auto plain = trajectory("undamped", kUndamped);
  auto with_error = with_error_column(trajectory("undamped", kUndamped));
  REQUIRE(with_error->width() == plain->width() + 1);
  CHECK(with_error->info().columns.back() == "error");
  CHECK(with_error->bends_between_samples() == plain->bends_between_samples());
  std::vector<double> a(plain->width()), b(with_error->width());
  int steps = 0;
  double largest = 0;
  do {
    plain->row(a), with_error->row(b);
    CHECK(with_error->index() == plain->index());
    CHECK(with_error->t() == a[0]);
    CHECK(b[1] == a[1]);
    CHECK(b.back() == Approx(a[1] - exact(a[0])).margin(1e-15));
    largest = std::max(largest, std::abs(b.back()));
    ++steps;
    with_error->advance();
  } while (plain->advance());
  CHECK(with_error->done());
  CHECK(steps == 31);
  // The centered scheme's error is small and not zero: the column is the scheme's, not a copy of u.
  CHECK(largest > 1e-3);
  CHECK(largest < 0.2);
}

TEST_CASE("the error column between samples is the interpolated u minus the exact solution there", "[error_column]") {
  auto plain = trajectory("undamped", kUndamped);
  auto with_error = with_error_column(trajectory("undamped", kUndamped));
  plain->advance(), with_error->advance();  // row_at reaches back over the step just taken, [0, 0.1]
  std::vector<double> a(plain->width()), b(with_error->width());
  for (double t : {0.02, 0.05, 0.08}) {
    plain->row_at(t, a), with_error->row_at(t, b);
    REQUIRE(b[0] == Approx(t));
    CHECK(b[1] == a[1]);
    CHECK(b.back() == Approx(a[1] - exact(t)).margin(1e-15));
  }
}

TEST_CASE("the error column refuses a run with an approximate exact solution or none, naming which", "[error_column]") {
  const auto refused = [](const std::string& model, const std::vector<std::string>& settings) {
    try {
      with_error_column(trajectory(model, settings));
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string small_angle = refused("pendulum", {"alpha=0", "T=1"});
  CHECK(small_angle.find("only an approximate one (small-angle)") != std::string::npos);
  const std::string none = refused("vibration", {"F=cos(t)", "b=0.3", "T=1"});
  CHECK(none.find("and this run has none") != std::string::npos);
}
