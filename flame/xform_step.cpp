// SPDX-License-Identifier: Apache-2.0
// One xform's motion over a batch of walkers (flame/detail/xform_step.h).
#include "flame/detail/xform_step.h"

#include <algorithm>
#include <string_view>

namespace ifsfx::flame::detail {
namespace {

constexpr std::size_t kN = kStepStride;

// n rounded up to a whole register of float lanes (8 on AVX2), at most kN: the batch forms run
// over whole registers, so the arrays' padding must hold numbers too.
std::size_t padded_count(std::size_t n) {
  return std::min(kN, (n + 7) / 8 * 8);
}

// The term's random draws for points [0, n), draw j of point i at u[j·kN + i]: draw by draw,
// each over the points (point by point, the strided stores and the generator's state went
// through memory).
const double* fill_draws(const Term& t, std::size_t n, Scratch& w, Rng& rng) {
  const auto draws = static_cast<std::size_t>(t.batch->draws);
  if (w.u.size() < draws * kN) w.u.resize(draws * kN);
  Rng local = rng;
  for (std::size_t j = 0; j < draws; ++j) {
    double* u = w.u.data() + j * kN;
    for (std::size_t i = 0; i < n; ++i) u[i] = local.uniform();
  }
  rng = local;
  return w.u.data();
}

// Points [0, n) of (x, y) through one term, its w·V added to (ox, oy).
void run_term(const Term& t, const AffineMap& pre, std::size_t n, const double* x, const double* y,
              double* ox, double* oy, Scratch& w, Rng& rng) {
  if (!t.batch) {
    for (std::size_t i = 0; i < n; ++i) {
      const Point r = t.f({.p = {x[i], y[i]}, .w = t.w, .params = t.params, .pre = &pre}, rng);
      ox[i] += r.x;
      oy[i] += r.y;
    }
    return;
  }
  const double* u = fill_draws(t, n, w, rng);
  t.batch->function({.w = t.w, .params = t.params.data(), .pre = &pre, .u = u}, n, x, y, ox, oy);
}

// The term has a float form over float arrays (BatchVariation::function_f).
bool has_float_form(const Term& t) {
  return t.batch && t.batch->function_f;
}

// A float form of the sum over the float copy (w.fx, w.fy), its w·V added to (w.fsx, w.fsy).
void run_term_f(const Term& t, const AffineMap& pre, std::size_t n, Scratch& w, Rng& rng) {
  const double* u = fill_draws(t, n, w, rng);
  t.batch->function_f({.w = t.w, .params = t.params.data(), .pre = &pre, .u = u}, n, w.fx.data(),
                      w.fy.data(), w.fsx.data(), w.fsy.data());
}

}  // namespace

std::vector<Term> terms_of(const std::vector<VariationTerm>& list, bool in_sum, Kernels kernels) {
  std::vector<Term> out;
  for (const VariationTerm& t : list) {
    const Variation& v = variation(t.id);
    // z only: adds nothing to the sum, leaves the point alone in a list.
    if (v.kind == VariationKind::flat_3d) continue;
    // linear3D is linear in the plane (its z part is dropped): the same term, so that a flame
    // of linear3D xforms (Fractorium's hexagonal tilings) walks as an affine one. linear (an
    // IFS's own maps) stays in double lanes: float would only round it.
    const bool linear = v.name == "linear" || v.name == "linear3D";
    const std::string_view name = linear ? std::string_view("linear") : v.name;
    const LaneType type = linear ? LaneType::f64 : kernels.type;
    const BatchVariation* batch = find_batch_variation(kernels.level, name, type);
    out.push_back({v.function, batch ? batch : find_batch_variation(kernels.level, name), t.weight,
                   t.params, !in_sum && v.assign == Assign::add, linear});
  }
  return out;
}

XformStep xform_step_of(const Xform& xf, Kernels kernels) {
  XformStep s;
  s.pre = xf.pre;
  s.has_post = xf.post.has_value();
  if (s.has_post) s.post = *xf.post;
  // With no normal term the sum is empty, (0, 0), unless pre_ terms hand their point on
  // (apply_xform, flame/xform_eval.cpp).
  s.has_sum = !xf.variations.empty() || xf.pre_variations.empty();
  s.pre_terms = terms_of(xf.pre_variations, false, kernels);
  s.sum_terms = terms_of(xf.variations, true, kernels);
  s.post_terms = terms_of(xf.post_variations, false, kernels);
  s.affine_only =
      s.pre_terms.empty() && s.post_terms.empty() &&
      std::all_of(s.sum_terms.begin(), s.sum_terms.end(), [](const Term& t) { return t.linear; });
  s.float_sum = std::any_of(s.sum_terms.begin(), s.sum_terms.end(), has_float_form);
  s.double_sum = !std::all_of(s.sum_terms.begin(), s.sum_terms.end(), has_float_form);
  return s;
}

void XformStep::chain(const std::vector<Term>& terms, std::size_t n, double* x, double* y,
                      Scratch& w, Rng& rng) const {
  const std::size_t padded = padded_count(n);
  for (const Term& t : terms) {
    std::fill_n(w.tx.begin(), padded, 0.0);
    std::fill_n(w.ty.begin(), padded, 0.0);
    run_term(t, pre, n, x, y, w.tx.data(), w.ty.data(), w, rng);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = t.adds ? x[i] + w.tx[i] : w.tx[i];
      y[i] = t.adds ? y[i] + w.ty[i] : w.ty[i];
    }
  }
}

