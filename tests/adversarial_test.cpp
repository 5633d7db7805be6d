// The adversarial matrix (issues 27 and 30): hostile values for every
// numeric option and key, empty values, paths that are folders, read-only or
// odd, broken inputs to concat. Each refusal is checked the one way
// (cli_support.hpp, check_refused): exit code 2, exactly one line on stderr
// naming the problem, at most about 240 characters, nothing at the output.
// The odd paths that are valid (spaces, unicode, a newline) must work, and
// text that reaches a page must arrive escaped.
#include <catch2/catch.hpp>
#include <chrono>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::check_refusal;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {

/// Values no numeric option takes; each case's message must name the option.
const std::vector<std::string> kBadNumbers = {"''", "nan", "inf", "-inf", "1e308", "1e400", "30abc", "0x10", "'foo(1)'", "-5"};

struct Case {
  std::string args, expected;
};

std::size_t longest_line(const std::string& text) {
  std::size_t longest = 0, start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    longest = std::max(longest, end - start);
  return std::max(longest, text.size() - start);
}

}  // namespace

TEST_CASE("adversarial: every numeric render option refuses hostile numbers", "[cli][adversarial]") {
  // 8 options x 10 values = 80 cases.
  const std::vector<std::pair<std::string, std::string>> options = {
      {"--fps", "fps"},         {"--speed", "speed"},     {"--every", "--every"}, {"--threads", "--threads"},
      {"--crf", "--crf"},       {"--window", "window"},   {"--at", "--at"},       {"--exaggerate", "exaggerate"}};
  int cases = 0;
  for (const auto& [option, named] : options)
    for (const auto& value : kBadNumbers) {
      const std::string out = option == "--at" ? " -o OUT.png" : " -o OUT.mp4";
      check_refused("render --set periods=0.2 " + option + " " + value + out, named);
      ++cases;
    }
  CHECK(cases == 80);
}

TEST_CASE("adversarial: model keys refuse hostile numbers, blamed on the key", "[cli][adversarial]") {
  // 6 keys x 8 values = 48 cases, through solve; the message names the key.
  const std::vector<std::string> keys = {"dt", "T", "Theta", "alpha", "periods", "steps_per_period"};
  const std::vector<std::string> values = {"nan", "1e308", "1e400", "-inf", "30abc", "0x10", "'foo(1)'", "''"};
  int cases = 0;
  for (const auto& key : keys)
    for (const auto& value : values) {
      check_refused("solve pendulum --set " + key + "=" + value + " -o OUT.csv", key);
      ++cases;
    }
  CHECK(cases == 48);
}

