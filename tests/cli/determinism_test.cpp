// Determinism: the same inputs give the same bytes, across runs and thread
// counts, and the bytes are the ones held here (Debian 12's libm, Cairo,
// Pango, fonts and libdeflate; -ffp-contract=off keeps the arithmetic fixed).
// A hash is a tripwire: it says that something changed, not what. Each one
// is paired with a test of what the held output means (the cases named
// "... when its hash trips"): when a hash trips and its pair passes, the
// change kept the output right (a deliberate change of numerics or drawing);
// refresh the hash as docs/contributing.md says, in the same commit that
// explains the change. When the pair fails too, it names what is wrong.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "test_support.hpp"

using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bits: enough to tell outputs apart, simple enough to inline.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t hash = 14695981039346656037ull) {
  for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

// Every frame of a render, in name order, hashed as one stream.
std::uint64_t render_frames(const std::string& threads, std::vector<std::string>& frames) {
  ScratchDirectory dir;
  const auto r = run_vibra("render --set periods=1 --size 320x180 --fps 10 -q --threads " + threads + " -o " +
                           (dir / "f_%03d.png"));
  REQUIRE(r.exit_code == 0);
  std::vector<fs::path> names;
  for (const auto& e : fs::directory_iterator(dir.path))
    if (e.path().extension() == ".png") names.push_back(e.path());  // not the ledger of what vibra wrote
  std::sort(names.begin(), names.end());
  frames.clear();
  std::uint64_t hash = 14695981039346656037ull;
  for (const auto& name : names) {
    frames.push_back(read_file(name));
    hash = fnv1a(frames.back(), hash);
  }
  return hash;
}

std::string hex(std::uint64_t hash) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llxull", static_cast<unsigned long long>(hash));
  return text;
}

/// The solve runs whose CSV is held by its hash.
struct SolveCase {
  const char* model;
  std::vector<std::string> settings;  ///< each given as --set
  std::uint64_t hash;
  /// Largest |main quantity - reference| over the run allowed, the reference
  /// being RK4 at dt/16: about twice the scheme's own error at this dt as
  /// measured when the hash was set (in the comment). A wrong scheme is off
  /// by far more; a deliberate change of rounding, by far less.
  double accuracy;
};

const SolveCase kSolveCases[] = {
    {"pendulum", {"scheme=rk4", "Theta=70", "alpha=0.4", "periods=3"}, 0x1cd3a901af16ba01ull, 1e-5},  // 4.7e-6
    {"elastic-pendulum", {"scheme=pefrl", "Theta=40", "eps=0.1", "gamma=0.05"}, 0xfecdd6304713e2a4ull,
     0.03},  // 0.0143
    {"vibration", {"scheme=crank-nicolson", "s=sin(u)", "F=3*cos(4*t)", "damping=quadratic", "b=0.2"},
     0x4826b72b8372fcdfull, 0.05},                                                          // 0.025
    {"two-body", {"scheme=euler-cromer", "periods=2"}, 0x6f344516948c59f1ull, 0.07},  // 0.034
};

std::string solve_command(const SolveCase& c) {
  std::string command = std::string("solve ") + c.model;
  for (const auto& s : c.settings) command += " --set '" + s + "'";
  return command;
}

}  // namespace

TEST_CASE("solve prints the same CSV on every run, the one held here", "[determinism]") {
  for (const auto& c : kSolveCases) {
    INFO("vibra " << solve_command(c) << " (if only the hash differs, see the next test case)");
    const auto first = run_vibra(solve_command(c)), second = run_vibra(solve_command(c));
    REQUIRE(first.exit_code == 0);
    CHECK(first.out == second.out);
    CHECK(hex(fnv1a(first.out)) == hex(c.hash));
  }
}

