// classify_output: the kind of output a -o name is, one table for every command (render/encode/output_kind.hpp).
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "cli_support.hpp"
#include "render/encode/output_kind.hpp"

using vibra::render::classify_output;
using vibra::render::OutputKind;
namespace fs = std::filesystem;

TEST_CASE("classify_output: every kind by its name, extensions in any case", "[output][kind]") {
  const struct {
    const char* name;
    OutputKind kind;
  } cases[] = {
      {"-", OutputKind::stream},
      {"talk.html", OutputKind::page},        {"TALK.HTML", OutputKind::page},
      {"swing.mp4", OutputKind::video},       {"swing.MP4", OutputKind::video},
      {"swing.webm", OutputKind::video},      {"swing.mkv", OutputKind::video},
      {"swing.mov", OutputKind::video},       {"swing.ogv", OutputKind::video},
      {"swing.gif", OutputKind::video},       {"swing.yuv", OutputKind::video},
      {"swing.nut", OutputKind::video},       {"swing.flv", OutputKind::video},
      {"frames/tmp_%04d.png", OutputKind::frames}, {"frames/", OutputKind::frames},
      {"still.png", OutputKind::picture},     {"still.SVG", OutputKind::picture},
      {"still.pdf", OutputKind::picture},
      {"notes.txt", OutputKind::unknown},     {"swing", OutputKind::unknown},
      {"", OutputKind::unknown},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    CHECK(classify_output(c.name) == c.kind);
  }
}

TEST_CASE("classify_output: an existing folder is frames, whatever its name says but .html or a video's", "[output][kind]") {
  vibra::test::ScratchDirectory dir;
  fs::create_directory(dir.path / "shots");
  fs::create_directory(dir.path / "shot.png");
  CHECK(classify_output((dir.path / "shots").string()) == OutputKind::frames);
  CHECK(classify_output((dir.path / "shot.png").string()) == OutputKind::frames);
}
