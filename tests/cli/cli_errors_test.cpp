// Bad input over the real executable: one clear line on stderr, exit code 2,
// nothing at the output path and no temporary left behind.
#include <catch2/catch.hpp>
#include <fstream>
#include <string>
#include <utility>

#include "cli_support.hpp"
#include "test_support.hpp"

using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

namespace {
struct BadInput {
  const char* args;      ///< after `vibra`; OUT is replaced by a path in a scratch directory
  const char* expected;  ///< part of the one-line message
};

// Scene files with the faults people make by hand, in one directory that
// the cases name as SCENES/NAME.toml.
const ScratchDirectory& bad_scene_files() {
  static const ScratchDirectory dir = [] {
    ScratchDirectory d;
    const std::pair<const char*, std::string> files[] = {
        {"empty.toml", "# only a comment\n"},
        {"binary.toml", std::string("model = \"pendulum\"\0\x01\x02", 21)},
        {"truncated.toml", "model = \"pendulum\"\nTheta = [1, 2"},
        {"nested.toml", "a = " + std::string(5000, '[') + std::string(5000, ']') + "\n"},
        {"duplicate.toml", "model = \"pendulum\"\nTheta = 40\nTheta = 50\n"},
        {"mistyped.toml", "model = \"pendulum\"\nalpha = 0.4\nTheeta = 40\n"},
        {"wrong_type.toml", "model = \"pendulum\"\nfps = \"fast\"\n"},
        {"bad_colour.toml", "model = \"pendulum\"\n[colors]\nbob = \"#12345\"\n"},
        {"bad_model.toml", "model = \"pendulm\"\n"},
        {"transposed.toml", "model = \"pendulum\"\nalpah = 0.8\n"},
    };
    for (const auto& [name, text] : files) std::ofstream(d / name, std::ios::binary) << text;
    return d;
  }();
  return dir;
}

void check_refused(const BadInput& c) {
  std::string args = c.args;
  for (auto at = args.find("SCENES"); at != std::string::npos; at = args.find("SCENES"))
    args.replace(at, 6, bad_scene_files().path.string());
  vibra::test::check_refused(args, c.expected);
}
}  // namespace

TEST_CASE("solve refuses bad input with one line and exit code 2", "[cli]") {
  const BadInput cases[] = {
      {"solve", "needs a MODEL"},
      {"solve pendulm", "did you mean 'pendulum'"},
      {"solve pendulum --set Thta=3 -o OUT.csv", "did you mean 'Theta'"},
      {"solve pendulum --set alpah=0.8 -o OUT.csv", "did you mean 'alpha'?"},
      {"solve pendulum --set scheme=rk5 -o OUT.csv", "choose one of"},
      {"solve pendulum --set dt=0 -o OUT.csv", "dt=0 must be a positive"},
      {"solve pendulum --set dt=-0.1 -o OUT.csv", "must be a positive"},
      {"solve pendulum --set T=0 -o OUT.csv", "T=0 must be a positive"},
      {"solve pendulum --set dt=nan -o OUT.csv", "dt"},
      {"solve pendulum --set dt=1/0 -o OUT.csv", "finite"},
      {"solve pendulum --set dt=abc -o OUT.csv", "cannot read dt='abc'"},
      {"solve pendulum --set Theta=40x -o OUT.csv", "Theta"},
      {"solve undamped --set dt=0.5 -o OUT.csv", "stability limit"},
      {"solve undamped --set scheme=forward-euler --set dt=0.3 --set T=1e4 -o OUT.csv", "non-finite at step"},
      {"solve vibration --set 's=sin(x)' -o OUT.csv", "cannot read s='sin(x)'"},
      {"solve vibration --set 'F=3*cos(' -o OUT.csv", "cannot read F="},
      {"solve pendulum --set noequals -o OUT.csv", "not KEY=VALUE"},
      {"solve pendulum --every 0 -o OUT.csv", "--every"},
      {"solve pendulum -o /proc/version/x.csv", "not a directory"},
      {"solve elastic-pendulum --set beta=1.5 -o OUT.csv", "beta must be < 1"},
      {"solve two-body --set x0=0 --set y0=0 -o OUT.csv", "cannot start at the star"},
      {"solve pendulum -o /dev/full", "writing /dev/full: No space left on device"},  // a stream: written as -o -
      {"solve pendulum -o /tmp", "'/tmp' is a folder, not a file"},
      {"solve pendulum -o ''", "the output path is empty"},
      {"frobnicate", "unknown command 'frobnicate'"},
  };
  for (const auto& c : cases) check_refused(c);
}

