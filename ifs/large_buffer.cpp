// SPDX-License-Identifier: Apache-2.0
#include "ifs/large_buffer.h"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ifsfx::detail {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}

void* allocate_large(std::size_t bytes) {
  if (bytes < kHugePage) {
    void* p = std::malloc(bytes == 0 ? 1 : bytes);
    if (p == nullptr) throw std::bad_alloc();
    return p;
  }
  // aligned_alloc wants a multiple of the alignment; the tail up to it is unused.
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (p == nullptr) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  // Advice only: where the kernel has no huge page to give (or THP is off) it maps 4 KiB pages
  // as before, so a failure changes nothing but the time.
  (void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

void free_large(void* p) noexcept {
  std::free(p);
}

}  // namespace ifsfx::detail
