#pragma once
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

namespace vibra::render {

/// Asks the kernel to back the 2 MiB pages inside [data, data + bytes) with
/// huge pages. Call it before the memory is first touched: a frame-sized
/// buffer then faults in a few times instead of thousands (4 KiB each), which
/// on a virtual machine is a large part of a short render's start-up. Advice
/// only: where the kernel declines, nothing changes.
void advise_huge_pages(void* data, std::size_t bytes);

/// An uninitialised array of trivial T in 2 MiB-aligned memory advised as
/// above: for frame-sized buffers that are written before they are read.
template <class T>
class LargeArray {
 public:
  LargeArray() = default;
  explicit LargeArray(std::size_t size) : size_(size) {
    constexpr std::size_t kHuge = std::size_t(2) << 20;
    const std::size_t bytes = (size * sizeof(T) + kHuge - 1) / kHuge * kHuge;  // aligned_alloc wants a multiple
    data_.reset(static_cast<T*>(std::aligned_alloc(kHuge, bytes ? bytes : kHuge)));
    if (!data_) throw std::bad_alloc();
    advise_huge_pages(data_.get(), bytes);
  }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T[], Free> data_;
  std::size_t size_ = 0;
};

}  // namespace vibra::render