TEST_CASE("render refuses bad input with one line and exit code 2", "[cli]") {
  const BadInput cases[] = {
      {"render no_such_scene -o OUT.mp4", "no scene 'no_such_scene'"},
      {"render --set Thta=40 -o OUT.mp4", "did you mean 'Theta'"},
      {"render --size 0x720 -o OUT.mp4", "1..8192"},
      {"render --size 9000x9000 -o OUT.mp4", "1..8192"},
      {"render --size abc -o OUT.mp4", "WxH"},
      {"render --fps 0 -o OUT.mp4", "fps=0"},
      {"render --fps 1000 -o OUT.mp4", "1..240"},
      {"render --speed -1 -o OUT.mp4", "speed=-1"},
      {"render --layout sideways -o OUT.mp4", "layout 'sideways'"},
      {"render -o OUT.xyz", "cannot tell what to write"},
      {"render -o OUT.png", "add --at T"},
      {"render -o OUT.svg", "add --at T"},
      {"render --at 1 -o OUT.mp4", "one still"},
      {"render --at 1e6 -o OUT.png", "--at 1e+06 is outside the run [0, 37.6991]"},  // %g, not 1000000.000000
      {"render --at 1e308 -o OUT.png", "--at 1e308 must be a number -1e+15..1e+15"},   // a number, only too large
      {"render --at foo -o OUT.png", "--at foo is not a time: give a number or an expression"},
      {"render --at 1/0 -o OUT.png", "--at 1/0 is not a time"},
      {"render --at 'pi/' -o OUT.png", "--at pi/ is not a time"},
      {"render --set dt=-1 -o OUT.mp4", "must be a positive"},
      {"render --set T=inf -o OUT.mp4", "finite end time"},
      {"render undamped --layout fbd -o OUT.mp4", "no free-body diagram"},
      {"render --window-mode sliding -o OUT.mp4", "drawing, movement, jumps"},
      {"render --window=-2 -o OUT.mp4", "window=-2 must be a positive number"},
      // 0 is outside a range open at 0 (value_ranges.cpp): refused with the range, not drawn.
      {"render --window 0.0 -o OUT.mp4", "window=0.0 must be a positive number at most 1e+15"},
      {"render spring_dashpot --set drag_magnification=0 -o OUT.mp4",
       "drag_magnification=0 must be a positive number at most 1000000"},
      {"render --frames-player -o OUT.mp4", "--frames-player"},
      {"render --codec h265 -o OUT.mp4", "unknown video codec 'h265'"},
      {"render --crf 99 -o OUT.mp4", "--crf: 99 must be a whole number 0..63"},
      {"render --preset ludicrous -o OUT.mp4", "unknown x264 preset"},
      {"render --quality ultra -o OUT.mp4", "--quality ultra"},
      {"render --set 'alpha=1e400' -o OUT.mp4", "alpha"},
      {"render SCENES/empty.toml -o OUT.mp4", "empty.toml: the scene file sets nothing"},
      {"render SCENES/binary.toml -o OUT.mp4", "binary.toml: is a binary file"},
      {"render SCENES/truncated.toml -o OUT.mp4", "truncated.toml:2:"},
      {"render SCENES/nested.toml -o OUT.mp4", "nested.toml:1:"},
      {"render SCENES/duplicate.toml -o OUT.mp4", "duplicate.toml:3:"},
      {"render SCENES/mistyped.toml -o OUT.mp4", "mistyped.toml:3: unknown key 'Theeta' (did you mean 'Theta'?)"},
      {"render SCENES/wrong_type.toml -o OUT.mp4", "wrong_type.toml:2: cannot read fps='fast'"},
      {"render SCENES/bad_colour.toml -o OUT.mp4", "bad_colour.toml:3: colors.bob"},
      {"render SCENES/bad_model.toml -o OUT.mp4", "did you mean 'pendulum'"},
      // Two letters swapped is one slip, and gets its suggestion.
      {"render SCENES/transposed.toml -o OUT.mp4", "transposed.toml:2: unknown key 'alpah' (did you mean 'alpha'?)"},
      {"render --set alpah=0.8 -o OUT.mp4", "did you mean 'alpha'?"},
      {"render --set Thtea=40 -o OUT.mp4", "did you mean 'Theta'?"},
      // A frame count beyond any integer is refused, not wrapped to a negative one.
      {"render --speed 1e-300 -o OUT.mp4", "more than 1e8 frames"},
      {"render --fps 240 --speed 1e-12 -o OUT.mp4", "more than 1e8 frames"},
      {"render --at nan -o OUT.png", "--at nan is not a time"},
      {"render --at inf -o OUT.png", "--at inf is not a time"},
      {"render --at -inf -o OUT.svg", "--at -inf is not a time"},
  };
  for (const auto& c : cases) check_refused(c);
}