TEST_CASE("adversarial: empty and malformed values of every kind of option", "[cli][adversarial]") {
  const Case cases[] = {
      // An empty value is an error, never the default (10).
      {"render --size '' -o OUT.mp4", "--size: the value is empty"},
      {"render --quality '' -o OUT.mp4", "--quality: the value is empty"},
      {"render --segment '' -o OUT.mp4", "--segment: the value is empty"},
      {"render --panels '' -o OUT.mp4", "--panels: the value is empty"},
      {"render --layout '' -o OUT.mp4", "--layout: the value is empty"},
      {"render --compare '' -o OUT.mp4", "--compare: the value is empty"},
      {"render --window-mode '' -o OUT.mp4", "--window-mode: the value is empty"},
      {"render --codec '' -o OUT.mp4", "--codec: the value is empty"},
      {"render --preset '' -o OUT.mp4", "--preset: the value is empty"},
      {"render --format '' -o OUT.mp4", "--format: the value is empty"},
      // Sizes (7).
      {"render --size 64x -o OUT.mp4", "WxH"},
      {"render --size 1e9x1e9 -o OUT.mp4", "WxH"},
      {"render --size -64x36 -o OUT.mp4", "WxH"},
      {"render --size 0x0 -o OUT.mp4", "1..8192"},
      {"render --size 64x36x2 -o OUT.mp4", "WxH"},
      {"render --size 99999999999x1 -o OUT.mp4", "WxH"},
      {"plot pendulum --size 100000x100000 -o OUT.png", "8192"},
      // ascii and analyze options (9).
      {"ascii undamped --width ''", "--width: the value is empty"},
      {"ascii undamped --width 1e308", "--width"},
      {"ascii undamped --rate -1", "--rate"},
      {"ascii undamped --rate nan", "--rate"},
      {"ascii undamped --rate 1e308", "--rate"},
      {"analyze orbit --orbits 0", "--orbits"},
      {"analyze orbit --orbits 1e10", "--orbits"},
      {"analyze orbit --orbits 30abc", "--orbits"},
      {"analyze orbit --orbits ''", "empty value for --orbits"},
      // Parser text gets a fix (5).
      {"solve pendulum --set dt=nan -o OUT.csv", "write a decimal number or an expression"},
      {"solve pendulum --set dt=0x10 -o OUT.csv", "write a decimal number or an expression"},
      {"solve pendulum --set dt=1.0abc -o OUT.csv", "write a decimal number or an expression"},
      {"solve pendulum --set 'dt=foo(1)' -o OUT.csv", "write a decimal number or an expression"},
      {"render --fps 30abc -o OUT.mp4", "write a decimal number or an expression"},
      // An input that overflows is blamed on the input, not on dt (3).
      {"solve vibration --set I=1e308 -o OUT.csv", "I=1e308 must be a number"},
      {"solve vibration --set 'F=ln(0)' -o OUT.csv", "an input is infinite or overflows"},
      {"solve vibration --set 'F=1/0' -o OUT.csv", "an input is infinite or overflows"},
      // Work without bound is refused with the size it would need (3).
      {"render bumpy_road --set speed=1e12 -o OUT.mp4", "heights, more than 2e7"},
      {"render bumpy_road --set dx=1e-12 -o OUT.mp4", "heights, more than 2e7"},
      {"render bumpy_road --set dx=1e9 -o OUT.mp4", "coarser than the road's shape"},
      {"render bumpy_road --set road=bumps --set wavelength=1e-6 --set dx=1 -o OUT.mp4", "coarser than the road's shape"},
      {"solve pendulum --set T=1e15 --set dt=1e-9 -o OUT.csv", "too many"},
      // A window below a time step: once heap corruption, once an endless tick loop (2).
      {"render --window 1e-300 --at 0.5 -o OUT.png", "narrower than one time step"},
      {"render --window 1e-16 --set periods=0.2 -o OUT.mp4", "narrower than one time step"},
  };
  for (const auto& c : cases) check_refused(c.args, c.expected);
  CHECK(std::size(cases) == 41);
}

TEST_CASE("adversarial: adaptive runs doubles cannot advance end in seconds with one line", "[cli][adversarial][adaptive]") {
  // docs/schemes.md, "Adaptive": each once wrote rows at t = 0 without end,
  // or shrank the step until a vague message.
  const Case cases[] = {
      // A tolerance below what doubles resolve, refused before the run (3).
      {"solve undamped --set scheme=dopri5 --set rtol=1e-15 -o OUT.csv", "rtol=1e-15 is out of range"},
      {"solve undamped --set scheme=rkf45 --set rtol=5e-15 -o OUT.csv", "in [1e-14, 1) (doubles resolve no finer)"},
      {"render spring --set scheme=dopri5 --set rtol=1e-16 --at 1 -o OUT.png", "rtol=1e-16 is out of range"},
      // u'' = u^3 from u = 1 blows up at t = 1.854: the step underflows there (2).
      {"solve vibration --set scheme=dopri5 --set 's=-u^3' --set dt=0.01 --set T=3 -o OUT.csv",
       "dopri5: the step size fell below what doubles resolve at t = 1.85"},
      {"solve vibration --set scheme=rkf45 --set 's=-u^3' --set dt=0.01 --set T=3 -o OUT.csv",
       "rkf45: the step size fell below what doubles resolve at t = 1.85"},
      // F is undefined after t = 0.5: no step size gives a finite error (3).
      {"solve vibration --set scheme=dopri5 --set 'F=sqrt(0.5-t)' --set T=1 -o OUT.csv",
       "the error estimate is not finite for any step size at t = 0.5"},
      {"solve vibration --set scheme=rkf45 --set 'F=sqrt(0.5-t)' --set T=1 -o OUT.csv", "check the --set values"},
      {"render spring --set scheme=dopri5 --set 'F=sqrt(0.5-t)' --set T=1 -o OUT.mp4", "check the --set values"},
  };
  for (const auto& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    check_refused(c.args, c.expected);
    CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5);
  }
}

