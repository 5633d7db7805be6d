// `vibra ascii` end to end: the classic plotter's lines, character for character.
#include <catch2/catch.hpp>
#include <sstream>

#include "cli_support.hpp"

using vibra::test::check_refusal;
using vibra::test::run_vibra;

TEST_CASE("ascii: the book's u and exact series, by hand", "[ascii-command]") {
  // u'' + 4 pi^2 u = 0, dt = 0.1: u = 1, 0.8026, 0.2884, -0.3397; exact
  // cos(2 pi t) = 1, 0.8090, 0.3090, -0.3090. Columns round((y + 1.2)/2.4 * 20);
  // the axis sits at column 10; the exact 'o' draws over '+'.
  const auto r = run_vibra("ascii undamped --set dt=0.1 --set T=0.3 --width 20 --symbols +o --exact --ymin -1.2 --ymax 1.2");
  REQUIRE(r.exit_code == 0);
  CHECK(r.out ==
        "          |       o   0.0\n"
        "          |      o    0.1\n"
        "          | +o        0.2\n"
        "       o  |           0.3\n");
}

TEST_CASE("ascii: --legend names the series first, the lines below unchanged", "[ascii-command]") {
  const std::string args = "ascii undamped --set dt=0.1 --set T=0.3 --width 20 --symbols +o --exact --ymin -1.2 --ymax 1.2";
  const auto plain = run_vibra(args), legend = run_vibra(args + " --legend");
  REQUIRE(legend.exit_code == 0);
  CHECK(legend.out == "+ u   o exact\n" + plain.out);
}

TEST_CASE("ascii: out-of-range values are appended, counters by time", "[ascii-command]") {
  const auto r = run_vibra("ascii undamped --set dt=0.1 --set T=0.1 --width 4 --ymin -0.5 --ymax 0.5 --counter time");
  REQUIRE(r.exit_code == 0);
  CHECK(r.out == "  |   1.0E+00 0.0\n  |   8.0E-01 0.1\n");
}

TEST_CASE("ascii: endless runs end quietly in a pipeline", "[ascii-command]") {
  const auto r = run_vibra("ascii pendulum --set T=inf | head -5");
  CHECK(r.exit_code == 0);
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 5);
  CHECK(r.err.empty());
}

TEST_CASE("ascii: several series with a legend, default range from the amplitude", "[ascii-command]") {
  const auto r = run_vibra("ascii pendulum --columns theta,S,D --set periods=1 --width 40");
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.substr(0, r.out.find('\n')) == "* theta   o S   + D");
  // Every line after the legend: width + 1 = 41 columns, a space and the
  // counter t/P with one decimal (0.0 to 1.0 over one period).
  std::istringstream lines(r.out.substr(r.out.find('\n') + 1));
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    INFO("line " << count << ": '" << line << "'");
    REQUIRE(line.size() == 41 + 1 + 3);
    CHECK(line[41] == ' ');
    CHECK(line.substr(42, 1) <= "1");
    CHECK(line[43] == '.');
  }
  CHECK(count == 61);  // one line per step: t = 0 and the 60 steps of the period
}

TEST_CASE("ascii: the default range holds every column shown, not just the first", "[ascii-command]") {
  // theta stays below Theta = 0.35 rad, but the wire force S is about 1:
  // a range from theta alone puts S out of range (appended as 1.0E+00) on every line.
  const auto r = run_vibra("ascii pendulum --columns theta,S,D --set periods=2 --width 40");
  REQUIRE(r.exit_code == 0);
  int lines = 0;
  for (size_t start = r.out.find('\n') + 1, end; (end = r.out.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = r.out.substr(start, end - start);
    INFO(line);
    CHECK(line.find("E+") == std::string::npos);
    CHECK(line.find("E-") == std::string::npos);
    CHECK(line.find('o') != std::string::npos);  // S is drawn on every line
    ++lines;
  }
  CHECK(lines > 20);
}

TEST_CASE("ascii: bad options are one-line errors", "[ascii-command]") {
  for (const char* args : {"ascii pendulum --columns phi", "ascii pendulum --exact", "ascii undamped --ymin 1",
                           "ascii undamped --ymin 1 --ymax 0", "ascii undamped --width 0", "ascii undamped --width x",
                           "ascii undamped --counter days", "ascii undamped --exact --symbols '*'",
                           "ascii undamped --rate -1"}) {
    INFO(args);
    const auto r = run_vibra(args);
    check_refusal(r, "");
  }
}

TEST_CASE("ascii: a forced run, with no energy bound, gets a default range that holds its start", "[ascii-command]") {
  // resonance: u(0) = I = 3 and a forcing of amplitude 1: no bound from the
  // energy, so the range is the start's |u|, and u = 3 is drawn, not appended.
  const auto r = run_vibra("ascii resonance --set I=3 --set beta=0.5 --set periods=1 --width 40");
  REQUIRE(r.exit_code == 0);
  const std::string first = r.out.substr(0, r.out.find('\n'));
  INFO(first);
  CHECK(first.find('*') != std::string::npos);
  CHECK(first.find("E+") == std::string::npos);
}
