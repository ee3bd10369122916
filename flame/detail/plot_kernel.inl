// SPDX-License-Identifier: Apache-2.0
// The walk's plot (flame/detail/batch_variations.h, flame_plot), one source for every kernel
// level: integer sums and the same double operations at each, so the same sums. Included in a
// level's kernel namespace after it defines
//   using U4 = std::uint32_t __attribute__((vector_size(16))); (M4: its comparisons' int32 lanes)
//   unsigned wrapped_lanes(M4 m);
// (the lanes of a comparison's mask as bits 0-3). No std:: templates here: an AVX2 copy of an
// inline template could be the one the linker keeps for baseline code.

// One hit's colour: palette entry ⌊256·c⌋ of a step palette, or entries ⌊256·c⌋ and the next
// mixed by the fraction in 1/256 steps for a linear one (from 255 on, the last entry): an entry
// is at most 2¹⁶, so the mix fits 32 bits.
namespace {
inline U4 hit_colour(const std::uint32_t* table, bool linear, double c) {
  c = c < 0 ? 0 : (1 < c ? 1 : c);
  U4 a, b;
  if (!linear) {
    const auto e = static_cast<std::size_t>(c * 256);
    std::memcpy(&a, table + 4 * (e < 255 ? e : 255), sizeof a);
    return a;
  }
  const double x256 = c * 256 < 255.0 ? c * 256 : 255.0;
  const auto x = static_cast<std::uint32_t>(x256 * 256);
  const std::uint32_t i = (x >> 8) < 254 ? x >> 8 : 254;
  const std::uint32_t w = x - (i << 8);
  std::memcpy(&a, table + 4 * std::size_t{i}, sizeof a);
  std::memcpy(&b, table + 4 * std::size_t{i} + 4, sizeof b);
  return (a * (256 - w) + b * w) >> 8;
}
}  // namespace

namespace {
// flame_plot over the walkers hits[j] (Listed) or j itself.
template <bool Listed>
std::size_t plot_hits(const flame::detail::PlotTables& t, std::uint32_t* bins, std::size_t from,
                      std::size_t n, const std::uint32_t* hits, const std::uint32_t* at,
                      const std::uint32_t* k, const double* c, unsigned* wrapped) {
  for (std::size_t j = from; j < n; ++j) {
    const std::size_t i = Listed ? hits[j] : j;
    U4 v;
    if (t.fixed)
      std::memcpy(&v, t.fixed + 4 * std::size_t{k[i]}, sizeof v);
    else
      v = hit_colour(t.colours[k[i]], t.linear, c[i]);
    std::uint32_t* p = bins + 4 * std::size_t{at[i]};
    U4 s;
    std::memcpy(&s, p, sizeof s);
    s += v;
    std::memcpy(p, &s, sizeof s);
    // A sum below what was added wrapped past 2³² (a hit adds at most 2¹⁶).
    const unsigned lanes = wrapped_lanes(s < v);
    if (lanes != 0) [[unlikely]] {
      *wrapped = lanes;
      return j + 1;
    }
  }
  return n;
}
}  // namespace

std::size_t flame_plot(const flame::detail::PlotTables& t, std::uint32_t* bins, std::size_t from,
                       std::size_t n, const std::uint32_t* hits, const std::uint32_t* at,
                       const std::uint32_t* k, const double* c, unsigned* wrapped) {
  if (hits == nullptr) return plot_hits<false>(t, bins, from, n, hits, at, k, c, wrapped);
  return plot_hits<true>(t, bins, from, n, hits, at, k, c, wrapped);
}
