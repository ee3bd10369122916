// SPDX-License-Identifier: Apache-2.0
// The superIFS reader's fuzz check (see fuzz_checks.h): a file it reads is valid, and the
// probabilities of the IFSs are ready for the V-variable step.
#pragma once

#include <cmath>
#include <string_view>

#include "ifs/error.h"
#include "superifs/superifs_file.h"
#include "tests/fuzz/fuzz_checks.h"

namespace ifsfx::fuzz {

inline void superifs_toml(std::string_view text) {
  SuperIfsPreset preset;
  try {
    preset = parse_superifs_toml(text, "fuzz.super.toml");
  } catch (const Error&) {
    return;
  }
  check(!preset.super.ifs.empty(), "a superIFS has IFSs");
  for (const Ifs& f : preset.super.ifs)
    check(f.maps.size() == preset.super.ifs[0].maps.size(), "every IFS has M maps");
  const std::vector<double> P = effective_probabilities(preset.super);
  check(P.size() == preset.super.ifs.size(), "one P_n per IFS");
  double sum = 0;
  for (double p : P) sum += p;
  check(std::abs(sum - 1) < 1e-9, "P sums to 1");
}

}  // namespace ifsfx::fuzz