TEST_CASE("solve's held CSV, when its hash trips: the model's columns, every step, the solver's doubles, accurate",
          "[determinism]") {
  for (const auto& c : kSolveCases) {
    INFO("vibra " << solve_command(c));
    const auto r = run_vibra(solve_command(c));
    REQUIRE(r.exit_code == 0);
    const auto csv = vibra::test::csv_rows(r.out);
    auto run = vibra::test::trajectory(c.model, c.settings);
    const auto info = run->info();
    const auto rows = vibra::test::rows(*run);
    // The header is the model's columns; one row per step, t = 0 to T.
    REQUIRE(!csv.empty());
    CHECK(csv[0] == info.columns);
    REQUIRE(csv.size() == rows.size() + 1);
    CHECK(rows.size() == size_t(info.mesh.steps) + 1);
    // Printing: every cell reads back to the solver's double, to the last bit.
    size_t misprinted = 0;
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < rows[i].size() && j < csv[i + 1].size(); ++j)
        misprinted += std::strtod(csv[i + 1][j].c_str(), nullptr) != rows[i][j];
    CHECK(misprinted == 0);
    // Numerics: the main quantity is within the scheme's error of a far finer RK4 run.
    auto settings = c.settings;
    for (auto& s : settings)
      if (s.rfind("scheme=", 0) == 0) s = "scheme=rk4";
    settings.push_back("dt=" + vibra::test::str(info.mesh.dt / 16));
    const auto reference = vibra::test::rows(*vibra::test::trajectory(c.model, settings));
    REQUIRE(reference.size() == 16 * (rows.size() - 1) + 1);
    double worst = 0;
    for (size_t i = 0; i < rows.size(); ++i) worst = std::max(worst, std::abs(rows[i][1] - reference[16 * i][1]));
    INFO("largest difference from RK4 at dt/16: " << worst);
    CHECK(worst <= c.accuracy);
  }
}

TEST_CASE("PNG frames are byte-identical across runs and thread counts, and held here", "[determinism][render]") {
  std::vector<std::string> one_thread, two_threads, again;
  const std::uint64_t hash = render_frames("1", one_thread);
  REQUIRE(one_thread.size() == 21);
  CHECK(render_frames("2", two_threads) == hash);
  CHECK(render_frames("2", again) == hash);
  CHECK(one_thread == two_threads);
  // Labels pasted from their kept images (LabelCache): the same glyphs, a
  // level of rounding apart at antialiased edges.
  INFO("if only the hash differs, see the next test case");
  CHECK(hex(hash) == hex(0x0eafefb9cb901361ull));
}

TEST_CASE("the held PNG frames, when their hash trips: 21 frames of 320x180, each the still at its time, in motion",
          "[determinism][render]") {
  ScratchDirectory dir;
  const std::string base = "render --set periods=1 --size 320x180 --fps 10 -q";
  REQUIRE(run_vibra(base + " -o " + (dir / "f_%03d.png")).exit_code == 0);
  std::vector<std::string> frames;
  for (int k = 0;; ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "f_%03d.png", k);
    if (!fs::exists(dir / name)) break;
    frames.push_back(read_file(dir / name));
    INFO(name);
    CHECK(vibra::test::png_size(dir / name) == std::pair{320, 180});
    if (k) CHECK(frames[k] != frames[k - 1]);  // the pendulum moves every frame
  }
  // periods=1 is T = 2 pi at the scene's speed, a period in 2 s: 20 intervals of 2 pi/20.
  CHECK(frames.size() == 21);
  // Each frame is the still drawn at its time (the still's labels set
  // afresh, the frames' pasted from kept images: alike to 45 dB, the
  // frame-truth test's bound), and not the still of a neighbouring frame.
  for (int k : {0, 7, 20}) {
    const std::string t = vibra::test::str(k * 2 * M_PI / 20);
    REQUIRE(run_vibra(base + " --at " + t + " -o " + (dir / "still.png")).exit_code == 0);
    char name[16];
    std::snprintf(name, sizeof name, "f_%03d.png", k);
    char neighbour[16];
    std::snprintf(neighbour, sizeof neighbour, "f_%03d.png", k == 20 ? 19 : k + 1);
    INFO("frame " << k << " against --at " << t);
    CHECK(vibra::test::psnr(dir / name, dir / "still.png") >= 45);
    CHECK(vibra::test::psnr(dir / neighbour, dir / "still.png") < 45);
  }
}
