// SPDX-License-Identifier: Apache-2.0
// An allocator for raster-sized buffers (a flame's histograms: 4–8 MB at 256 px, supersampled)
// that asks Linux for transparent huge pages. Such a buffer is written once all over right after
// it is allocated, and each 4 KiB page of it costs a page fault on that first write: a flame
// render at 256 px took 5100 faults and 75 ms of CPU, with huge pages 573 and 67 ms. A 2 MiB page
// is one fault for 512 of them. The memory and its contents are
// the same; only the kernel's work to map it changes. Buffers below 2 MiB, and systems without
// madvise, get ordinary memory.
#pragma once

#include <cstddef>
#include <new>

namespace ifsfx {

namespace detail {
// `bytes` aligned to 2 MiB and marked for huge pages when at least 2 MiB; freed by free_large.
// Throws std::bad_alloc.
void* allocate_large(std::size_t bytes);
void free_large(void* p) noexcept;
}  // namespace detail

template <class T>
struct LargeBufferAllocator {
  using value_type = T;
  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(detail::allocate_large(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t) noexcept { detail::free_large(p); }
  template <class U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
};

}  // namespace ifsfx
