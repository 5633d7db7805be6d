// `vibra analyze` over the real executable: CSV columns, figures, help, and
// bad input refused with one line, exit code 2 and no file.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include "cli_support.hpp"
#include "core/scheme.hpp"

using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

using vibra::test::csv_rows;

TEST_CASE("analyze convergence prints i,dt,E,r with rates near the scheme's order", "[analysis]") {
  const auto r = run_vibra("analyze convergence undamped --set scheme=crank-nicolson --set T=2 --levels 4 --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  REQUIRE(rows.size() == 5);
  CHECK(rows[0] == std::vector<std::string>{"i", "dt", "E", "r"});
  CHECK(rows[1][0] == "0");
  CHECK(rows[1][3].empty());  // no rate on the first level
  CHECK(std::stod(rows[2][1]) == Approx(std::stod(rows[1][1]) / 2));
  CHECK(std::stod(rows[4][3]) == Approx(2).margin(0.1));
}

TEST_CASE("analyze convergence's defaults reach every scheme's order and say so", "[analysis]") {
  // With no --levels, dt is halved until the last two rates agree: the last
  // rate is then the order, for the first-order schemes too.
  for (const auto& info : vibra::all_schemes()) {
    if (info.adaptive) continue;  // no dt to halve: refused
    const std::string scheme(info.name);
    // Without damping, backward-damping is the centered scheme: second order.
    const int order = info.scheme == vibra::Scheme::backward_damping ? 2 : info.order;
    INFO(scheme << ", order " << order);
    const auto r = run_vibra("analyze convergence undamped --set scheme=" + scheme + " --csv");
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    const auto rows = csv_rows(r.out);
    REQUIRE(rows.size() >= 5);
    CHECK(std::stod(rows.back()[3]) == Approx(order).margin(0.1));
    CHECK_THAT(r.err, Catch::Contains("The rates have settled"));
  }
  // The aligned table says it under the table.
  const auto aligned = run_vibra("analyze convergence undamped --set scheme=rk4");
  CHECK_THAT(aligned.out, Catch::Contains("The rates have settled"));
}

TEST_CASE("analyze convergence says plainly when the rates have not settled", "[analysis]") {
  // Forward Euler's first rates, from the default dt, are far from 1.
  const auto r = run_vibra("analyze convergence undamped --set scheme=forward-euler --levels 3");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("The rates have NOT settled"));
}

namespace {
/// A figure's size in pixels as written: a PNG's IHDR, an SVG's width and
/// height (Cairo writes pt, one per pixel), a PDF's MediaBox.
std::pair<int, int> figure_size(const std::string& path) {
  const std::string bytes = vibra::test::read_file(path);
  if (path.ends_with(".png")) return vibra::test::png_size(path);
  int w = 0, h = 0;
  if (path.ends_with(".svg")) {
    const auto svg = bytes.find("<svg");
    const auto at = svg == std::string::npos ? svg : bytes.find("width=\"", svg);
    if (at != std::string::npos) std::sscanf(bytes.c_str() + at, "width=\"%dpt\" height=\"%dpt\"", &w, &h);
  } else if (const auto at = bytes.find("/MediaBox"); at != std::string::npos) {
    std::sscanf(bytes.c_str() + at, "/MediaBox [ 0 0 %d %d ]", &w, &h);
  }
  return {w, h};
}
}  // namespace

TEST_CASE("analyze experiments draw their figures at the requested size", "[analysis]") {
  ScratchDirectory dir;
  struct Case {
    std::string command, file;
    std::pair<int, int> size;
  };
  // Each at its own size, two at the default 1280x720.
  const Case cases[] = {
      {"analyze convergence undamped --set scheme=rk4 --levels 3", "convergence.png", {1280, 720}},
      {"analyze energy --schemes rk4 --T 1 --dt 0.05,0.025 --size 900x500", "energy.svg", {900, 500}},
      {"analyze empirical pendulum --dt 0.1,0.05 --size 640x480", "empirical.pdf", {640, 480}},
      {"analyze frequency --size 800x600", "frequency.png", {800, 600}},
      {"analyze amplitude --periods 4 --size 1000x700", "amplitude.png", {1000, 700}},
      {"analyze orbit --orbits 5 --steps-per-orbit 100,200 --size 960x540", "orbit.png", {960, 540}},
      {"analyze period pendulum --set alpha=0", "period.png", {1280, 720}},
  };
  for (const auto& c : cases) {
    const std::string command = c.command + " -o " + (dir / c.file);
    INFO("vibra " << command);
    const auto r = run_vibra(command);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    // Like render: one line saying what was written (silent with --quiet).
    CHECK(r.err == "vibra: wrote " + (dir / c.file) + "\n");
    CHECK(figure_size(dir / c.file) == c.size);
    CHECK(run_vibra(command + " --quiet").err.empty());
    CHECK(std::filesystem::file_size(dir / c.file) > 1000);
  }
}

