// Frames of an earlier run are removed only when vibra's ledger proves it wrote them (render/output/frame_ledger.hpp).
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_support.hpp"
#include "render/output/file_listing.hpp"
#include "render/output/frame_ledger.hpp"

using vibra::test::read_file;
using vibra::test::write_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;
namespace vr = vibra::render;

namespace {
const std::string kSmallRunPeriods = " --size 160x90 -q --set periods=";  // periods=0.5: 31 frames, 0.1: 7


std::string frame(int i, int digits = 4) {
  char name[32];
  std::snprintf(name, sizeof name, "f_%0*d.png", digits, i);
  return name;
}
}  // namespace

TEST_CASE("file listing: names of any bytes come back as written, and a listing not in the form is none",
          "[output][ledger]") {
  ScratchDirectory dir;
  const vr::FileListing listing = {{"plain.png", vr::fingerprint_of("a", 1)},
                                   {"100% sure.png", vr::fingerprint_of("bc", 2)},
                                   {std::string("tab\there\nnewline.png"), vr::fingerprint_of("", 0)}};
  vr::write_file_listing(dir.path / "list", listing, "a test listing");
  const auto back = vr::read_file_listing(dir.path / "list");
  REQUIRE(back);
  CHECK(*back == listing);
  CHECK(vr::fingerprint_of("a", 1).size == 1);
  CHECK(vr::fingerprint_of("a", 1).hash == 0xaf63dc4c8601ec8cull);  // FNV-1a 64 of "a", its published test vector
  for (const char* bad : {"my own notes\n", "vibra manifest 1\n3 0000000000000001\n",
                          "vibra manifest 1\n1 0000000000000001 bad%G1.png\n", "vibra manifest 1\n1 01 cut%4\n"}) {
    INFO(bad);
    write_file(dir.path / "bad", bad);
    CHECK_FALSE(vr::read_file_listing(dir.path / "bad"));
  }
}

TEST_CASE("a whole run removes only the earlier frames its ledger proves, and says what it kept", "[output][ledger]") {
  ScratchDirectory dir;
  const std::string pattern = dir / "f_%04d.png";
  REQUIRE(run_vibra("render" + kSmallRunPeriods + "0.5 -o " + pattern).exit_code == 0);  // 31 frames and their ledger
  REQUIRE(fs::exists(dir.path / ".vibra-frames"));
  // Since then: the user edited one frame, locked another, and put files of their own under the pattern's names.
  write_file(dir.path / frame(20), read_file(dir.path / frame(20)) + "edited");
  const std::string locked = read_file(dir.path / frame(25));
  fs::permissions(dir.path / frame(25), fs::perms::none);
  write_file(dir.path / frame(40), "the user's own");
  write_file(dir.path / frame(30, 5), "the user's own, five digits");

  const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + pattern);  // 7 frames
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("removed 22 frames of an earlier run"));  // 7..30 but the edited and the locked
  CHECK_THAT(r.err, Catch::Contains("kept 4 files named like frames that vibra cannot prove it wrote"));
  for (int i = 7; i <= 30; ++i) CHECK(fs::exists(dir.path / frame(i)) == (i == 20 || i == 25));
  CHECK_THAT(read_file(dir.path / frame(20)), Catch::EndsWith("edited"));
  fs::permissions(dir.path / frame(25), fs::perms::owner_read);
  CHECK(read_file(dir.path / frame(25)) == locked);
  CHECK(read_file(dir.path / frame(40)) == "the user's own");
  CHECK(read_file(dir.path / frame(30, 5)) == "the user's own, five digits");
  // The new ledger lists this run's frames as they are on disk.
  const auto ledger = vr::read_file_listing(dir.path / ".vibra-frames");
  REQUIRE(ledger);
  for (int i = 0; i < 7; ++i) {
    INFO(frame(i));
    REQUIRE(ledger->count(frame(i)));
    CHECK(vr::fingerprint_file(dir.path / frame(i)) == ledger->at(frame(i)));
  }
  CHECK_FALSE(ledger->count(frame(40)));
}

TEST_CASE("a ledger vibra did not write is neither trusted nor replaced", "[output][ledger]") {
  ScratchDirectory dir;
  write_file(dir.path / frame(9), "the user's frame");
  SECTION("the user's own file of that name") {
    write_file(dir.path / ".vibra-frames", "my notes");
    const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + (dir / "f_%04d.png"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(read_file(dir.path / ".vibra-frames") == "my notes");
    CHECK_THAT(r.err, Catch::Contains("kept .vibra-frames, which vibra did not write"));
  }
  SECTION("a ledger in vibra's form whose entry does not match the file") {
    vr::write_file_listing(dir.path / ".vibra-frames", {{frame(9), vr::fingerprint_of("other bytes", 11)}}, "a forged ledger");
    const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + (dir / "f_%04d.png"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.err, Catch::Contains("kept 1 files named like frames"));
  }
  CHECK(read_file(dir.path / frame(9)) == "the user's frame");
}

TEST_CASE("a frame given to another user stays, though the ledger lists it unchanged", "[output][ledger]") {
  ScratchDirectory dir;
  const std::string pattern = dir / "f_%04d.png";
  REQUIRE(run_vibra("render" + kSmallRunPeriods + "0.5 -o " + pattern).exit_code == 0);
  if (::geteuid() != 0 || ::lchown((dir.path / frame(12)).c_str(), 65534, 65534) != 0) {
    WARN("skipped: giving a file to another user needs root");
    return;
  }
  const std::string before = read_file(dir.path / frame(12));
  const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + pattern);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("removed 23 frames of an earlier run") && Catch::Contains("kept 1 files"));
  CHECK(read_file(dir.path / frame(12)) == before);
}

TEST_CASE("segments keep ledgers of their own, which a whole run folds into its ledger", "[output][ledger][segment]") {
  ScratchDirectory dir;
  const std::string pattern = dir / "f_%04d.png";
  for (const char* segment : {"0/2", "1/2"})
    REQUIRE(run_vibra("render" + kSmallRunPeriods + "0.5 --segment " + segment + " -o " + pattern).exit_code == 0);
  const vr::FrameLedger ledger(dir.path);
  for (int i = 0; i < 31; ++i) CHECK(ledger.vouches_for(frame(i)));
  CHECK(fs::exists(dir.path / ".vibra-frames.0"));
  const auto r = run_vibra("render --size 160x90 --set periods=0.1 -o " + pattern);
  INFO(r.err);
  CHECK_THAT(r.err, Catch::Contains("removed 24 frames of an earlier run"));
  CHECK_FALSE(fs::exists(dir.path / ".vibra-frames.0"));
  const auto whole = vr::read_file_listing(dir.path / ".vibra-frames");
  REQUIRE(whole);
  CHECK(whole->size() == 7);
}
