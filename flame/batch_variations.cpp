// SPDX-License-Identifier: Apache-2.0
// The dispatcher of the variations' batch forms: the table of the level asked for.
#include "flame/detail/batch_variations.h"

#include <algorithm>

namespace ifsfx::flame::detail {

std::span<const BatchVariation> batch_variations(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  // AVX-512 runs the AVX2 forms: four doubles a lane group is what the variations fill.
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_batch_table();
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_batch_table();
}

const BatchVariation* find_batch_variation(CpuLevel level, std::string_view name) {
  const auto table = batch_variations(level);
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const BatchVariation& v) { return v.name == name; });
  return it == table.end() ? nullptr : &*it;
}

}  // namespace ifsfx::flame::detail
