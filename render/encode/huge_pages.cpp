// Frame buffers backed by transparent huge pages (HugePageArray), so a frame faults in a few times, not thousands.
#include "render/encode/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

// Sanitizer builds allocate exactly what is asked, so that overruns show.
#if defined(__SANITIZE_ADDRESS__)
#define VIBRA_EXACT_ALLOCATIONS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VIBRA_EXACT_ALLOCATIONS 1
#endif
#endif

namespace vibra::render {

void advise_huge_pages(void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  const std::uintptr_t end = (start + bytes) & ~(kHugePageBytes - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: failure is harmless
#else
  (void)data, (void)bytes;
#endif
}

void* allocate_huge_page_memory(std::size_t bytes) {
  const bool large = bytes >= kHugePageBytes / 2;
  // A huge page must lie whole inside the mapping: large buffers are
  // allocated in whole huge pages, or their last part faults in 4 KiB pages.
  const std::size_t whole_pages = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
#ifdef VIBRA_EXACT_ALLOCATIONS
  const std::size_t allocated = bytes;
#else
  const std::size_t allocated = large ? whole_pages : bytes;
#endif
  void* memory = nullptr;
  // Small buffers still get 64 bytes, what SIMD loads in encoders want.
  if (posix_memalign(&memory, large ? kHugePageBytes : 64, allocated ? allocated : 1) != 0) throw std::bad_alloc();
  if (large) advise_huge_pages(memory, whole_pages);
  return memory;
}

void free_huge_page_memory(void* memory) { std::free(memory); }

}  // namespace vibra::render