TEST_CASE("adversarial: the adaptive runs that once never advanced now reach T", "[cli][adversarial][adaptive]") {
  // atol = 1e-300 with v(0) = 0 overflowed the starting rule's norms, and
  // F = 1e200 t its second one: every step had h = 0.
  const std::pair<std::string, double> runs[] = {{"undamped --set atol=1e-300 --set dt=0.001 --set T=0.01", 0.01},
                                                 {"vibration --set 'F=1e200*t' --set dt=0.5 --set T=10", 10}};
  for (const auto& [run, T] : runs)
    for (const std::string scheme : {"dopri5", "rkf45"}) {
      const auto r = run_vibra("solve " + run + " --set scheme=" + scheme);
      INFO(run << " " << scheme << ": " << r.err);
      REQUIRE(r.exit_code == 0);
      const auto table = vibra::test::csv_rows(r.out);
      CHECK(table.size() < 5000);
      for (std::size_t i = 2; i < table.size(); ++i) REQUIRE(std::stod(table[i][0]) > std::stod(table[i - 1][0]));
      CHECK(std::stod(table.back()[0]) == Approx(T).epsilon(1e-12));
    }
}

TEST_CASE("adversarial: long values and newlines are quoted shortened, on one line", "[cli][adversarial]") {
  ScratchDirectory dir;
  const std::string huge(100000, '1');
  for (const std::string& args : {"solve pendulum --set 'dt=" + huge + "x' -o " + (dir / "a.csv"),
                                  "render --at '" + huge + "+' -o " + (dir / "a.png"),
                                  "solve pendulum --set \"$(printf 'dt=1\\n2')\" -o " + (dir / "a.csv"),
                                  "render --at 1e308 -o " + (dir / "a.png"),
                                  "render --set 'Theta=" + huge + "' -o " + (dir / "a.mp4")}) {
    INFO(args.substr(0, 200));
    const auto r = run_vibra(args);
    check_refusal(r, "");
    CHECK(longest_line(r.err) <= 240);
    CHECK(r.err.find(std::string(200, '1')) == std::string::npos);
  }
  CHECK(dir.empty());
}

TEST_CASE("adversarial: outputs onto folders and into read-only places", "[cli][adversarial]") {
  ScratchDirectory dir;
  fs::create_directory(dir / "folder.csv");
  fs::create_directory(dir / "folder.mp4");
  fs::create_directory(dir / "folder.png");
  fs::create_directory(dir / "folder.html");
  const Case cases[] = {
      {"solve pendulum -o " + (dir / "folder.csv"), "is a folder, not a file"},
      {"render --set periods=0.2 -o " + (dir / "folder.mp4"), "is a folder, not a file"},
      {"render --at 0.5 -o " + (dir / "folder.png"), "is a folder, not a file"},
      {"render --set periods=0.2 -o " + (dir / "folder.html"), "is a folder, not a file"},
      {"plot pendulum -o " + (dir / "folder.png"), "is a folder, not a file"},
      {"analyze convergence undamped --levels 3 -o " + (dir / "folder.png"), "is a folder, not a file"},
      // /proc refuses new files even to root.
      {"solve pendulum -o /proc/vibra_adversarial.csv", "/proc/vibra_adversarial.csv"},
      {"render --set periods=0.2 -o /proc/vibra_adversarial.mp4", "/proc/vibra_adversarial.mp4"},
      {"plot pendulum -o /proc/self/vibra_adversarial.png", "'/proc/self' is not writable"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_vibra(c.args);
    INFO(r.err);
    check_refusal(r, c.expected);
  }
  for (const char* folder : {"folder.csv", "folder.mp4", "folder.png", "folder.html"}) CHECK(fs::is_empty(dir / folder));
  CHECK_FALSE(fs::exists("/proc/vibra_adversarial.csv"));
}

TEST_CASE("adversarial: files vibra may not read or write are refused as such, naming them", "[cli][adversarial]") {
  ScratchDirectory dir;
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    fs::permissions(dir / name, fs::perms::none);
    return dir / name;
  };
  const std::string scene = write("scene.toml", "model = \"pendulum\"\n");
  const std::string road = write("road.txt", "0\n0.01\n0\n0.02\n0\n");
  const std::string storyboard = write("lecture.toml", "[[shot]]\ncard = \"A\"\nseconds = 1\n");
  fs::create_directory(dir / "read_only");
  fs::permissions(dir / "read_only", fs::perms::owner_read | fs::perms::owner_exec);
  // Root reads and writes every file: without the two capabilities that let
  // it, it meets the permissions as any other user does.
  const std::string launcher = ::geteuid() == 0 ? "setpriv --bounding-set=-dac_override,-dac_read_search " : "";
  const std::string denied = "Permission denied: give vibra read permission (chmod a+r) or copy it";
  check_refused("render " + scene + " --at 1 -o OUT.png", "cannot read the scene file '" + scene + "': " + denied, launcher);
  check_refused("solve bumpy-road --set road=" + road + " --set dx=0.1 -o OUT.csv",
                "cannot read the road file '" + road + "': " + denied, launcher);
  check_refused("lecture " + storyboard + " -o OUT.mp4", "cannot read the storyboard '" + storyboard + "': " + denied,
                launcher);
  check_refused("solve pendulum -o " + (dir / "read_only/out.csv"), "is not writable", launcher);
  CHECK(fs::is_empty(dir / "read_only"));
}

