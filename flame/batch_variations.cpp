// SPDX-License-Identifier: Apache-2.0
// The dispatcher of the variations' batch forms: the table of the level asked for.
#include "flame/detail/batch_variations.h"

#include <algorithm>

namespace ifsfx::flame::detail {

std::span<const BatchVariation> batch_variations(CpuLevel level, LaneType type) {
  const bool f32 = type == LaneType::f32;
#if IFSFX_FLAME_X86_KERNELS
  // AVX-512 runs the AVX2 forms: four doubles or eight floats a lane group is what the
  // variations fill (a group of one xform in a step is 128/xforms walkers).
  namespace avx2 = ifsfx::detail::kernel_avx2;
  if (level != CpuLevel::scalar)
    return f32 ? avx2::flame_batch_table_f32() : avx2::flame_batch_table();
#else
  (void)level;
#endif
  namespace scalar = ifsfx::detail::kernel_scalar;
  return f32 ? scalar::flame_batch_table_f32() : scalar::flame_batch_table();
}

const BatchVariation* find_batch_variation(CpuLevel level, std::string_view name, LaneType type) {
  const auto table = batch_variations(level, type);
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const BatchVariation& v) { return v.name == name; });
  return it == table.end() ? nullptr : &*it;
}

BinFunction bin_function(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_bin_numbers;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_bin_numbers;
}

PlotFunction plot_function(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_plot;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_plot;
}

ListFunction list_function(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_list_by_xform;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_list_by_xform;
}

HitsFunction hits_function(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_hits;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_hits;
}

}  // namespace ifsfx::flame::detail
