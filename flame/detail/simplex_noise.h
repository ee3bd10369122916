// SPDX-License-Identifier: Apache-2.0
// 3-D simplex noise (Perlin 2001; as Gustavson states it in "Simplex noise demystified", 2005):
// the lattice skewed by F = 1/3 into tetrahedra, each of the four corners of the one holding p
// adding (0.6 − |d|²)⁴·(g·d) for its offset d and its gradient g, the sum times 32 (about
// [−1, 1]). The gradients are ifsfx's own: unit vectors drawn once from a fixed hash of the
// corner, so the noise is the same in every build and on every machine, but not the same
// numbers as the Apophysis plugins' tables (docs/flames.md, crackle).
#pragma once

namespace ifsfx::flame::detail {

double simplex_noise(double x, double y, double z);

}  // namespace ifsfx::flame::detail
