// The book's verification of the schemes (docs/schemes.md, docs/analysis.md): exact discrete
// solution, manufactured solutions, and convergence rates against theory.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/analysis/convergence.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

TEST_CASE("centered scheme reproduces the exact discrete solution (1.20)", "[schemes]") {
  const double w = 2 * M_PI, dt = 0.1;
  auto t = trajectory("undamped", {"w=2*pi", "I=1", "V=0", "dt=0.1", "T=20"});
  const double w_tilde = 2 / dt * std::asin(w * dt / 2);
  double worst = 0;
  for (auto& r : rows(*t)) worst = std::max(worst, std::abs(r[1] - std::cos(w_tilde * r[0])));
  CHECK(worst < 1e-12);
}

TEST_CASE("the book's first three steps for I=1, w=2pi, dt=0.1", "[schemes]") {
  auto r = rows(*trajectory("undamped", {"dt=0.1", "T=0.2"}));
  REQUIRE(r.size() == 3);
  CHECK(r[0][1] == 1.0);
  CHECK(r[1][1] == Approx(0.802607911978213).epsilon(1e-14));
  CHECK(r[2][1] == Approx(0.288358920740053).epsilon(1e-14));
}

TEST_CASE("every scheme keeps a constant solution u = I with F = s(I)", "[schemes]") {
  for (const auto& info : all_schemes()) {
    if (info.scheme == Scheme::centered_adjusted) continue;  // undamped only
    for (std::string damping : {"linear", "quadratic"}) {
      INFO(info.name << " " << damping);
      auto r = rows(*trajectory("vibration", {"scheme=" + std::string(info.name), "damping=" + damping, "b=0.3",
                                              "m=2", "s=3*u+u^3", "F=3*0.7+0.7^3", "I=0.7", "V=0", "dt=0.1",
                                              "T=10"}));
      double worst = 0;
      for (auto& row : r) worst = std::max(worst, std::abs(row[1] - 0.7));
      CHECK(worst < 1e-13);
    }
  }
}

