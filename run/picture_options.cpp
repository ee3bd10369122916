// SPDX-License-Identifier: Apache-2.0
#include "run/picture_options.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {

Rgb colour_option(const std::string& text, const std::string& what) {
  std::string t = text;
  for (auto& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t == "black") return {0, 0, 0};
  if (t == "white") return {1, 1, 1};
  const auto fail = [&] {
    return Error(
        ErrorKind::parse,
        fmt::format("{}: a colour is black, white, #rrggbb or R,G,B with 0..255 (got '{}')", what,
                    text));
  };
  if (t.size() == 7 && t[0] == '#') {
    int v[3];
    for (int i = 0; i < 3; ++i) {
      std::size_t used = 0;
      try {
        v[i] = std::stoi(t.substr(1 + 2 * static_cast<std::size_t>(i), 2), &used, 16);
      } catch (const std::exception&) {
        throw fail();
      }
      if (used != 2) throw fail();
    }
    return {v[0] / 255.0, v[1] / 255.0, v[2] / 255.0};
  }
  int r = 0, g = 0, b = 0;
  char tail = 0;
  if (std::sscanf(t.c_str(), "%d,%d,%d%c", &r, &g, &b, &tail) == 3 && r >= 0 && r <= 255 &&
      g >= 0 && g <= 255 && b >= 0 && b <= 255)
    return {r / 255.0, g / 255.0, b / 255.0};
  throw fail();
}

bool format_has_alpha(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr";
}

flame::Rgba flame_background_option(const std::string& text, const std::string& what) {
  std::string t = text;
  for (auto& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t == "transparent") return {0, 0, 0, 0};
  try {
    const Rgb c = colour_option(text, what);
    return {c.r, c.g, c.b, 1};
  } catch (const Error&) {
    throw Error(ErrorKind::parse,
                fmt::format("{}: a flame's background is transparent, black, white, #rrggbb or "
                            "R,G,B with 0..255 (got '{}')",
                            what, text));
  }
}

}  // namespace ifsfx::app
