// SPDX-License-Identifier: Apache-2.0
// Reading the fields of the studio's JSON requests (docs/studio.md), each checked against its
// rule; a bad field throws Error{parse} "FIELD: rule (got X)", which the server answers with 400.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ifsfx::app {

// Throws Error{parse} "FIELD: RULE (got GOT)".
[[noreturn]] void bad_field(const std::string& field, const std::string& rule,
                            const nlohmann::json& got);

// body[field] when present (and not null), else `fallback`; a string.
std::string text_field(const nlohmann::json& body, const char* field, const std::string& fallback);
// A string that must be given.
std::string required_text(const nlohmann::json& body, const char* field);
// A finite number in [low, high].
double number_field(const nlohmann::json& body, const char* field, double fallback, double low,
                    double high);
// A whole number in [low, high].
std::int64_t integer_field(const nlohmann::json& body, const char* field, std::int64_t fallback,
                           std::int64_t low, std::int64_t high);
bool bool_field(const nlohmann::json& body, const char* field, bool fallback);
// One of `choices`.
std::string choice_field(const nlohmann::json& body, const char* field, const std::string& fallback,
                         const std::vector<std::string>& choices);

}  // namespace ifsfx::app
