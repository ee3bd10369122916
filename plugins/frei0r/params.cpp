// SPDX-License-Identifier: Apache-2.0
#include "plugins/frei0r/params.h"

namespace ifsfx::frei0r {

void describe(std::span<const ParamInfo> table, f0r_param_info_t* info, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= table.size()) return;
  const ParamInfo& p = table[static_cast<std::size_t>(index)];
  info->name = p.name;
  info->type = static_cast<int>(p.type);
  info->explanation = p.explanation;
}

ParamValues::ParamValues(std::span<const ParamInfo> table) : table_(table) {
  for (const ParamInfo& p : table) {
    values_.numbers.push_back(p.type == ParamType::text ? 0.0 : p.number);
    values_.texts.emplace_back(p.type == ParamType::text ? p.text : "");
  }
}

bool ParamValues::set(const void* param, int index) {
  if (param == nullptr || index < 0 || static_cast<std::size_t>(index) >= table_.size())
    return false;
  const auto i = static_cast<std::size_t>(index);
  std::lock_guard lock(mutex_);
  if (table_[i].type == ParamType::text) {
    const char* text = *static_cast<const char* const*>(param);
    const std::string value = text == nullptr ? std::string() : std::string(text);
    if (value == values_.texts[i]) return false;
    values_.texts[i] = value;
    return true;
  }
  const double value = *static_cast<const double*>(param);
  if (value == values_.numbers[i]) return false;
  values_.numbers[i] = value;
  return true;
}

void ParamValues::get(void* param, int index) {
  if (param == nullptr || index < 0 || static_cast<std::size_t>(index) >= table_.size()) return;
  const auto i = static_cast<std::size_t>(index);
  std::lock_guard lock(mutex_);
  if (table_[i].type == ParamType::text)
    *static_cast<const char**>(param) = values_.texts[i].c_str();
  else
    *static_cast<double*>(param) = values_.numbers[i];
}

ParamValues::Values ParamValues::values() const {
  std::lock_guard lock(mutex_);
  return values_;
}

}  // namespace ifsfx::frei0r
