// SPDX-License-Identifier: Apache-2.0
// The entries of a Fractint .ifs file one by one, for load_ifs: a file whose other entries are
// (3D) or broken still yields the 2-D entry asked for. Users call parse_fractint (ifs/preset.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx::detail {

struct FractintEntry {
  std::string name;
  int line = 0;                     // of the name
  std::optional<IfsPreset> preset;  // the entry, when it can be used
  std::optional<Error> error;       // else why not: a (3D) entry, a bad number, a bad count
};

// Every entry in file order. Errors of the file's structure (a missing brace) throw Error{parse}.
std::vector<FractintEntry> read_fractint_entries(std::string_view text,
                                                 const std::string& filename);

}  // namespace ifsfx::detail
