// SPDX-License-Identifier: Apache-2.0
// The registry: the tables of variations_*.cpp in one list, numbered, with a sorted name index.
#include "flame/variations.h"

#include <algorithm>
#include <utility>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame {
namespace {

struct Registry {
  std::vector<Variation> rows;
  std::vector<std::pair<std::string_view, std::uint32_t>> by_name;  // sorted by name
};

Registry build() {
  Registry reg;
  detail::add_paper_variations(reg.rows);
  detail::add_flam3_variations(reg.rows);
  detail::add_complex_variations(reg.rows);
  detail::add_more_variations(reg.rows);
  detail::add_pack_variations(reg.rows);
  detail::add_pack2_variations(reg.rows);
  detail::add_pack3_variations(reg.rows);
  detail::add_pack4_variations(reg.rows);
  detail::add_pack5_variations(reg.rows);
  for (std::uint32_t i = 0; i < reg.rows.size(); ++i) {
    reg.rows[i].id = i;
    reg.by_name.emplace_back(reg.rows[i].name, i);
  }
  std::sort(reg.by_name.begin(), reg.by_name.end());
  return reg;
}

// Built once, never changed: constant data, like a table in the source.
const Registry& registry() {
  static const Registry reg = build();
  return reg;
}

}  // namespace

std::span<const Variation> variations() {
  return registry().rows;
}

const Variation* find_variation(std::string_view name) {
  const auto& index = registry().by_name;
  const auto it = std::lower_bound(index.begin(), index.end(), name,
                                   [](const auto& e, std::string_view n) { return e.first < n; });
  if (it == index.end() || it->first != name) return nullptr;
  return &registry().rows[it->second];
}

const Variation& variation(std::uint32_t id) {
  return registry().rows.at(id);
}

std::vector<double> default_parameters(const Variation& v) {
  std::vector<double> values;
  for (const VariationParameter& p : v.parameters) values.push_back(p.default_value);
  return values;
}

}  // namespace ifsfx::flame
