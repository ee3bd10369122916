// SPDX-License-Identifier: Apache-2.0
// Option parsing shared by the subcommands: sizes, views, colours, thread counts. Thin wrappers
// that turn a command-line string into a library type, reporting errors as ifsfx::Error.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>

#include <fmt/format.h>

#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/output_file.h"
#include "ifs/parallel.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"
#include "run/arguments.h"

namespace ifsfx::app {

// The --help text of an option taking one of `names`, e.g. "{attractor,measure}=measure" (CLI11's
// own shows the enum's numbers too).
template <class Map>
std::string choices_text(const Map& names, const std::string& fallback) {
  std::string text = "{";
  for (const auto& [name, value] : names) text += (text.size() > 1 ? "," : "") + name;
  return text + "}=" + fallback;
}

// A transform for an enum option taking one of `names` (case ignored), with a plain error:
// "--mode: must be one of attractor, measure, steal, tops (got 'bogus')".
template <class Map>
CLI::Validator choice(const Map& names) {
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        std::string key = value;
        for (auto& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        const auto found = names.find(key);
        if (found == names.end()) {
          std::string list;
          for (const auto& [name, unused] : names) list += (list.empty() ? "" : ", ") + name;
          return "must be one of " + list + " (got '" + value + "')";
        }
        value = std::to_string(static_cast<int>(found->second));  // CLI11 reads enums as numbers
        return {};
      },
      "");
}

// A check for a number option: a finite number in [low, high] (or (low, high] with
// `above_low`), with a plain error naming the option: "--margin: must be a number in [0, 10]
// (got nan)". CLI11's own Range lets NaN through.
inline CLI::Validator number_in(double low, double high, bool above_low = false) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        try {
          std::size_t used = 0;
          value = std::stod(text, &used);
          if (used != text.size()) return "expected a number (got '" + text + "')";
        } catch (const std::exception&) {
          return "expected a number (got '" + text + "')";
        }
        const bool inside =
            std::isfinite(value) && (above_low ? value > low : value >= low) && value <= high;
        if (inside) return {};
        return fmt::format("must be a number in {}{:g}, {:g}] (got {})", above_low ? "(" : "[", low,
                           high, text);
      },
      "");
}

// A check for a whole-number option that must not be negative (a seed, a count): CLI11 would
// wrap "-1" into an unsigned seed, and its own NonNegativeNumber prints the largest double.
inline CLI::Validator not_negative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.find_first_not_of(" \t") != std::string::npos &&
            text[text.find_first_not_of(" \t")] == '-')
          return "must be 0 or more (got " + text + ")";
        return {};
      },
      "");
}

// --threads, the same for every command: 0 = all cores, at most kMaxThreads (more would only
// multiply per-thread buffers and a codec's per-thread frames).
inline CLI::Option* add_threads_option(CLI::App& cmd, int& threads) {
  return cmd
      .add_option("--threads", threads,
                  fmt::format("Worker threads, 0 = all cores (at most {})", kMaxThreads))
      ->capture_default_str()
      ->check(CLI::Range(0, kMaxThreads));
}

// A library's warnings (IfsPreset::warnings: a Fractint entry accepted because it contracts on
// average) on stderr, one line each: "ifsfx: warning: ...".
inline void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) fmt::print(stderr, "ifsfx: warning: {}\n", warning);
}

// load_ifs, and its warnings printed.
inline IfsPreset load_preset(const std::string& spec, const ValidateOptions& options = {}) {
  IfsPreset preset = load_ifs(spec, options);
  print_warnings(preset.warnings);
  return preset;
}

}  // namespace ifsfx::app
