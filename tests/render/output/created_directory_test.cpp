// A frame pattern's directory is part of the product: made when missing, and
// removed again when the run that made it does not finish.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "render/output/created_directory.hpp"
#include "render/output/output_error.hpp"

using vibra::render::CreatedDirectory;
using vibra::render::OutputError;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

TEST_CASE("CreatedDirectory makes missing parents and removes them unless kept", "[png]") {
  ScratchDirectory dir;
  {
    CreatedDirectory made(dir / "a/b/c");
    CHECK(fs::is_directory(dir / "a/b/c"));
    CHECK(made.created().size() == 3);
  }
  CHECK(dir.empty());  // not kept: all three are gone
  {
    CreatedDirectory made(dir / "a/b");
    made.keep();
  }
  CHECK(fs::is_directory(dir / "a/b"));
  {
    CreatedDirectory existing(dir / "a/b");  // made by no one here: never removed
    CHECK(existing.created().empty());
  }
  CHECK(fs::is_directory(dir / "a/b"));
  {
    CreatedDirectory made(dir / "x/y");
    std::ofstream(dir / "x/y/foreign") << "not ours";  // something else wrote there: it stays
  }
  CHECK(fs::exists(dir / "x/y/foreign"));
}

TEST_CASE("CreatedDirectory refuses a file in the way, naming it", "[png]") {
  ScratchDirectory dir;
  std::ofstream(dir / "file") << "x";
  CHECK_THROWS_AS(CreatedDirectory(dir / "file/frames"), OutputError);
  CHECK_THROWS_WITH(CreatedDirectory(dir / "file/frames"), Catch::Contains("is a file, not a directory"));
  CHECK_THROWS_WITH(CreatedDirectory(dir / "file"), Catch::Contains("is a file, not a directory"));
}

TEST_CASE("render creates the directory of a frame pattern or a frames directory", "[render]") {
  ScratchDirectory dir;
  const std::string quick = "render pendulum_book --size 160x90 --set periods=0.25 -q -o ";
  const auto pattern = run_vibra(quick + (dir / "frames/deeper/tmp_%04d.png"));
  INFO(pattern.err);
  REQUIRE(pattern.exit_code == 0);
  CHECK(fs::exists(dir / "frames/deeper/tmp_0000.png"));
  const auto directory = run_vibra(quick + (dir / "made/"));
  INFO(directory.err);
  REQUIRE(directory.exit_code == 0);
  CHECK(fs::exists(dir / "made/tmp_0000.png"));
}

TEST_CASE("a moved CreatedDirectory hands over what it made, and one assigned over removes its own first", "[png]") {
  ScratchDirectory dir;
  {
    CreatedDirectory first(dir / "one/two/");  // a trailing separator names the same directory
    CHECK(first.created() == std::vector<fs::path>{dir / "one", dir / "one/two"});
    CreatedDirectory second(std::move(first));
    CHECK(first.created().empty());
    CHECK(second.created().size() == 2);
    CreatedDirectory third(dir / "three");
    third = std::move(second);  // "three" was third's own: removed now; "one/two" is third's to remove
    CHECK_FALSE(fs::exists(dir / "three"));
    CHECK(fs::is_directory(dir / "one/two"));
    CHECK(third.created().size() == 2);
  }
  CHECK(dir.empty());  // each made directory removed once, by its last owner
}
