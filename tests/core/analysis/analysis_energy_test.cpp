// `vibra analyze energy`: the chapter's energy-error table (docs/analysis.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "cli_support.hpp"
#include "core/analysis/energy_study.hpp"

using namespace vibra;

namespace {
using Key = std::tuple<std::string, double, double>;

/// The book's values (the table after (1.49), docs/analysis.md). Crank-Nicolson at T = 10, dt = 0.0125 is left out: the
/// book prints 3.125e-3, the analytic value is 3.077e-3 (checked below).
const std::map<Key, double> kBookTable = {
    {{"forward-euler", 1, 0.025}, 1.678e0},     {{"backward-euler", 1, 0.025}, 6.235e-1},
    {{"crank-nicolson", 1, 0.025}, 1.221e-2},   {{"rk2", 1, 0.025}, 6.076e-3},
    {{"rk4", 1, 0.025}, 8.214e-3},              {{"forward-euler", 10, 0.05}, 1.120e8},
    {{"forward-euler", 10, 0.025}, 1.788e4},    {{"forward-euler", 10, 0.0125}, 1.374e2},
    {{"crank-nicolson", 10, 0.05}, 4.756e-2},   {{"crank-nicolson", 10, 0.025}, 1.221e-2},
    {{"rk2", 10, 0.05}, 6.152e-1},              {{"rk2", 10, 0.025}, 6.250e-2},
    {{"rk2", 10, 0.0125}, 7.631e-3},            {{"rk4", 10, 0.05}, 3.510e-2},
    {{"rk4", 10, 0.025}, 8.288e-3},             {{"rk4", 10, 0.0125}, 2.058e-3},
    {{"euler-cromer", 10, 0.05}, 2.530e-2},     {{"euler-cromer", 10, 0.025}, 6.206e-3},
    {{"euler-cromer", 10, 0.0125}, 1.544e-3},
};

/// Agreement to 3 significant digits: less than half a unit of the reference's third digit apart.
bool three_digits(double value, double reference) {
  const double third_digit = std::pow(10.0, std::floor(std::log10(std::abs(reference))) - 2);
  return std::abs(value - reference) < 0.5 * third_digit;
}

/// The analytic max |e_E|/E(0) of Crank-Nicolson (exact energy for (u, v),
/// error from the centered difference of u'): 1 - sin^2(w~ dt)/(w dt)^2, w~ dt = 2 atan(w dt/2).
double crank_nicolson_bound(double dt) {
  const double wdt = 2 * M_PI * dt;
  return 1 - std::pow(std::sin(2 * std::atan(wdt / 2)) / wdt, 2);
}
}  // namespace

TEST_CASE("the energy table reproduces the book's to 3 significant digits", "[analysis]") {
  const auto table = energy_error_table({"forward-euler", "backward-euler", "crank-nicolson", "rk2", "rk4", "euler-cromer"},
                                        {1, 10}, {0.05, 0.025, 0.0125});
  REQUIRE(table.size() == 6 * 2 * 3);
  int checked = 0;
  for (const auto& e : table) {
    INFO(e.scheme << " T=" << e.T << " dt=" << e.dt << ": " << e.max_relative_error);
    if (e.scheme == "crank-nicolson" && e.T == 10 && e.dt == 0.0125) {
      CHECK(e.max_relative_error == Approx(crank_nicolson_bound(0.0125)).epsilon(1e-4));
      CHECK(three_digits(e.max_relative_error, 3.077e-3));
      ++checked;
    }
    const auto book = kBookTable.find({e.scheme, e.T, e.dt});
    if (book == kBookTable.end()) continue;
    CHECK(three_digits(e.max_relative_error, book->second));
    ++checked;
  }
  CHECK(checked == static_cast<int>(kBookTable.size()) + 1);
}

TEST_CASE("vibra analyze energy prints the table as CSV with full precision", "[analysis]") {
  const auto r = test::run_vibra("analyze energy --schemes rk4,euler-cromer --T 10 --dt 0.05,0.025 --csv");
  REQUIRE(r.exit_code == 0);
  std::istringstream out(r.out);
  std::string line;
  std::getline(out, line);
  CHECK(line == "scheme,T,dt,max_rel_energy_error");
  int rows = 0;
  while (std::getline(out, line)) {
    std::istringstream cells(line);
    std::string scheme, T, dt, error;
    std::getline(cells, scheme, ','), std::getline(cells, T, ','), std::getline(cells, dt, ','), std::getline(cells, error);
    INFO(line);
    const auto book = kBookTable.find({scheme, std::stod(T), std::stod(dt)});
    REQUIRE(book != kBookTable.end());
    CHECK(three_digits(std::stod(error), book->second));
    ++rows;
  }
  CHECK(rows == 4);
}