TEST_CASE("analyze experiments explain themselves with an example", "[analysis]") {
  for (const char* experiment : {"convergence", "energy", "empirical", "frequency", "amplitude", "orbit", "period"}) {
    INFO(experiment);
    const auto r = run_vibra(std::string("analyze ") + experiment + " --help");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("Example") && Catch::Contains(std::string("vibra analyze ") + experiment));
  }
}

TEST_CASE("analyze refuses bad input with one line, exit code 2 and no file", "[analysis]") {
  const std::pair<const char*, const char*> cases[] = {
      {"analyze", "needs an experiment"},
      {"analyze energi", "did you mean 'energy'"},
      {"analyze convergence vibration --set 'F=cos(t)' -o OUT.png", "no exact solution"},
      {"analyze convergence", "needs a MODEL"},
      {"analyze convergence undamped --levels 1", "--levels"},
      {"analyze convergence undamped --set scheme=rk5", "not a valid scheme"},
      {"analyze energy --schemes rk4,magic -o OUT.png", "'magic' is not a valid scheme"},
      {"analyze energy --dt 0.05,-1", "--dt value '-1' must be a positive number"},
      {"analyze energy --T 1,abc", "cannot read --T='abc'"},
      {"analyze empirical undamped --set T=0.5", "no complete oscillation"},
      {"analyze frequency --steps-per-period 2", "below pi"},
      {"analyze frequency --w 0", "--w must be a positive number"},
      {"analyze amplitude --periods 1", "no complete oscillation"},
      {"analyze orbit --steps-per-orbit 2.5", "whole numbers"},
      {"analyze orbit --orbits 0", "--orbits"},
      {"analyze frequency -o OUT.gif", ".png, .svg or .pdf"},
      {"analyze frequency -o /proc/version/f.png", "not a directory"},
      {"analyze frequency --size 0x10", "WxH"},
      {"analyze period", "needs a MODEL"},
      {"analyze period pendulm", "did you mean 'pendulum'"},
      {"analyze period undamped --set periods=0.5 -o OUT.png", "no complete period"},
      {"analyze period undamped --set T=inf", "finite end time"},
      {"analyze perod", "did you mean 'period'"},
  };
  for (const auto& [args, expected] : cases) vibra::test::check_refused(args, expected);
}

TEST_CASE("analyze period prints i,t,period,exact with the pendulum's elliptic period", "[analysis]") {
  const auto r = run_vibra("analyze period pendulum --set alpha=0 --set Theta=60 --set steps_per_period=200 --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  CHECK(rows[0] == std::vector<std::string>{"i", "t", "period", "exact"});
  REQUIRE(rows.size() == 9);  // 10 small-angle periods hold 8 true ones between upward crossings
  for (size_t i = 1; i < rows.size(); ++i) {
    CHECK(std::stod(rows[i][3]) == Approx(6.7430014192503842).epsilon(1e-15));
    CHECK(std::stod(rows[i][2]) == Approx(6.7430014192503842).epsilon(1e-7));
  }
  // The aligned table names the small-angle period too.
  const auto table = run_vibra("analyze period pendulum --set alpha=0 --set Theta=60");
  CHECK_THAT(table.out, Catch::Contains("small-oscillation period 6.283185307"));
}

TEST_CASE("analyze period leaves exact empty where unknown and adds the log decrement when damped", "[analysis]") {
  const auto r = run_vibra("analyze period vibration --set b=0.2 --set scheme=rk4 --set steps_per_period=200 --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  CHECK(rows[0] == std::vector<std::string>{"i", "t", "period", "exact", "log_decrement"});
  // m = k = 1, b = 0.2: zeta = 0.1, zeta w P_d = 2 pi zeta / sqrt(1 - zeta^2).
  const double decrement = 2 * M_PI * 0.1 / std::sqrt(1 - 0.01);
  for (size_t i = 1; i + 1 < rows.size(); ++i) {
    CHECK(rows[i][3].empty());
    CHECK(std::stod(rows[i][4]) == Approx(decrement).epsilon(1e-6));  // RK4 at 200 steps per period: 3e-8
  }
  const auto undamped = csv_rows(run_vibra("analyze period undamped --set w=2 --csv").out);
  CHECK(std::stod(undamped[1][3]) == Approx(M_PI).epsilon(1e-15));
}
