#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "render/huge_pages.hpp"

using vibra::render::advise_huge_pages;
using vibra::render::LargeArray;

namespace {
constexpr std::size_t kHuge = std::size_t(2) << 20;

/// The kernel's transparent huge page mode: "always", "madvise" or "never".
std::string huge_page_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  const auto open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "never" : line.substr(open + 1, close - open - 1);
}

/// AnonHugePages, in KiB, of the mapping that holds `address` (/proc/self/smaps).
long huge_kib_at(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-') {  // a mapping's first line
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      return std::stol(line.substr(14));
    }
  }
  return -1;
}
}  // namespace

TEST_CASE("LargeArray: 2 MiB-aligned, the asked size, independent arrays", "[huge_pages]") {
  LargeArray<std::uint32_t> a(1000), b(3 * kHuge / 4 + 5);
  CHECK(a.size() == 1000);
  CHECK(b.size() == 3 * kHuge / 4 + 5);
  CHECK(reinterpret_cast<std::uintptr_t>(a.data()) % kHuge == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(b.data()) % kHuge == 0);
  std::memset(a.data(), 0x11, a.size() * sizeof(std::uint32_t));
  std::memset(b.data(), 0x22, b.size() * sizeof(std::uint32_t));
  CHECK(a[999] == 0x11111111u);
  CHECK(b[b.size() - 1] == 0x22222222u);
  CHECK(a[0] == 0x11111111u);
  LargeArray<std::uint32_t> moved;
  moved = std::move(a);  // how the converter sizes its planes
  CHECK(moved.size() == 1000);
  CHECK(moved[999] == 0x11111111u);
}

TEST_CASE("advise_huge_pages accepts ranges without a whole huge page", "[huge_pages]") {
  char small[100] = {};
  advise_huge_pages(small, sizeof small);  // nothing inside to advise: a no-op
  advise_huge_pages(nullptr, 0);
  CHECK(small[0] == 0);
}

TEST_CASE("a LargeArray is backed by huge pages where the kernel offers them", "[huge_pages]") {
  const std::string mode = huge_page_mode();
  INFO("transparent_hugepage: " << mode);
  if (mode == "never") {
    WARN("this kernel offers no transparent huge pages: nothing to check");
    return;
  }
  LargeArray<std::uint8_t> pixels(8 * kHuge);
  std::memset(pixels.data(), 1, pixels.size());  // first touch
  CHECK(huge_kib_at(pixels.data()) >= 2048);
}
