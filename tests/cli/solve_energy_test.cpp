// `vibra solve MODEL --energy`: the columns E and E_rel over the real executable.
#include <catch2/catch.hpp>

#include <cmath>

#include "cli_support.hpp"

using vibra::test::run_vibra;

namespace {
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

Csv read_csv(const std::string& text) {
  const auto cells = vibra::test::csv_rows(text);
  Csv csv{cells.at(0), {}};
  for (size_t i = 1; i < cells.size(); ++i) {
    csv.rows.emplace_back();
    for (const auto& cell : cells[i]) csv.rows.back().push_back(cell.empty() ? NAN : std::stod(cell));
  }
  return csv;
}
}  // namespace

TEST_CASE("solve --energy appends E and E_rel with Forward Euler's factor 1 + w^2 dt^2", "[solve-energy]") {
  const auto r = run_vibra("solve undamped --set scheme=forward-euler --set dt=0.01 --set T=2 --energy");
  REQUIRE(r.exit_code == 0);
  const Csv csv = read_csv(r.out);
  CHECK(csv.header == std::vector<std::string>{"t", "u", "v", "E", "E_rel"});
  REQUIRE(csv.rows.size() == 201);
  const double w = 2 * M_PI, E0 = 0.5 * w * w;
  CHECK(csv.rows[0][3] == Approx(E0).epsilon(1e-15));
  CHECK(csv.rows[0][4] == 0);
  for (size_t n = 0; n < csv.rows.size(); n += 50) {
    const double growth = std::pow(1 + w * w * 1e-4, double(n));
    CHECK(csv.rows[n][3] == Approx(E0 * growth).epsilon(1e-12));
    CHECK(csv.rows[n][4] == Approx(growth - 1).epsilon(1e-11));
  }
}

TEST_CASE("solve --energy agrees with analyze energy where they measure the same", "[solve-energy]") {
  // The centered scheme's own velocity is the centered difference the book's
  // table uses, so max |E_rel| over n = 1..Nt-1 is analyze energy's number.
  const auto table = run_vibra("analyze energy --schemes centered --T 1 --dt 0.05 --csv");
  REQUIRE(table.exit_code == 0);
  const std::string last_line = table.out.substr(table.out.rfind(',') + 1);
  const double expected = std::stod(last_line);
  const auto solved = run_vibra("solve undamped --set scheme=centered --set T=1 --set dt=0.05 --energy");
  REQUIRE(solved.exit_code == 0);
  const Csv csv = read_csv(solved.out);
  double worst = 0;
  for (size_t n = 1; n + 1 < csv.rows.size(); ++n) worst = std::max(worst, std::abs(csv.rows[n][4]));
  CHECK(worst == Approx(expected).epsilon(1e-12));
  CHECK(expected > 1e-3);  // a real difference, not two zeros
}

TEST_CASE("solve --energy works for every model and with --every", "[solve-energy]") {
  for (const char* model : {"vibration", "pendulum", "physical-pendulum", "elastic-pendulum", "two-body"}) {
    INFO(model);
    const auto r = run_vibra(std::string("solve ") + model + " --energy --every 10");
    REQUIRE(r.exit_code == 0);
    const Csv csv = read_csv(r.out);
    CHECK(csv.header.back() == "E_rel");
    CHECK(csv.rows.front().size() == csv.header.size());
    CHECK(csv.rows.front().back() == 0);
  }
  // The pendulum with drag loses energy; its E_rel ends negative.
  const Csv damped = read_csv(run_vibra("solve pendulum --set alpha=0.4 --energy").out);
  CHECK(damped.rows.back().back() < -0.5);
}