TEST_CASE("solve writes CSV that reads back to the same doubles", "[cli]") {
  ScratchDirectory dir;
  const auto r = run_vibra("solve undamped --set dt=0.1 --set T=0.2 -o " + (dir / "u.csv"));
  REQUIRE(r.exit_code == 0);
  std::FILE* f = std::fopen((dir / "u.csv").c_str(), "r");
  char text[512] = {};
  std::fread(text, 1, sizeof text - 1, f);
  std::fclose(f);
  CHECK(std::string(text) == "t,u,v\n0,1,0\n0.1,0.8026079119782128,-3.558205396299734\n"
                             "0.2,0.2883589207400532,-5.7116876070274785\n");
  // Each cell reads back to the very double the solver computed (shortest
  // round-trip printing), not merely to something close.
  const auto written = vibra::test::csv_rows(vibra::test::read_file(dir / "u.csv"));
  const auto computed = vibra::test::rows(*vibra::test::trajectory("undamped", {"dt=0.1", "T=0.2"}));
  REQUIRE(written.size() == computed.size() + 1);
  for (size_t i = 0; i < computed.size(); ++i) {
    REQUIRE(written[i + 1].size() == computed[i].size());
    for (size_t j = 0; j < computed[i].size(); ++j) {
      INFO("row " << i << ", column " << j << ": " << written[i + 1][j]);
      CHECK(std::strtod(written[i + 1][j].c_str(), nullptr) == computed[i][j]);
    }
  }
}

TEST_CASE("solve --every and help", "[cli]") {
  const auto r = run_vibra("solve pendulum --set steps_per_period=10 --set periods=1 --every 4");
  REQUIRE(r.exit_code == 0);
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1 + 4);  // header, steps 0, 4, 8, and the last (10)
  const auto help = run_vibra("solve pendulum --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Contains("Theta") && Catch::Contains("deg") && Catch::Contains("default: 70"));
  CHECK_THAT(run_vibra("solve --help").out, Catch::Contains("elastic-pendulum") && Catch::Contains("pefrl"));
}

TEST_CASE("solve to a closed pipe ends quietly", "[cli]") {
  const auto r = run_vibra("solve pendulum --set T=inf | head -3");
  CHECK(r.exit_code == 0);
  CHECK(r.out.size() > 10);
  CHECK(r.err.empty());
}

TEST_CASE("plot, ascii and analyze refuse bad input with one line and exit code 2", "[cli]") {
  const BadInput cases[] = {
      {"plot pendulum --panels theta,Q -o OUT.png", "unknown panel 'Q'"},
      {"plot pendulum", "needs an output file"},
      {"plot pendulum -o OUT.gif", "end the file name in .png, .svg or .pdf"},
      {"plot undamped --panels path -o OUT.png", "unknown panel 'path'"},
      {"plot pendulum --size 10x10 -o OUT.png", "figure size 10x10 is out of range"},
      {"plot pendulum --size 9000x9000 -o OUT.png", "each side 1..8192"},
      {"plot pendulum --set Theta=nan -o OUT.png", "Theta"},
      {"plot pendulum -o /dev/full/x.png", "is a file, not a directory"},
      {"ascii pendulum --width 0", "--width must be 1..10000"},
      {"ascii pendulum --ymin 1 --ymax 0", "ymin must be less than ymax"},
      {"ascii pendulum --symbols ''", "--symbols: the value is empty"},
      {"ascii pendulum --counter days", "--counter days"},
      {"ascii pendulum --rate -1", "--rate: -1 must be a number 0..1000000"},
      {"ascii pendulum --columns theta,Q", "no column 'Q'"},
      {"ascii pendulum --ymin 1", "give both --ymin and --ymax"},
      {"ascii pendulm", "did you mean 'pendulum'"},
      {"ascii pendulum --set alpah=0.8", "did you mean 'alpha'?"},
      {"plot pendulum --set alpah=0.8 -o OUT.png", "did you mean 'alpha'?"},
      {"analyze nonsense", "unknown experiment 'nonsense'"},
      {"analyze convergence pendulum --set scheme=rk4", "no exact solution"},
      {"analyze convergence undamped --levels 0", "--levels: 0 must be a whole number 2..20: each level halves dt"},
      {"analyze convergence undamped --levels 1", "--levels: 1 must be a whole number 2..20"},
      {"analyze convergence undamped --levels 21", "--levels: 21 must be a whole number 2..20"},
      {"analyze convergence undamped --levels 2.5", "--levels: 2.5 must be a whole number 2..20"},
      {"analyze energy --schemes rk9", "'rk9' is not a valid scheme"},
      {"analyze energy --dt 0.05,-1", "must be a positive number"},
      {"analyze energy --T abc", "cannot read --T='abc'"},
      {"analyze orbit --orbits 0", "--orbits: 0 must be a whole number 1..1e+09"},
      {"analyze frequency --w -1", "--w must be a positive"},
      {"analyze empirical undamped --dt 0", "must be a positive number"},
      {"analyze energy -o OUT.bmp", "end the file name in .png, .svg or .pdf"},
  };
  for (const auto& c : cases) check_refused(c);
}