TEST_CASE("adversarial: concat of broken parts, or onto a part, writes nothing", "[cli][adversarial][video]") {
  ScratchDirectory dir;
  const std::string small = " --size 160x90 --fps 10 --set periods=0.5 -q";
  for (int k = 0; k < 2; ++k)
    REQUIRE(run_vibra("render" + small + " --segment " + std::to_string(k) + "/2 -o " + (dir / "p.mp4")).exit_code == 0);
  const std::string p0 = dir / "p.seg-0-of-2.mp4", p1 = dir / "p.seg-1-of-2.mp4";
  std::ofstream(dir / "zero.mp4", std::ios::binary).flush();
  const std::string bytes = read_file(p1);
  std::ofstream(dir / "truncated.mp4", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  // Damaged boxes (the container's structure): bit flips inside the frames'
  // payload alone would pass, as concat copies packets without decoding them.
  std::string corrupted = bytes;
  for (std::size_t i = 8; i < bytes.size(); i += 61) corrupted[i] = static_cast<char>(corrupted[i] ^ 0x5a);
  std::ofstream(dir / "corrupted.mp4", std::ios::binary) << corrupted;
  std::ofstream(dir / "text.mp4") << "just some text, not a video\n";
  std::ofstream(dir / "image.mp4", std::ios::binary) << std::string("\x89PNG\r\n\x1a\n", 8) << std::string(100, '\0');
  fs::create_directory(dir / "joined_folder.mp4");
  const std::string out = dir / "joined.mp4";
  const Case cases[] = {
      {"concat " + p0 + " " + (dir / "zero.mp4") + " -o " + out, "zero.mp4"},
      {"concat " + p0 + " " + (dir / "truncated.mp4") + " -o " + out, "truncated.mp4"},
      {"concat " + p0 + " " + (dir / "corrupted.mp4") + " -o " + out, "corrupted.mp4"},
      {"concat " + p0 + " " + (dir / "text.mp4") + " -o " + out, "text.mp4"},
      {"concat " + p0 + " " + (dir / "image.mp4") + " -o " + out, "image.mp4"},
      {"concat " + p0 + " " + p1 + " -o " + p0, "this run reads it"},
      {"concat " + p0 + " " + p1 + " -o " + (dir / "joined_folder.mp4"), "is a folder, not a file"},
      {"concat " + p0 + " " + p1 + " -o ''", "the output path is empty"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_vibra(c.args);
    INFO(r.err);
    check_refusal(r, c.expected);
    CHECK_FALSE(fs::exists(out));
    fs::remove(out);  // so one failure does not fail every case after it
  }
  CHECK(read_file(p1) == bytes);  // the parts are untouched
  CHECK(fs::is_empty(dir / "joined_folder.mp4"));
}

TEST_CASE("adversarial: odd but valid paths work, and the wrote line stays one line", "[cli][adversarial]") {
  ScratchDirectory dir;
  for (const std::string name : {"with space.csv", "unicodé θ ✓.csv", "new\nline.csv"}) {
    INFO(name);
    const std::string path = dir / name;
    std::string quoted = "'";
    for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    quoted += "'";
    const auto r = run_vibra("solve undamped --set T=1 -o " + quoted);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(fs::is_regular_file(path));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') <= 1);  // "wrote ..." at most, a newline in it escaped
  }
}

TEST_CASE("adversarial: markup in names reaches the page escaped", "[cli][adversarial][page]") {
  ScratchDirectory dir;
  // A file name and a folder name the page shows (in the command line and
  // its links): both carry markup that would run if pasted raw.
  const std::string folder = dir / "x<";
  const std::string page = folder + "/script><img src=x onerror=alert(1)>.html";
  const auto r = run_vibra("render --size 160x90 --fps 5 --set periods=0.3 -q --frames-player -o '" + page + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string html = read_file(page);
  REQUIRE_FALSE(html.empty());
  CHECK(html.find("<img src=x onerror=alert(1)>") == std::string::npos);
  CHECK(html.find("x</script>") == std::string::npos);
}

TEST_CASE("adversarial: a huge amplitude draws its still in bounded time", "[cli][adversarial]") {
  // Theta = 1e9 degrees once took minutes in Cairo (an arc of 1.7e7 turns);
  // the bound is a hang guard, far above the ordinary second.
  ScratchDirectory dir;
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_vibra("render --set Theta=1e9 --at 1 -q -o " + (dir / "still.png"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(seconds < 60);
  CHECK(vibra::test::png_size(dir / "still.png") == std::pair{1280, 720});
}

TEST_CASE("adversarial: a lecture's inputs as its outputs, and huge keys, refused before any work",
          "[cli][adversarial][lecture]") {
  // Each case: the files it starts with, the command (in the case's folder),
  // what the one line names. Refused quickly (no shot rendered, no megabytes
  // kept), exit 2, and every file as it was, nothing added.
  struct FileCase {
    std::vector<std::pair<std::string, std::string>> files;
    std::string args, expected;
  };
  // A lecture long enough that rendering it would show in the time taken.
  const std::string story = "size = \"640x360\"\nfps = 30\n[[shot]]\ncard = \"A\"\nseconds = 60\n"
                            "[[shot]]\nscene = \"pendulum\"\nseconds = 60\n";
  const std::string huge_key(5 << 20, 'k'), long_key(200, 'k');
  const std::vector<FileCase> cases = {
      {{{"lec.mp4", story}}, "lecture lec.mp4 -o lec.mp4", "this run reads it, as the storyboard"},
      {{{"lec.webm", story}}, "lecture lec.webm -o lec.webm", "this run reads it, as the storyboard"},
      {{{"talk.vtt", story}}, "lecture talk.vtt -o talk.mp4", "this run reads it, as the storyboard"},
      {{{"story.toml", story + "[[shot]]\nscene = \"cut.vtt\"\n"}, {"cut.vtt", "model = \"undamped\"\nT = 1\n"}},
       "lecture story.toml -o cut.mp4", "this run reads it, as the scene file"},
      {{{"story.toml", story + huge_key + " = 1\n"}}, "lecture story.toml -o out.mp4",
       "is longer than 1024 KiB, the most vibra reads of it"},
      {{{"story.toml", story + long_key + " = 1\n"}}, "lecture story.toml -o out.mp4",
       "a key of 200 characters: keys are at most 64"},
      {{{"story.toml", "[[shot]]\ncard = \"A\"\n" + long_key + " = 1\n"}}, "lecture story.toml -o out.mp4",
       "story.toml:3: a key of 200 characters"},
      {{{"story.toml", "[[shot]]\nscene = \"s.toml\"\n"}, {"s.toml", "model = \"undamped\"\n" + huge_key + " = 1\n"}},
       "lecture story.toml -o out.mp4", "the scene file"},
      {{{"s.toml", "model = \"undamped\"\n" + huge_key + " = 1\n"}}, "render s.toml -o out.mp4",
       "is longer than 1024 KiB"},
      {{{"s.toml", "model = \"undamped\"\n[colors]\n" + long_key + " = \"red\"\n"}}, "render s.toml -o out.mp4",
       "s.toml:3: a key of 200 characters"},
  };
  for (const FileCase& c : cases) {
    ScratchDirectory dir;
    for (const auto& [name, text] : c.files) std::ofstream(dir / name, std::ios::binary) << text;
    INFO(c.args);
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_vibra(c.args, "cd '" + dir.path.string() + "' && ");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(r.err);
    check_refusal(r, c.expected);
    CHECK(longest_line(r.err) <= 240);
    CHECK(seconds < 5);  // one shot alone takes longer than this to render
    CHECK(std::size_t(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator())) == c.files.size());
    for (const auto& [name, text] : c.files) CHECK(read_file(dir / name) == text);
  }
}
