// `vibra render -o PAGE.html` and `vibra plot -o FIGURE.html` through the
// real executable: what the page holds and links, its companions (videos or
// frames, and the CSV) in PAGE_files/, bad input. tests/browser/check_lecture_page.py checks the page in Chromium.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::check_refusal;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {
size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

size_t lines(const std::string& text) { return count(text, "\n"); }

const std::string kShortPage = " --size 320x180 --set periods=0.5 -q ";  // 31 frames at 30 fps, 61 steps
}  // namespace

TEST_CASE("a lecture page: video sources, plots' data, each fact once, the command, downloads", "[page][video]") {
  ScratchDirectory dir;
  fs::create_directory(dir.path / "my lectures ø");
  const fs::path page = dir.path / "my lectures ø" / "Pendel #1 ø.html";
  // From the scratch folder, as given: the page's "Made by" shows it so (an absolute path would be shown relative).
  REQUIRE(run_vibra("render" + kShortPage + "--set scheme=rk4 --set alpha=0.3 --every 4 -o 'my lectures ø/Pendel #1 ø.html'",
                    "cd '" + dir.path.string() + "' && ")
              .exit_code == 0);
  const std::string html = read_file(page);
  const fs::path files = page.parent_path() / "Pendel #1 ø_files";  // the companions' own folder
  for (const char* file : {"Pendel #1 ø.mp4", "Pendel #1 ø.webm", "Pendel #1 ø.csv"}) CHECK(fs::exists(files / file));

  // Links percent-encoded, MP4 first, then WebM; downloads of both videos and the CSV.
  const std::string folder = "Pendel%20%231%20%C3%B8_files/";
  vibra::test::check_in_order(html, {"<source src=\"" + folder + "Pendel%20%231%20%C3%B8.mp4\" type=\"video/mp4\">",
                                     "<source src=\"" + folder + "Pendel%20%231%20%C3%B8.webm\" type=\"video/webm\">"});
  CHECK_THAT(html, Catch::Contains("<a href=\"" + folder + "Pendel%20%231%20%C3%B8.csv\" download>CSV of the run</a>"));
  CHECK_THAT(html, Catch::Contains("<a href=\"" + folder + "Pendel%20%231%20%C3%B8.mp4\" download>MP4 video</a>"));
  CHECK_THAT(html, Catch::Contains("<a href=\"" + folder + "Pendel%20%231%20%C3%B8.webm\" download>WebM video</a>"));

  // Each key once, the settings given among them; the command that made the page.
  for (const char* key : {"scene", "model", "scheme", "dt", "T", "alpha", "periods", "frames", "size"}) {
    INFO(key);
    CHECK(count(html, std::string("<tr><td>") + key + "</td>") == 1);
  }
  CHECK_THAT(html, Catch::Contains("<tr><td>scheme</td><td>rk4</td></tr>") &&
                       Catch::Contains("<tr><td>frames</td><td>31 at 30 fps"));
  CHECK_THAT(html, Catch::Contains("<code id=\"command\">vibra render --size 320x180 --set periods=0.5 -q --set scheme=rk4 "
                                   "--set alpha=0.3 --every 4 -o &#39;my lectures ø/Pendel #1 ø.html&#39;"));  // shell-quoted, then HTML-escaped

  // The plots: the scene's three panels, uPlot and the page script inline, nothing from the network.
  CHECK_THAT(html, Catch::Contains("\"label\":\"θ (°)\"") && Catch::Contains("\"label\":\"S / mg, wire force\"") &&
                       Catch::Contains("\"label\":\"D / mg, air drag\""));
  CHECK_THAT(html, Catch::Contains("\"clock\":{\"fps\":30,\"frames\":31,"));
  CHECK_THAT(html, Catch::Contains("https://github.com/leeoniya/uPlot (v1.6.32)") && Catch::Contains("vibraPage"));
  CHECK(html.find("src=\"http") == std::string::npos);
  CHECK(html.find("href=\"http") == std::string::npos);
  CHECK(count(html, "<script") == 3);  // the data, uPlot, the page script: all inline

  // The CSV keeps every 4th step of the 61 and the last: 0, 4, ..., 60.
  const std::string csv = read_file(files / "Pendel #1 ø.csv");
  CHECK(csv.rfind("t,theta,omega,S,D\n", 0) == 0);
  CHECK(lines(csv) == 1 + 16);
}

TEST_CASE("a frames-player page: PNG frames and the same page around them", "[page]") {
  ScratchDirectory dir;
  REQUIRE(run_vibra("render" + kShortPage + "--frames-player -o " + (dir / "player.html")).exit_code == 0);
  CHECK(fs::exists(dir / "player_files/frame_0030.png"));
  CHECK(fs::exists(dir / "player_files/player.csv"));
  const std::string html = read_file(dir / "player.html");
  CHECK_THAT(html, Catch::Contains("\"media\":{\"kind\":\"frames\",\"prefix\":\"player_files/frame_\",\"digits\":4}") &&
                       Catch::Contains("<img id=\"frames\""));
  CHECK(html.find("<video") == std::string::npos);
}

TEST_CASE("a run too long for the page's data budget is decimated, not refused", "[heavy][page]") {
  ScratchDirectory dir;
  // 1e6 steps drawn in 3 frames; the CSV thinned to every 1000th step.
  REQUIRE(run_vibra("render --size 160x90 --set dt=1e-4 --set T=100 --speed 50 --every 1000 -q -o " + (dir / "long.html"))
              .exit_code == 0);
  CHECK(fs::file_size(dir / "long.html") < 2'000'000);
  CHECK(lines(read_file(dir / "long_files/long.csv")) == 1 + 1001);
  // 1e7 steps in a figure page.
  REQUIRE(run_vibra("plot undamped --set dt=1e-3 --set T=1e4 -o " + (dir / "figure.html")).exit_code == 0);
  CHECK(fs::file_size(dir / "figure.html") < 2'000'000);
  const std::string html = read_file(dir / "figure.html");
  CHECK_THAT(html, Catch::Contains("\"media\":{\"kind\":\"none\"},\"clock\":null"));
  CHECK_THAT(html, Catch::Contains("\"cells\":32768"));  // zoom reaches 32768 cells over the run
}

TEST_CASE("pages refuse what they cannot write, leaving nothing behind", "[page]") {
  check_refused("render" + kShortPage + "--every 0 -o OUT.html", "--every: 0 must be a whole number 1..");
  check_refused("render" + kShortPage + "--every 5 -o OUT.mp4", "--every thins the CSV beside a page");
  check_refused("plot pendulum --panels theta,phase -o OUT.html", "panel 'phase' is not against t");
  check_refused("plot pendulum --size 800x600 -o OUT.html", "drop --size");
  check_refused("plot pendulum -o /proc/version/figure.html", "not a directory");

  // The companions' folder name is taken by a file of the user's: nothing of the page is left.
  ScratchDirectory dir;
  std::ofstream(dir.path / "lecture_files") << "mine";
  const auto r = run_vibra("render" + kShortPage + "-o " + (dir / "lecture.html"));
  check_refusal(r, "was not written by vibra");
  const std::string taken = dir / "lecture_files";
  CHECK_THAT(r.err, Catch::Contains(taken) && Catch::Contains("--force"));
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(dir.path)) ++entries, (void)entry;
  CHECK(entries == 1);  // only the file that was there
  CHECK(read_file(dir.path / "lecture_files") == "mine");
}
