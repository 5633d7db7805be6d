// Determinism: the same inputs give the same bytes, across runs and thread
// counts, and the bytes are the ones held here (Debian 12's libm, Cairo,
// Pango, fonts and libdeflate; -ffp-contract=off keeps the arithmetic fixed). A
// changed hash after a deliberate change of numerics or drawing is updated
// here, in the same commit that explains it.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bits: enough to tell outputs apart, simple enough to inline.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t hash = 14695981039346656037ull) {
  for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every frame of a render, in name order, hashed as one stream.
std::uint64_t render_frames(const std::string& threads, std::vector<std::string>& frames) {
  ScratchDirectory dir;
  const auto r = run_vibra("render --set periods=1 --size 320x180 --fps 10 -q --threads " + threads + " -o " +
                           (dir / "f_%03d.png"));
  REQUIRE(r.exit_code == 0);
  std::vector<fs::path> names;
  for (const auto& e : fs::directory_iterator(dir.path)) names.push_back(e.path());
  std::sort(names.begin(), names.end());
  frames.clear();
  std::uint64_t hash = 14695981039346656037ull;
  for (const auto& name : names) {
    frames.push_back(read_file(name));
    hash = fnv1a(frames.back(), hash);
  }
  return hash;
}

}  // namespace

TEST_CASE("solve prints the same CSV on every run, the one held here", "[determinism]") {
  struct Case {
    const char* args;
    std::uint64_t hash;
  };
  const Case cases[] = {
      {"solve pendulum --set scheme=rk4 --set Theta=70 --set alpha=0.4 --set periods=3", 0x1cd3a901af16ba01ull},
      {"solve elastic-pendulum --set scheme=pefrl --set Theta=40 --set eps=0.1 --set gamma=0.05", 0xfc39dbadddecb133ull},
      {"solve vibration --set scheme=crank-nicolson --set 's=sin(u)' --set 'F=3*cos(4*t)' --set damping=quadratic "
       "--set b=0.2",
       0x4826b72b8372fcdfull},
      {"solve two-body --set scheme=euler-cromer --set periods=2", 0x6f344516948c59f1ull},
  };
  for (const auto& c : cases) {
    INFO("vibra " << c.args);
    const auto first = run_vibra(c.args), second = run_vibra(c.args);
    REQUIRE(first.exit_code == 0);
    CHECK(first.out == second.out);
    CHECK(fnv1a(first.out) == c.hash);
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
  CHECK(hash == 0xd485ae83de9e15daull);
}