// The gathers apply the pre-affine map as they copy, and the scatters the post map as they
// write back (AffineMap's operations, as PairMap's lanes, one pass fewer each way; the maps in
// registers: a store to the arrays might otherwise change them).
void XformStep::operator()(std::size_t n, double* x, double* y, Scratch& w, Rng& rng) const {
  const PairMap to_q(pre);
  for (std::size_t i = 0; i < n; ++i) {
    const D2 q = to_q(x[i], y[i]);
    w.qx[i] = q[0];
    w.qy[i] = q[1];
  }
  const auto [sx, sy] = move_scratch(n, w, rng);
  if (!has_post) {
    std::copy_n(sx, n, x);
    std::copy_n(sy, n, y);
    return;
  }
  const PairMap to_p(post);
  for (std::size_t i = 0; i < n; ++i) {
    const D2 p = to_p(sx[i], sy[i]);
    x[i] = p[0];
    y[i] = p[1];
  }
}

void XformStep::operator()(std::size_t n, const std::uint32_t* at, double* x, double* y, Scratch& w,
                           Rng& rng) const {
  const PairMap to_q(pre);
  for (std::size_t i = 0; i < n; ++i) {
    const D2 q = to_q(x[at[i]], y[at[i]]);
    w.qx[i] = q[0];
    w.qy[i] = q[1];
  }
  const auto [sx, sy] = move_scratch(n, w, rng);
  if (!has_post) {
    for (std::size_t i = 0; i < n; ++i) {
      x[at[i]] = sx[i];
      y[at[i]] = sy[i];
    }
    return;
  }
  const PairMap to_p(post);
  for (std::size_t i = 0; i < n; ++i) {
    const D2 p = to_p(sx[i], sy[i]);
    x[at[i]] = p[0];
    y[at[i]] = p[1];
  }
}

void XformStep::sum(std::size_t n, Scratch& w, Rng& rng) const {
  const std::size_t padded = padded_count(n);
  if (double_sum) {
    std::fill_n(w.sx.begin(), padded, 0.0);
    std::fill_n(w.sy.begin(), padded, 0.0);
  }
  if (float_sum) {
    // One rounding of the point for every float term (the padding's zeros too), their sum in
    // float, added to the double terms' sum once after them.
    for (std::size_t i = 0; i < padded; ++i) {
      w.fx[i] = static_cast<float>(w.qx[i]);
      w.fy[i] = static_cast<float>(w.qy[i]);
    }
    std::fill_n(w.fsx.begin(), padded, 0.0f);
    std::fill_n(w.fsy.begin(), padded, 0.0f);
  }
  for (const Term& t : sum_terms) {
    if (has_float_form(t))
      run_term_f(t, pre, n, w, rng);
    else
      run_term(t, pre, n, w.qx.data(), w.qy.data(), w.sx.data(), w.sy.data(), w, rng);
  }
  if (!float_sum) return;
  // Through the padding too: without double terms the sums there were not zeroed, and a post_
  // term reads them (stale values, not a number perhaps, would send its lanes to libm).
  for (std::size_t i = 0; i < padded; ++i) {
    w.sx[i] = double_sum ? w.sx[i] + w.fsx[i] : w.fsx[i];
    w.sy[i] = double_sum ? w.sy[i] + w.fsy[i] : w.fsy[i];
  }
}

std::pair<double*, double*> XformStep::move_scratch(std::size_t n, Scratch& w, Rng& rng) const {
  const std::size_t padded = padded_count(n);
  std::fill(w.qx.begin() + static_cast<std::ptrdiff_t>(n),
            w.qx.begin() + static_cast<std::ptrdiff_t>(padded), 0.0);
  std::fill(w.qy.begin() + static_cast<std::ptrdiff_t>(n),
            w.qy.begin() + static_cast<std::ptrdiff_t>(padded), 0.0);
  chain(pre_terms, n, w.qx.data(), w.qy.data(), w, rng);
  if (!has_sum) {
    chain(post_terms, n, w.qx.data(), w.qy.data(), w, rng);
    return {w.qx.data(), w.qy.data()};
  }
  sum(n, w, rng);
  chain(post_terms, n, w.sx.data(), w.sy.data(), w, rng);
  return {w.sx.data(), w.sy.data()};
}

}  // namespace ifsfx::flame::detail