TEST_CASE("centered scheme reproduces a linear solution for both damping laws", "[schemes]") {
  // u = V t + I: m*0 + f(V) + s(u) = F.
  const double I = 0.3, V = -0.8, b = 0.4;
  for (std::string damping : {"linear", "quadratic"}) {
    INFO(damping);
    const double f = damping == "linear" ? b * V : b * std::abs(V) * V;
    auto r = rows(*trajectory("vibration",
                              {"damping=" + damping, "b=" + str(b), "m=1.5", "s=2*u", "I=" + str(I), "V=" + str(V),
                               "F=" + str(f) + "+2*(" + str(V) + "*t+" + str(I) + ")", "dt=0.13", "T=6"}));
    double worst = 0;
    for (auto& row : r) worst = std::max(worst, std::abs(row[1] - (V * row[0] + I)));
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("centered scheme reproduces a quadratic solution with linear damping", "[schemes]") {
  // u = c t^2 + V t + I: 2 m c + b (2 c t + V) + k u = F.
  const double c = 0.6, V = -0.5, I = 1.2, m = 2, b = 0.7, k = 3;
  const std::string F = str(2 * m * c) + "+" + str(b) + "*(2*" + str(c) + "*t+" + str(V) + ")+" + str(k) + "*(" +
                        str(c) + "*t^2+" + str(V) + "*t+" + str(I) + ")";
  auto r = rows(*trajectory("vibration", {"m=2", "b=0.7", "s=3*u", "I=" + str(I), "V=" + str(V), "F=" + F,
                                          "dt=0.05", "T=3"}));
  double worst = 0;
  for (auto& row : r) worst = std::max(worst, std::abs(row[1] - (c * row[0] * row[0] + V * row[0] + I)) / 10);
  CHECK(worst < 1e-12);
}

namespace {
/// The discrete L2 error of one column of a trajectory against `exact`.
double l2_column_error(Trajectory& run, int column, const std::function<double(double)>& exact) {
  std::vector<double> row(run.width());
  double sum = 0;
  do {
    run.row(row);
    const double e = row[column] - exact(row[0]);
    sum += e * e;
  } while (run.advance());
  return std::sqrt(run.info().mesh.dt * sum);
}

/// The last convergence rates of u and of the scheme's reported velocity v
/// (the column after u) over 5 halvings of dt from dt0.
struct Rates {
  double u, v;
};
Rates final_rates(const std::string& model, const std::vector<std::string>& base, const std::string& scheme,
                  const std::function<double(double)>& exact_u, const std::function<double(double)>& exact_v, double dt0) {
  auto make = [&](double dt) {
    auto settings = base;
    settings.push_back("scheme=" + scheme);
    settings.push_back("dt=" + str(dt));
    return trajectory(model, settings);
  };
  auto levels = convergence_study(make, exact_u, dt0, 5);
  for (auto& l : levels) UNSCOPED_INFO("u: dt=" << l.dt << " E=" << l.error << " r=" << l.rate);
  double previous = 0, rate_v = 0;
  for (int i = 0; i < 5; ++i) {
    const double dt = dt0 / (1 << i);
    auto run = make(dt);
    REQUIRE(velocity_column(run->info()) == 2);
    const double error = l2_column_error(*run, 2, exact_v);
    if (i) rate_v = std::log2(previous / error);
    UNSCOPED_INFO("v: dt=" << dt << " E=" << error << " r=" << rate_v);
    previous = error;
  }
  return {levels.back().rate, rate_v};
}

/// The order of the velocity a scheme reports for u'' + w^2 u = 0, where it
/// differs from u's: centered-adjusted reports v as the centered difference
/// (1.12) of its 4th-order u, second order; Euler-Cromer's v converges at
/// second order while its u is first (as measured over two periods).
int velocity_order(const SchemeInfo& info) {
  if (info.scheme == Scheme::centered_adjusted || info.scheme == Scheme::euler_cromer) return 2;
  return info.order;
}
}  // namespace

TEST_CASE("convergence rates match theory for u'' + w^2 u = 0, in u and in v", "[schemes][convergence]") {
  auto exact_u = [](double t) { return std::cos(2 * M_PI * t); };
  auto exact_v = [](double t) { return -2 * M_PI * std::sin(2 * M_PI * t); };
  for (const auto& info : all_schemes()) {
    if (info.scheme == Scheme::backward_damping) continue;  // equals centered without damping
    if (info.adaptive) continue;                             // no dt to halve: adaptive_schemes_test.cpp
    INFO("scheme " << info.name << ": expected order " << info.order << " in u, " << velocity_order(info) << " in v");
    const double dt0 = info.order == 1 ? 1.0 / 160 : 1.0 / 40;
    const Rates r = final_rates("undamped", {"T=2"}, std::string(info.name), exact_u, exact_v, dt0);
    CHECK(r.u == Approx(info.order).margin(0.1));
    CHECK(r.v == Approx(velocity_order(info)).margin(0.1));
  }
}

TEST_CASE("convergence rates with linear damping against the exact damped solution, in u and in v",
          "[schemes][convergence]") {
  // u'' + b u' + k u = 0, u(0) = 1, u'(0) = 0: u = e^{-bt/2} (cos wd t + b/(2 wd) sin wd t),
  // v = -(k / wd) e^{-bt/2} sin wd t.
  const double b = 0.5, k = 4, wd = std::sqrt(k - b * b / 4);
  auto exact_u = [=](double t) { return std::exp(-b * t / 2) * (std::cos(wd * t) + b / 2 / wd * std::sin(wd * t)); };
  auto exact_v = [=](double t) { return -k / wd * std::exp(-b * t / 2) * std::sin(wd * t); };
  struct Case {
    const char* scheme;
    int order;
  };
  // Euler-Cromer's damping uses a velocity half a step old, so the half-step
  // start does not lift it above order 1 once there is damping.
  for (Case c : {Case{"centered", 2}, {"backward-damping", 1}, {"euler-cromer", 1}, {"euler-cromer-half", 1},
                 {"staggered", 2}, {"velocity-verlet", 2}, {"rk2", 2}, {"rk3", 3}, {"rk4", 4}, {"forward-euler", 1},
                 {"backward-euler", 1}, {"crank-nicolson", 2}, {"ab2", 2}, {"ab3", 3}, {"backward2step", 2}}) {
    INFO("scheme " << c.scheme << ": expected order " << c.order << " in u and in v");
    const Rates r = final_rates("vibration", {"b=0.5", "s=4*u", "T=6"}, c.scheme, exact_u, exact_v,
                                c.order == 1 ? 0.01 : 0.05);
    CHECK(r.u == Approx(c.order).margin(0.1));
    CHECK(r.v == Approx(c.order).margin(0.1));
  }
}

TEST_CASE("staggered and euler-cromer-half equal the centered scheme without damping", "[schemes]") {
  auto centered = rows(*trajectory("undamped", {"dt=0.05", "T=3"}));
  for (std::string scheme : {"staggered", "euler-cromer-half"}) {
    auto other = rows(*trajectory("undamped", {"dt=0.05", "T=3", "scheme=" + scheme}));
    REQUIRE(other.size() == centered.size());
    double worst = 0;
    for (size_t i = 0; i < other.size(); ++i) worst = std::max(worst, std::abs(other[i][1] - centered[i][1]));
    CHECK(worst < 1e-12);
  }
}
