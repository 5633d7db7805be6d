// Tests of HugePageArray: size, alignment and huge-page advice for frame buffers.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "cli_support.hpp"
#include "render/encode/huge_pages.hpp"

using vibra::render::advise_huge_pages;
using vibra::render::HugePageArray;
using vibra::render::kHugePageBytes;

namespace {
std::string first_line(const char* path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

/// Whether this process may get transparent huge pages of kHugePageBytes:
/// the kernel offers them (sysfs), nothing disabled them for the process
/// (prctl, inherited from some container runtimes), and the size matches.
bool huge_pages_offered() {
  const std::string mode = first_line("/sys/kernel/mm/transparent_hugepage/enabled");
  if (mode.empty() || mode.find("[never]") != std::string::npos) return false;
  if (first_line("/sys/kernel/mm/transparent_hugepage/hpage_pmd_size") != std::to_string(kHugePageBytes)) return false;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("THP_enabled:", 0) == 0) return line.find('1') != std::string::npos;
  return true;
}

/// A field of the /proc/self/smaps entry of the mapping that holds `address`.
std::string smaps_field(const void* address, const std::string& field) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-')  // a mapping's first line
      inside = begin <= at && at < end;
    else if (inside && line.rfind(field + ":", 0) == 0)
      return line.substr(field.size() + 1);
  }
  return "";
}
}  // namespace

TEST_CASE("HugePageArray: exact size, 64-byte aligned, huge-page aligned from 1 MiB", "[huge_pages]") {
  HugePageArray<std::uint32_t> small(1000), large(kHugePageBytes / 4 + 5);  // 4000 B; 2 MiB + 20 B
  CHECK(small.size() == 1000);
  CHECK(large.size() == kHugePageBytes / 4 + 5);
  CHECK(reinterpret_cast<std::uintptr_t>(small.data()) % 64 == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePageBytes == 0);
  std::memset(small.data(), 0x11, small.size() * sizeof(std::uint32_t));
  std::memset(large.data(), 0x22, large.size() * sizeof(std::uint32_t));
  CHECK(small[0] == 0x11111111u);
  CHECK(small[999] == 0x11111111u);
  CHECK(large[large.size() - 1] == 0x22222222u);

  HugePageArray<std::uint32_t> moved;
  moved = std::move(small);  // how the converter sizes its planes
  CHECK(moved.size() == 1000);
  CHECK(moved[999] == 0x11111111u);
  CHECK(small.size() == 0);  // NOLINT(bugprone-use-after-move): the moved-from state is defined
  CHECK(small.data() == nullptr);
}

TEST_CASE("advise_huge_pages accepts ranges without a whole huge page", "[huge_pages]") {
  char small[100] = {};
  advise_huge_pages(small, sizeof small);  // nothing inside to advise: a no-op
  advise_huge_pages(nullptr, 0);
  CHECK(small[0] == 0);
}

TEST_CASE("a frame-sized HugePageArray is advised for huge pages", "[huge_pages]") {
  if (!huge_pages_offered()) {
    const char* what =
        "no transparent huge pages of 2 MiB for this process: enable them with "
        "`echo madvise > /sys/kernel/mm/transparent_hugepage/enabled` (as root)";
    // A kernel setting, not a package scripts/setup could install: a machine
    // without it (CI included) has nothing here to check.
    WARN(what << ": nothing to check");
    return;
  }
  HugePageArray<std::uint8_t> pixels(4 * kHugePageBytes);
  // What the code decides: the kernel records the advice as the "hg" flag.
  const std::string flags = smaps_field(pixels.data(), "VmFlags");
  INFO("VmFlags:" << flags);
  CHECK(flags.find(" hg") != std::string::npos);
  // Whether the kernel then finds free huge pages depends on the machine's
  // memory, so AnonHugePages is not required; the benchmark shows the gain.
}
