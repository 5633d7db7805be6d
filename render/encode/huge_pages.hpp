// Frame buffers backed by transparent huge pages (HugePageArray), so a frame faults in a few times, not thousands.
#pragma once
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

namespace vibra::render {

/// The huge page size of x86-64 (and arm64 with 4 KiB pages).
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

/// Asks the kernel to back the huge pages inside [data, data + bytes) with
/// huge pages. Call it before the memory is first touched: a frame-sized
/// buffer then faults in a few times instead of thousands (4 KiB each), which
/// on a virtual machine is a large part of a short render's start-up. Advice
/// only: where the kernel declines, nothing changes.
void advise_huge_pages(void* data, std::size_t bytes);

/// Uninitialised memory for `bytes`, 64-byte aligned; from 1 MiB on it is
/// huge-page aligned, rounded up to whole huge pages and advised as above
/// (smaller buffers would waste most of a huge page). Sanitizer builds round
/// nothing, so that overruns show. Free with free_huge_page_memory.
void* allocate_huge_page_memory(std::size_t bytes);
void free_huge_page_memory(void* memory);

/// An uninitialised array of trivial T in memory from allocate_huge_page_memory:
/// for frame-sized buffers that are written before they are read.
template <class T>
class HugePageArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  HugePageArray() = default;
  explicit HugePageArray(std::size_t size)
      : data_(static_cast<T*>(allocate_huge_page_memory(size * sizeof(T)))), size_(size) {}
  HugePageArray(HugePageArray&& other) noexcept
      : data_(std::move(other.data_)), size_(std::exchange(other.size_, 0)) {}
  HugePageArray& operator=(HugePageArray&& other) noexcept {
    data_ = std::move(other.data_);
    size_ = std::exchange(other.size_, 0);
    return *this;
  }

  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  struct Free {
    void operator()(T* p) const;
  };
  std::unique_ptr<T[], Free> data_;
  std::size_t size_ = 0;
};

template <class T>
void HugePageArray<T>::Free::operator()(T* p) const {
  free_huge_page_memory(p);
}

}  // namespace vibra::render
