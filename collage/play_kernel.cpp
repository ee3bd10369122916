// SPDX-License-Identifier: Apache-2.0
// The scalar reference of the attractor loss's chaos game (collage/detail/play_kernel.h), and the
// choice of a level's kernel. Every operation is the AVX2 kernel's, in its order: the clamps are
// written as MAXPS and MINPS compare (a > b ? a : b), the float products and sums are rounded one
// by one (-ffp-contract=off).
#include <algorithm>
#include <cmath>

#include "collage/detail/play_kernel.h"

namespace ifsfx::collage::detail {

PlayFunction play_function(CpuLevel level) {
#if IFSFX_COLLAGE_X86_KERNELS
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::collage_play;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::collage_play;
}

}  // namespace ifsfx::collage::detail

namespace ifsfx::detail::kernel_scalar {

namespace {

float maxps(float a, float b) {
  return a > b ? a : b;
}
float minps(float a, float b) {
  return a < b ? a : b;
}

// The distance map's bilinear value at canvas point (px, py) (play_kernel.h).
float lookup(const collage::detail::PlayInput& in, float px, float py) {
  const float hi = static_cast<float>(in.side - 1);
  const float u = px - 0.5f, v = py - 0.5f;
  const float cu = minps(maxps(u, 0.0f), hi), cv = minps(maxps(v, 0.0f), hi);
  const float du = u - cu, dv = v - cv;
  const float out = std::sqrt(du * du + dv * dv);
  const int c0 = std::min(static_cast<int>(cu), in.side - 2);
  const int r0 = std::min(static_cast<int>(cv), in.side - 2);
  const float fu = cu - static_cast<float>(c0), fv = cv - static_cast<float>(r0);
  const float* p = in.cells + 4 * (static_cast<std::ptrdiff_t>(r0) * in.side + c0);
  const float top = p[0] + fu * (p[1] - p[0]);
  const float bottom = p[2] + fu * (p[3] - p[2]);
  return (top + fv * (bottom - top)) + out;
}

}  // namespace

double collage_play(const collage::detail::PlayInput& in) {
  constexpr std::size_t lanes = collage::detail::kPlayLanes;
  const float* a = in.coefficients;
  const float *b = a + in.stride, *c = b + in.stride, *d = c + in.stride;
  const float *e = d + in.stride, *f = e + in.stride;
  const float side = static_cast<float>(in.side);
  float x[lanes], y[lanes];
  double spill[lanes];
  for (std::size_t lane = 0; lane < lanes; ++lane) {
    x[lane] = y[lane] = 0.5f;
    spill[lane] = 0;
  }
  for (std::size_t t = 0; t < in.steps; ++t)
    for (std::size_t lane = 0; lane < lanes; ++lane) {
      const float u = in.draws[t * lanes + lane];
      int n = 0;
      for (int k = 0; k + 1 < in.count; ++k) n += u >= in.cumulative[k];
      const float x0 = x[lane], y0 = y[lane];
      x[lane] = (a[n] * x0 + b[n] * y0) + e[n];
      y[lane] = (c[n] * x0 + d[n] * y0) + f[n];
      if (t < in.burn_in) continue;
      const float px = x[lane] * in.size + in.pad, py = (1.0f - y[lane]) * in.size + in.pad;
      spill[lane] += static_cast<double>(lookup(in, px, py));
      if (in.hits && px >= 0.0f && py >= 0.0f && px < side && py < side)
        in.hits[static_cast<std::ptrdiff_t>(static_cast<int>(py)) * in.side +
                static_cast<int>(px)] = 1;
    }
  double total = 0;
  for (double s : spill) total += s;
  return total;
}

}  // namespace ifsfx::detail::kernel_scalar
