// SPDX-License-Identifier: Apache-2.0
#include "collage/optimise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

namespace {

using Matrix = std::vector<std::vector<double>>;

// Standard normal by Box–Muller (both values used).
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    if (have_spare_) {
      have_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - rng_.uniform();  // (0, 1]
    const double u2 = rng_.uniform();
    const double r = std::sqrt(-2 * std::log(u1));
    spare_ = r * std::sin(2 * std::numbers::pi * u2);
    have_spare_ = true;
    return r * std::cos(2 * std::numbers::pi * u2);
  }

 private:
  Rng rng_;
  double spare_ = 0;
  bool have_spare_ = false;
};

// Cyclic Jacobi eigendecomposition of a symmetric matrix: C = B diag(values) Bᵀ, B's columns the
// eigenvectors. Plenty fast for the few dozen dimensions of an IFS (6 per map). A and Bᵀ are
// flat row-major arrays (B's columns are Bᵀ's rows: its rotations run along contiguous rows,
// which the compiler vectorises, as the row rotations of A); every element is the same product
// and difference in the same order as with B itself, so the result is the same bit for bit.
void eigen_symmetric(const Matrix& c, Matrix& b, std::vector<double>& values) {
  const std::size_t n = c.size();
  std::vector<double> a(n * n), bt(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::copy(c[i].begin(), c[i].end(), a.begin() + static_cast<std::ptrdiff_t>(i * n));
    bt[i * n + i] = 1;
  }
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off = 0, diag = 0;
    for (std::size_t i = 0; i < n; ++i) {
      diag += a[i * n + i] * a[i * n + i];
      for (std::size_t j = i + 1; j < n; ++j) off += a[i * n + j] * a[i * n + j];
    }
    if (off <= 1e-22 * diag) break;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) {
        if (a[p * n + q] == 0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2 * a[p * n + q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double cs = 1 / std::sqrt(t * t + 1), sn = t * cs;
        for (std::size_t k = 0; k < n; ++k) {  // A ← A J (columns p, q)
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = cs * akp - sn * akq;
          a[k * n + q] = sn * akp + cs * akq;
        }
        double* ap = a.data() + p * n;
        double* aq = a.data() + q * n;
        for (std::size_t k = 0; k < n; ++k) {  // A ← Jᵀ A (rows p, q)
          const double apk = ap[k], aqk = aq[k];
          ap[k] = cs * apk - sn * aqk;
          aq[k] = sn * apk + cs * aqk;
        }
        double* bp = bt.data() + p * n;
        double* bq = bt.data() + q * n;
        for (std::size_t k = 0; k < n; ++k) {  // B ← B J (Bᵀ's rows p, q)
          const double bkp = bp[k], bkq = bq[k];
          bp[k] = cs * bkp - sn * bkq;
          bq[k] = sn * bkp + cs * bkq;
        }
      }
  }
  b.assign(n, std::vector<double>(n, 0));
  values.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    values[i] = a[i * n + i];
    for (std::size_t k = 0; k < n; ++k) b[k][i] = bt[i * n + k];
  }
}

}  // namespace

