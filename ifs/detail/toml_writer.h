// SPDX-License-Identifier: Apache-2.0
// The pieces of TOML the preset writers share (ifs/preset_toml.cpp, superifs/superifs_file.cpp),
// so that every preset file ifsfx writes reads back to exactly the numbers it was made from.
#pragma once

#include <string>
#include <string_view>

namespace ifsfx::detail {

// The shortest text that reads back as exactly `x` ({fmt} prints the shortest round-trip form),
// kept a TOML float rather than an integer so that the file reads as coefficients.
std::string toml_number(double x);

// A TOML basic string; TOML text is UTF-8, so other bytes are read as Latin-1 (valid_utf8).
std::string toml_string(std::string_view text);

}  // namespace ifsfx::detail
