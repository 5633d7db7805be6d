// `vibra analyze convergence` as the command runs it: rates against theory,
// dt_0 from the model's settings, and the models that have no exact solution.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/analysis/model_convergence.hpp"
#include "core/error.hpp"
#include "core/scheme.hpp"

using namespace vibra;

TEST_CASE("convergence rates of every scheme on undamped are within 0.1 of theory", "[analysis]") {
  for (const auto& info : all_schemes()) {
    if (info.scheme == Scheme::backward_damping) continue;  // the centered scheme when there is no damping
    if (info.adaptive) continue;                             // refused: no dt to halve (below)
    const std::string scheme(info.name);
    INFO(scheme << ", expected order " << info.order);
    // First-order schemes need smaller steps before the leading error term dominates.
    const std::string dt = info.order == 1 ? "dt=1/160" : "dt=1/40";
    const ModelConvergence study = model_convergence("undamped", {"scheme=" + scheme, dt, "T=2"}, 5);
    for (const auto& level : study.levels) UNSCOPED_INFO("dt=" << level.dt << " E=" << level.error << " r=" << level.rate);
    CHECK(study.scheme == scheme);
    CHECK(study.order == info.order);
    REQUIRE(study.levels.size() == 5);
    CHECK(std::isnan(study.levels[0].rate));
    CHECK(study.levels.back().rate == Approx(info.order).margin(0.1));
  }
}

TEST_CASE("convergence rates of every scheme with damping and forcing: u'' + beta u' + u = sin(gamma t)", "[analysis]") {
  // Forcing tests that each stage takes a at its own time, damping that it
  // takes v where it should; Euler-Cromer's half-step start and PEFRL take
  // the damping a step behind and fall to first order.
  for (const auto& info : all_schemes()) {
    if (info.scheme == Scheme::centered_adjusted || info.adaptive) continue;  // refused: undamped only, no dt
    const std::string scheme(info.name);
    const int expected = damped_order(info);
    INFO(scheme << ", expected order " << expected);
    CHECK(expected == ((info.scheme == Scheme::euler_cromer_half || info.scheme == Scheme::pefrl) ? 1 : info.order));
    const std::string dt = expected == 1 ? "dt=1/160" : "dt=1/40";
    const ModelConvergence study =
        model_convergence("resonance", {"scheme=" + scheme, "beta=0.3", "gamma=1.7", "I=0.4", "V=-0.2", dt, "T=4"}, 5);
    for (const auto& level : study.levels) UNSCOPED_INFO("dt=" << level.dt << " E=" << level.error << " r=" << level.rate);
    CHECK(study.order == expected);
    CHECK(study.levels.back().rate == Approx(expected).margin(0.1));
  }
  // Without damping both keep their order, forcing or not.
  for (const char* scheme : {"pefrl", "euler-cromer-half"}) {
    INFO(scheme);
    const ModelConvergence study =
        model_convergence("resonance", {std::string("scheme=") + scheme, "beta=0", "gamma=1.7", "I=0.4", "dt=1/40", "T=4"}, 5);
    CHECK(study.order == scheme_info(parse_scheme(scheme)).order);
    CHECK(study.levels.back().rate == Approx(study.order).margin(0.1));
  }
}

TEST_CASE("convergence on the circular orbit of two-body: PEFRL and RK4 are 4th order", "[analysis]") {
  for (const char* scheme : {"pefrl", "rk4"}) {
    INFO(scheme);
    const ModelConvergence study = model_convergence("two-body", {std::string("scheme=") + scheme, "steps_per_period=100", "periods=1"}, 5);
    CHECK(study.levels.back().rate == Approx(4).margin(0.1));
  }
}

TEST_CASE("convergence starts from the model's dt and halves it", "[analysis]") {
  const ModelConvergence study = model_convergence("undamped", {"steps_per_period=20", "T=1"}, 3);
  CHECK(study.levels[0].dt == Approx(1.0 / 20));
  CHECK(study.levels[1].dt == Approx(1.0 / 40));
  CHECK(study.levels[2].dt == Approx(1.0 / 80));
}

TEST_CASE("convergence needs an exact solution and a sensible number of levels", "[analysis]") {
  CHECK_THROWS_WITH(model_convergence("vibration", {"F=cos(t)"}, 5),
                    Catch::Contains("no exact solution") && Catch::Contains("undamped"));
  CHECK_THROWS_WITH(model_convergence("pendulum", {"alpha=0"}, 5), Catch::Contains("small-angle solution is an approximation"));
  CHECK_THROWS_WITH(model_convergence("two-body", {"vy0=1.2"}, 5), Catch::Contains("circular orbit"));
  CHECK_THROWS_WITH(model_convergence("undamped", {"scheme=dopri5"}, 5),
                    Catch::Contains("dopri5 chooses its own") && Catch::Contains("scheme=rk4"));
  CHECK_THROWS_AS(model_convergence("undamped", {}, 1), UsageError);
  CHECK_THROWS_AS(model_convergence("undamped", {}, 21), UsageError);
}
