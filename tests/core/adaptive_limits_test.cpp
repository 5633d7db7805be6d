// The runs an adaptive scheme cannot advance in doubles end with one line
// naming the setting (docs/schemes.md, "Adaptive"; docs/reliability.md):
// a step below what doubles resolve, an error norm that stays non-finite,
// 100 rejections in a row; tolerances that doubles can meet run through;
// and Ctrl-C stops a run that emits no sample.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "core/schemes/adaptive_runge_kutta.hpp"
#include "core/stop_flag.hpp"

using namespace vibra;

namespace {
/// Steps `Pair` on `system` from u = 1, v = 0 until T and returns the
/// UsageError's message, or "" when the run reaches T.
template <class Pair>
std::string run_to_end(const SecondOrderSystem<1>& system, StepControl control, double u0 = 1) {
  AdaptiveRungeKutta<1, Pair> scheme(system, Vec<1>(u0), Vec<1>(0.0), 0.01, control);
  try {
    while (scheme.current().t < control.end) scheme.step();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

template <class Check>
void for_both_pairs(Check check) {
  check(Fehlberg45{});
  check(DormandPrince54{});
}
}  // namespace

TEST_CASE("adaptive limits: a blow-up in finite time ends where the step underflows", "[schemes][adaptive][limits]") {
  // u'' = u^3 from u = 1: v^2 = (u^4 - 1)/2, so u reaches infinity at
  // t* = sqrt(2) int_1^inf du / sqrt(u^4 - 1) = 1.8541.
  const auto system = SecondOrderSystem<1>::general([](const Vec<1>& u, double) { return Vec<1>(u[0] * u[0] * u[0]); });
  for_both_pairs([&](auto pair) {
    const std::string message = run_to_end<decltype(pair)>(system, {1e-8, 1e-10, 3, false});
    INFO(message);
    CHECK_THAT(message, Catch::StartsWith(std::string(decltype(pair)::name) +
                                          ": the step size fell below what doubles resolve at t = 1.85"));
    CHECK_THAT(message, Catch::Contains("raise rtol/atol"));
  });
}

TEST_CASE("adaptive limits: an input undefined after t = 0.5 ends with the non-finite error estimate",
          "[schemes][adaptive][limits]") {
  const auto system = SecondOrderSystem<1>::general([](const Vec<1>& u, double t) { return Vec<1>(-u[0] + std::sqrt(0.5 - t)); });
  for_both_pairs([&](auto pair) {
    const std::string message = run_to_end<decltype(pair)>(system, {1e-6, 1e-9, 1, false});
    INFO(message);
    CHECK_THAT(message, Catch::Contains("the error estimate is not finite for any step size at t = 0.5 "));
  });
}

TEST_CASE("adaptive limits: 100 rejections in a row end the run", "[schemes][adaptive][limits]") {
  // u'' = 1/t^2 for t > 0 (0 at t = 0): the error of a first step of size h
  // grows like 1/h, so no step size is ever accepted.
  const auto system = SecondOrderSystem<1>::general([](const Vec<1>&, double t) { return Vec<1>(t > 0 ? 1 / (t * t) : 0); });
  for_both_pairs([&](auto pair) {
    AdaptiveRungeKutta<1, decltype(pair)> scheme(system, Vec<1>(1.0), Vec<1>(0.0), 0.01, {1e-6, 1e-9, 1, false});
    CHECK_THROWS_WITH(scheme.step(), Catch::Contains("100 step sizes in a row were rejected at t = 0 "));
    CHECK(scheme.rejected() == 100);
    CHECK(scheme.accepted() == 0);
  });
}

TEST_CASE("adaptive limits: a tiny or zero atol runs through, t advancing every step", "[schemes][adaptive][limits]") {
  // atol only matters where a component is near 0 (here v(0) = 0), and
  // there rtol max(|y^n|, |y^{n+1}|) still holds the step: once the
  // starting rule's norms overflowed and every step had h = 0.
  const auto spring = SecondOrderSystem<1>::spring(4 * M_PI * M_PI);
  for (double atol : {1e-300, 0.0})
    for_both_pairs([&](auto pair) {
      AdaptiveRungeKutta<1, decltype(pair)> scheme(spring, Vec<1>(1.0), Vec<1>(0.0), 0.01, {1e-6, atol, 1, false});
      for (double t = 0; scheme.current().t < 1; t = scheme.current().t) {
        scheme.step();
        REQUIRE(scheme.current().t > t);
      }
      INFO("atol = " << atol << ": " << scheme.accepted() << " steps");
      CHECK(scheme.accepted() < 2000);
      CHECK(scheme.current().u[0] == Approx(1).margin(1e-4));  // cos(2 pi)
    });
  // A component at rest with atol = 0: its zero error counts 0, not 0/0.
  for_both_pairs([&](auto pair) {
    CHECK(run_to_end<decltype(pair)>(SecondOrderSystem<1>::spring(1), {1e-6, 0, 1, false}, 0) == "");
  });
}

TEST_CASE("adaptive limits: Ctrl-C stops one mesh step of many adaptive steps", "[schemes][adaptive][limits]") {
  // One step() on the mesh of dt = 1e4 takes about 1e6 adaptive steps and
  // emits no sample on the way: the stop flag must still be seen.
  const auto spring = SecondOrderSystem<1>::spring(1);
  for_both_pairs([&](auto pair) {
    AdaptiveRungeKutta<1, decltype(pair)> scheme(spring, Vec<1>(1.0), Vec<1>(0.0), 1e4, {1e-10, 1e-12, 1e4, true});
    record_stop_signal(2);
    CHECK_THROWS_AS(scheme.step(), Interrupted);
    CHECK(take_stop_signal() == 2);
    CHECK(scheme.accepted() + scheme.rejected() <= 65536);
  });
}
