// SPDX-License-Identifier: Apache-2.0
// SuperIFS preset files (extension .super.toml), the same TOML family as the IFS presets of
// ifs/preset.h:
//
//   name = "paper-fig4"
//   description = "Paper Fig. 4: Sierpinski triangles of factor 1/2 and 1/3"   # optional
//   probabilities = [0.5, 0.5]        # optional P_1..P_N; default uniform
//   view = [0.0, 0.0, 1.0, 1.0]       # optional plane rectangle x0, y0, x1, y1 shown on the
//                                     # whole raster (stretched); default: auto-framed
//   [[ifs]]                           # F^1; one [[ifs]] table per IFS, all with M maps
//   name = "half"                     # optional
//   maps = [ [0.5, 0, 0, 0.5, 0, 0], ... ]   # a b c d e f, as in IFS presets
//   probabilities = [ ... ]           # optional p^n_m (measure mode); default ∝ |det|
//   [[ifs]]                           # F^2 ...
//   [[colouring]]                     # optional colouring IFS G (unit square, y up): one table
//   maps = [ ... ]                    # for every n, or one per [[ifs]]; default: the tiling
//                                     # default_colouring(M)
//   [seamless]                        # optional: offered as a seamless tile (ifs/tiles.h):
//   view = [x0, y0, x1, y1]           # optional tile, default the view above
//   offset = [0.5, 0.5]               # optional: where the picture starts in the period
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ifs/tiles.h"
#include "superifs/superifs.h"

namespace ifsfx {

struct SuperIfsPreset {
  SuperIfs super;
  std::string description;
  std::string origin;  // "shipped:paper-fig4.super.toml" or the path it was read from
  std::string text;    // the file's own text (stored in the metadata of rendered images)
  // Offered as a seamless tile (`ifsfx texture --seamless`, docs/seamless.md); empty: not offered.
  std::optional<SeamlessTile> seamless;
};

// The extension that marks a superIFS preset among the files of presets/.
inline constexpr std::string_view superifs_extension = ".super.toml";

// Parses a superIFS TOML file and validates it. Errors read "FILE:LINE: rule (got X)":
// Error{parse} for syntax, unknown keys and wrong types, Error{invalid_ifs} for bad maps,
// probabilities or map counts.
SuperIfsPreset parse_superifs_toml(std::string_view text, const std::string& filename);

// The TOML text of a superIFS preset in the format above, which parse_superifs_toml reads back to
// the same SuperIfs (every number exactly).
//   write_file("mine.super.toml", to_toml(preset.super, preset.description));
std::string to_toml(const SuperIfs& super, const std::string& description = {});

// Loads a superIFS named on the command line: a shipped preset's name ("paper-fig4", the file
// stem without .super.toml) or a path to a .toml file. Throws Error{not_found} naming the spec
// and the shipped names when neither exists, and the parse errors above.
SuperIfsPreset load_superifs(const std::string& spec);

// One line per shipped superIFS preset, sorted by name.
struct SuperIfsSummary {
  std::string name;
  std::size_t ifs = 0;   // N
  std::size_t maps = 0;  // M
  std::string description;
  bool seamless = false;  // offered as a seamless tile (SuperIfsPreset::seamless)
};
std::vector<SuperIfsSummary> list_shipped_superifs();

}  // namespace ifsfx
