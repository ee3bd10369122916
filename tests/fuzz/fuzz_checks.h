// SPDX-License-Identifier: Apache-2.0
// What the fuzz harnesses check for one input, shared by the libFuzzer programs (fuzz/*_fuzz.cpp,
// built by tools/run-fuzz.sh) and by the GoogleTest suites that replay the seed corpus and every
// input a fuzzer once broke (tests/fuzz/corpus, tests/fuzz/regressions) in the normal builds.
//
// A reader may refuse any input with ifsfx::Error: that is the contract. Anything else — another
// exception (an "internal error" for the user), a crash, a sanitizer report, a hang — is a bug,
// and so is a broken property (check() throws std::logic_error naming it).
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

#include "fractaldb/dataset.h"
#include "fractaldb/render.h"
#include "ifs/error.h"
#include "ifs/ifs.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"

namespace ifsfx::fuzz {

inline void check(bool property, const char* what) {
  if (!property) throw std::logic_error(std::string("fuzz property broken: ") + what);
}

// A validated IFS is usable: finite maps, probabilities that sum to 1, one per map.
inline void check_usable(const Ifs& ifs) {
  ValidateOptions options;
  options.allow_expansive = true;
  try {
    validate(ifs, "fuzz", options);
  } catch (const Error&) {
    return;
  }
  check(!ifs.maps.empty(), "a validated IFS has maps");
  check(ifs.probabilities.empty() || ifs.probabilities.size() == ifs.maps.size(),
        "one probability per map");
}

// The native TOML reader; what it reads, to_toml writes back so that it reads the same.
inline void preset_toml(std::string_view text) {
  IfsPreset preset;
  try {
    preset = parse_ifs_toml(text, "fuzz.toml");
  } catch (const Error&) {
    return;
  }
  check_usable(preset.ifs);
  IfsPreset again;
  try {
    again = parse_ifs_toml(to_toml(preset.ifs, preset.description), "again.toml");
  } catch (const Error& e) {
    throw std::logic_error(std::string("to_toml wrote what parse_ifs_toml refuses: ") + e.what());
  }
  check(again.ifs.name == preset.ifs.name, "to_toml keeps the name");
  check(again.description == preset.description, "to_toml keeps the description");
  check(again.ifs.maps == preset.ifs.maps, "to_toml keeps every coefficient exactly");
  check(again.ifs.probabilities == preset.ifs.probabilities, "to_toml keeps the probabilities");
  check(again.ifs.colours == preset.ifs.colours, "to_toml keeps the colours exactly");
}

// The Fractint .ifs reader: every entry, usable or refused with its reason.
inline void fractint(std::string_view text) {
  try {
    for (const IfsPreset& preset : parse_fractint(text, "fuzz.ifs")) check_usable(preset.ifs);
  } catch (const Error&) {
  }
}

// FractalDB's CSV readers, the same bytes as a category and as weights. A category read is
// usable: finite maps, p ≥ 0 summing to 1, contracting on average; category_text writes it back
// so that it reads the same; a small picture of it draws, plain and weighted to overflow.
inline void fractaldb_csv(std::string_view text) {
  try {
    for (const fractaldb::Weight& w : fractaldb::parse_weights(text, "fuzz-weights.csv"))
      for (const double x : w) check(std::isfinite(x), "weights are finite");
  } catch (const Error&) {
  }
  fractaldb::Category c;
  try {
    c = fractaldb::parse_category(text, "fuzz.csv");
  } catch (const Error&) {
    return;
  }
  check(!c.maps.empty() && c.maps.size() == c.probabilities.size(), "one p per map");
  double sum = 0;
  for (std::size_t i = 0; i < c.maps.size(); ++i) {
    check(c.maps[i].finite(), "finite maps");
    check(c.probabilities[i] >= 0, "p >= 0");
    sum += c.probabilities[i];
  }
  check(std::abs(sum - 1) <= 1e-6, "p sums to 1");
  check(fractaldb::contraction_rate(c.maps, c.probabilities) < 0, "a category read contracts");
  fractaldb::Category again;
  try {
    again = fractaldb::parse_category(fractaldb::category_text(c), "fuzz.csv");
  } catch (const Error& e) {
    throw std::logic_error(std::string("category_text wrote what parse_category refuses: ") +
                           e.what());
  }
  check(again.maps == c.maps && again.probabilities == c.probabilities,
        "category_text keeps every number exactly");
  const fractaldb::DrawSettings settings{.size = {16, 12},
                                         .padding = {1, 1},
                                         .iterations = 300,
                                         .draw = fractaldb::DrawType::patch_color};
  const auto draws = fractaldb::reference_draws(settings.iterations);
  for (const fractaldb::Weight& w :
       {fractaldb::Weight{1, 1, 1, 1, 1, 1}, fractaldb::Weight{40, 40, 40, 40, 1e300, 1e300}}) {
    const fractaldb::Points points = fractaldb::walk(c, w, settings, draws);
    check(points.size() <= 300, "at most `iterations` points");
    const cv::Mat canvas = fractaldb::draw(points, settings, 1);
    cv::Mat image;
    fractaldb::to_image(canvas, 3, settings.draw, false, image);
    check(image.size() == cv::Size(16, 12) && image.type() == CV_8UC3, "a 16x12 BGR picture");
    check(!fractaldb::encode_png(canvas, 2, settings.draw, false).empty(), "a PNG");
  }
}

// The steal map file reader (a path: the bytes go to a scratch file first). A map it loads can be
// applied; small ones are, to a small frame.
inline void steal_map_file(std::string_view bytes, const std::filesystem::path& scratch) {
  {
    std::ofstream out(scratch, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  StealMap map;
  try {
    map = load_steal_map(scratch);
  } catch (const Error&) {
    return;
  }
  check(!map.empty() && map.source_uv.size() == map.coverage.size(), "a loaded map is whole");
  if (map.size().area() > 4096) return;
  const cv::Mat frame(6, 8, CV_8UC3, cv::Scalar(10, 20, 30));
  ApplyOptions options;
  options.threads = 1;
  const cv::Mat out = apply(map, frame, options);
  check(out.size() == map.size() && out.type() == frame.type(), "apply gives the map's size");
}

// A scratch file of this process for steal_map_file.
inline std::filesystem::path scratch_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("ifsfx-fuzz-" + name + "-" + std::to_string(getpid()));
}

}  // namespace ifsfx::fuzz
