// SPDX-License-Identifier: Apache-2.0
#include "studio/fields.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {

using nlohmann::json;

namespace {

const json* present(const json& body, const char* field) {
  if (!body.is_object()) bad_field("request", "must be a JSON object", body);
  const auto it = body.find(field);
  return it == body.end() || it->is_null() ? nullptr : &*it;
}

}  // namespace

void bad_field(const std::string& field, const std::string& rule, const json& got) {
  throw Error(ErrorKind::parse,
              fmt::format("{}: {} (got {})", field, rule,
                          got.dump(-1, ' ', false, json::error_handler_t::replace)));
}

std::string text_field(const json& body, const char* field, const std::string& fallback) {
  const json* v = present(body, field);
  if (!v) return fallback;
  if (!v->is_string()) bad_field(field, "must be a string", *v);
  return v->get<std::string>();
}

std::string required_text(const json& body, const char* field) {
  const json* v = present(body, field);
  if (!v || !v->is_string() || v->get<std::string>().empty())
    bad_field(field, "must be given, a string", v ? *v : json("nothing"));
  return v->get<std::string>();
}

double number_field(const json& body, const char* field, double fallback, double low, double high) {
  const json* v = present(body, field);
  if (!v) return fallback;
  if (!v->is_number()) bad_field(field, "must be a number", *v);
  const double x = v->get<double>();
  if (!std::isfinite(x) || x < low || x > high)
    bad_field(field, fmt::format("must be a number in [{:g}, {:g}]", low, high), *v);
  return x;
}

std::int64_t integer_field(const json& body, const char* field, std::int64_t fallback,
                           std::int64_t low, std::int64_t high) {
  const json* v = present(body, field);
  if (!v) return fallback;
  const std::string rule = fmt::format("must be a whole number in [{}, {}]", low, high);
  if (!v->is_number()) bad_field(field, rule, *v);
  const double x = v->get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || x < static_cast<double>(low) ||
      x > static_cast<double>(high))
    bad_field(field, rule, *v);
  return static_cast<std::int64_t>(x);
}

bool bool_field(const json& body, const char* field, bool fallback) {
  const json* v = present(body, field);
  if (!v) return fallback;
  if (!v->is_boolean()) bad_field(field, "must be true or false", *v);
  return v->get<bool>();
}

std::string choice_field(const json& body, const char* field, const std::string& fallback,
                         const std::vector<std::string>& choices) {
  const std::string value = text_field(body, field, fallback);
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    bad_field(field, "one of " + list, json(value));
  }
  return value;
}

}  // namespace ifsfx::app
