// SPDX-License-Identifier: Apache-2.0
// Text that goes into metadata, JSON and TOML must be valid UTF-8, whatever the bytes it came
// from: a Fractint comment from a DOS-era file, a file name from another system.
#pragma once

#include <string>
#include <string_view>

namespace ifsfx {

// `text` made valid UTF-8: well-formed UTF-8 sequences are kept as they are; every other byte is
// read as Latin-1 (ISO 8859-1, the likeliest encoding of such text, where 0xE9 is 'é') and
// written as its UTF-8 sequence. Never fails; valid input comes back unchanged.
//   valid_utf8("caf\xe9") == "café"
std::string valid_utf8(std::string_view text);

}  // namespace ifsfx