CmaesResult minimise_cmaes(const std::function<double(std::span<const double>)>& f,
                           std::vector<double> x0, const CmaesOptions& options) {
  const std::size_t n = x0.size();
  if (n == 0) throw Error(ErrorKind::invalid_argument, "cmaes: x0 must not be empty");
  if (!(options.sigma > 0) || !std::isfinite(options.sigma))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("cmaes: sigma must be > 0 (got {})", options.sigma));
  if (options.population < 0 || options.max_evaluations < 1)
    throw Error(ErrorKind::invalid_argument,
                "cmaes: population must be ≥ 0 and max_evaluations ≥ 1");
  const double dn = static_cast<double>(n);

  // Strategy parameters, Hansen's defaults ("The CMA Evolution Strategy: A Tutorial", Table 1).
  const int lambda = options.population > 0 ? std::max(options.population, 2)
                                            : 4 + static_cast<int>(3 * std::log(dn));
  const int mu = lambda / 2;
  std::vector<double> w(static_cast<std::size_t>(mu));
  for (int i = 0; i < mu; ++i)
    w[static_cast<std::size_t>(i)] = std::log(mu + 0.5) - std::log(i + 1.0);
  const double wsum = std::accumulate(w.begin(), w.end(), 0.0);
  for (auto& x : w) x /= wsum;
  double w2 = 0;
  for (double x : w) w2 += x * x;
  const double mueff = 1 / w2;
  const double cs = (mueff + 2) / (dn + mueff + 5);
  const double ds = 1 + 2 * std::max(0.0, std::sqrt((mueff - 1) / (dn + 1)) - 1) + cs;
  const double cc = (4 + mueff / dn) / (dn + 4 + 2 * mueff / dn);
  const double c1 = 2 / ((dn + 1.3) * (dn + 1.3) + mueff);
  const double cmu = std::min(1 - c1, 2 * (mueff - 2 + 1 / mueff) / ((dn + 2) * (dn + 2) + mueff));
  const double chi_n = std::sqrt(dn) * (1 - 1 / (4 * dn) + 1 / (21 * dn * dn));
  const int stall = options.stall_generations > 0 ? options.stall_generations
                                                  : 20 + static_cast<int>(30 * dn / lambda);
  const int eigen_every = std::max(1, static_cast<int>(1 / ((c1 + cmu) * dn * 10)));

  std::vector<double> m = std::move(x0);
  double sigma = options.sigma;
  std::vector<double> pc(n, 0), ps(n, 0), d(n, 1);
  Matrix c(n, std::vector<double>(n, 0)), b(n, std::vector<double>(n, 0));
  for (std::size_t i = 0; i < n; ++i) c[i][i] = b[i][i] = 1;

  CmaesResult result;
  result.x = m;
  result.value = f(m);
  result.evaluations = 1;
  double stall_reference = result.value;
  int stall_since = 0;

  const auto count = static_cast<std::size_t>(lambda);
  std::vector<std::vector<double>> z(count, std::vector<double>(n)),
      y(count, std::vector<double>(n)), x(count, std::vector<double>(n));
  std::vector<double> values(count);
  std::vector<std::size_t> order(count);

  for (int g = 0;; ++g) {
    options.cancel.check("fit");
    if (result.evaluations + lambda > options.max_evaluations) break;
    if (std::chrono::steady_clock::now() >= options.deadline) {
      result.deadline_reached = true;
      break;
    }
    // Sample λ candidates x_k = m + σ B D z_k on this thread: the draws depend on (seed, g) only.
    Normal normal(stream_seed(options.seed, static_cast<std::uint64_t>(g)));
    for (std::size_t k = 0; k < count; ++k) {
      for (std::size_t i = 0; i < n; ++i) z[k][i] = normal();
      for (std::size_t i = 0; i < n; ++i) {
        double s = 0;
        for (std::size_t j = 0; j < n; ++j) s += b[i][j] * d[j] * z[k][j];
        y[k][i] = s;
        x[k][i] = m[i] + sigma * s;
      }
    }
    parallel_for(count, options.threads, [&](std::size_t k, int) { values[k] = f(x[k]); });
    result.evaluations += lambda;
    result.generations = g + 1;

    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
    if (values[order[0]] < result.value) {
      result.value = values[order[0]];
      result.x = x[order[0]];
    }

    // Recombination: the new mean and the weighted mean step y_w.
    std::vector<double> yw(n, 0);
    for (int r = 0; r < mu; ++r)
      for (std::size_t i = 0; i < n; ++i)
        yw[i] += w[static_cast<std::size_t>(r)] * y[order[static_cast<std::size_t>(r)]][i];
    for (std::size_t i = 0; i < n; ++i) m[i] += sigma * yw[i];

    // Evolution paths. C^{-1/2} y_w = B D⁻¹ Bᵀ y_w.
    std::vector<double> bty(n, 0), cinv(n, 0);
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t i = 0; i < n; ++i) bty[j] += b[i][j] * yw[i];
      bty[j] /= d[j];
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) cinv[i] += b[i][j] * bty[j];
    const double ks = std::sqrt(cs * (2 - cs) * mueff);
    double ps_norm = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ps[i] = (1 - cs) * ps[i] + ks * cinv[i];
      ps_norm += ps[i] * ps[i];
    }
    ps_norm = std::sqrt(ps_norm);
    const bool hsig =
        ps_norm / std::sqrt(1 - std::pow(1 - cs, 2.0 * (g + 1))) < (1.4 + 2 / (dn + 1)) * chi_n;
    const double kc = std::sqrt(cc * (2 - cc) * mueff);
    for (std::size_t i = 0; i < n; ++i) pc[i] = (1 - cc) * pc[i] + (hsig ? kc * yw[i] : 0);

    // Covariance: rank-one update from pc, rank-μ update from the selected steps.
    const double old_weight = 1 - c1 - cmu + (hsig ? 0 : c1 * cc * (2 - cc));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j <= i; ++j) {
        double rank_mu = 0;
        for (int r = 0; r < mu; ++r) {
          const auto& yr = y[order[static_cast<std::size_t>(r)]];
          rank_mu += w[static_cast<std::size_t>(r)] * yr[i] * yr[j];
        }
        c[i][j] = old_weight * c[i][j] + c1 * pc[i] * pc[j] + cmu * rank_mu;
        c[j][i] = c[i][j];
      }
    sigma *= std::exp((cs / ds) * (ps_norm / chi_n - 1));

    if (g % eigen_every == 0) {
      std::vector<double> eig;
      eigen_symmetric(c, b, eig);
      for (std::size_t i = 0; i < n; ++i) d[i] = std::sqrt(std::max(eig[i], 1e-20));
    }

    if (options.progress) options.progress({g + 1, result.evaluations, result.value, sigma});

    // Stop on a vanishing step or a long stall.
    const double largest_d = *std::max_element(d.begin(), d.end());
    if (sigma * largest_d < options.min_sigma || !std::isfinite(sigma)) break;
    if (result.value < stall_reference - 1e-7) {
      stall_reference = result.value;
      stall_since = g;
    } else if (g - stall_since >= stall) {
      break;
    }
  }
  return result;
}

}  // namespace ifsfx::collage
