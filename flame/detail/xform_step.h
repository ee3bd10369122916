// SPDX-License-Identifier: Apache-2.0
// One xform's motion over a batch of walkers: apply_xform's steps (flame/xform_eval.h) — the
// pre-affine map, the pre_ terms, the weighted sum of the variations, the post_ terms, the post
// map — resolved once and run over arrays of points, each variation through its batch form
// (flame/detail/batch_variations.h) where it has one. The walks that move many walkers in
// lockstep share it: the renderer's (flame/render_chaos.cpp, which adds the colour) and the
// paper modes' (flame/flame_walk.cpp, which adds the address).
//
//   const XformStep step = xform_step_of(xf, {cpu_level(), LaneType::f32});
//   step(n, at, x, y, scratch, rng);  // walkers at[0..n) of (x, y) moved, in place
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "flame/detail/batch_variations.h"
#include "flame/flame.h"
#include "flame/variations.h"
#include "ifs/rng.h"

namespace ifsfx::flame::detail {

// The length of a batch's arrays: kBatchLanes walkers, padded to whole vectors.
inline constexpr std::size_t kStepStride = kBatchStride;

// The kernel level and lane type the batch forms run at.
struct Kernels {
  CpuLevel level;
  LaneType type;
};

// Two doubles as one value (GCC's generic vectors, one SSE2 register): a point's x and y go
// through an affine map's products and sums together, each lane the scalar operations in order.
using D2 = double __attribute__((vector_size(16)));

// An affine map by columns, (a, c), (b, d), (e, f): p ↦ x·(a, c) + y·(b, d) + (e, f) is
// (a·x + b·y + e, c·x + d·y + f), AffineMap's operations in its order on each lane, so the same
// bits in half the instructions (the walks' gathers and scatters apply it to every point).
struct PairMap {
  D2 x{}, y{}, o{};
  PairMap() = default;
  explicit PairMap(const AffineMap& m) : x{m.a, m.c}, y{m.b, m.d}, o{m.e, m.f} {}
  D2 operator()(double px, double py) const { return x * px + y * py + o; }
};

// One variation term with everything the inner loop needs resolved once.
struct Term {
  VariationFunction f;
  const BatchVariation* batch;  // null: point by point through f
  double w;
  std::span<const double> params;
  bool adds;    // pre_/post_ lists: p + w·V(p) rather than w·V(p)
  bool linear;  // V(p) = p
};

// The arrays one xform's batch works in: the affine point q, a term's result t, the sum s and
// the random draws u; q rounded to float once (f) and the float terms' sum (fs).
struct Scratch {
  std::array<double, kStepStride> qx{}, qy{}, tx{}, ty{}, sx{}, sy{};
  std::array<float, kStepStride> fx{}, fy{}, fsx{}, fsy{};
  std::vector<double> u;
};

// An xform's terms of one list: `in_sum` for the weighted sum (w·V), else a pre_/post_ list
// (p + w·V where the variation adds). z-only variations are dropped; linear3D is `linear`.
std::vector<Term> terms_of(const std::vector<VariationTerm>& list, bool in_sum, Kernels kernels);

// An xform prepared for the loop: apply_xform's steps without looking anything up.
struct XformStep {
  AffineMap pre, post;
  bool has_post = false, has_sum = false;
  std::vector<Term> pre_terms, sum_terms, post_terms;
  // Only affine: no pre_/post_ terms and every term of the sum `linear` (an IFS drawn as a
  // flame), so that one point goes through it on its own without the arrays (moved()).
  bool affine_only = false;
  // Some term of the sum has a float form over float arrays (BatchVariation::function_f): the
  // sum's float terms read one float copy of the point and add in float, the total added to
  // the double terms' sum once (flame/xform_step.cpp).
  bool float_sum = false;
  bool double_sum = false;  // and some term adds in double (linear, no float form)

  // One point through an affine_only xform: the operations of operator() on it, in its order
  // (the sum starts from 0 and adds w·q term by term, as the batch does), so the bits are equal.
  Point moved(double x, double y) const {
    Point s = pre({x, y});
    if (has_sum) {
      const Point q = s;
      s = {0, 0};
      for (const Term& t : sum_terms) {
        s.x += t.w * q.x;
        s.y += t.w * q.y;
      }
    }
    return has_post ? post(s) : s;
  }

  // Points [0, n) of (x, y) moved through the xform, in place.
  void operator()(std::size_t n, double* x, double* y, Scratch& w, Rng& rng) const;
  // The points x[at[i]], y[at[i]] for i in [0, n) moved through the xform, in place.
  void operator()(std::size_t n, const std::uint32_t* at, double* x, double* y, Scratch& w,
                  Rng& rng) const;

 private:
  // The points [0, n) of (w.qx, w.qy), the pre-affine map applied, through the pre_ terms, the
  // sum and the post_ terms; where the result is (the post map is the caller's).
  std::pair<double*, double*> move_scratch(std::size_t n, Scratch& w, Rng& rng) const;
  // (w.sx, w.sy) ← the weighted sum of the terms at the points [0, n) of (w.qx, w.qy).
  void sum(std::size_t n, Scratch& w, Rng& rng) const;
  // (x, y) ← each term of `terms` in order, over points [0, n).
  void chain(const std::vector<Term>& terms, std::size_t n, double* x, double* y, Scratch& w,
             Rng& rng) const;
};

XformStep xform_step_of(const Xform& xf, Kernels kernels);

}  // namespace ifsfx::flame::detail
