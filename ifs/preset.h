// IFS preset files: the native TOML format and Fractint's .ifs format, and finding a preset by
// name among the shipped ones (embedded in the library at build time) or by path.
//
// Native format (one IFS per file, extension .toml):
//   name = "barnsley-fern"
//   description = "Barnsley's fern"           # optional, one line
//   maps = [ [0.00, 0.00, 0.00, 0.16, 0.00, 0.00],  # a b c d e f
//            [0.85, 0.04, -0.04, 0.85, 0.00, 1.60], ... ]
//   probabilities = [0.01, 0.85, 0.07, 0.07]   # optional; default ∝ |det| with a floor
//   colours = ["#1b5e20", "#43a047", ...]      # optional, one per map
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ifs/ifs.h"

namespace ifsfx {

struct IfsPreset {
  Ifs ifs;
  std::string description;
  std::string origin;  // where it came from: "shipped:fern.toml", a path, "FILE.ifs:NAME"
  std::string text;    // the preset's own text (the TOML file, or the Fractint entry)
};

// Parses a native TOML preset. `filename` names the source in errors, which read
// "FILE:LINE: rule (got X)" (Error{parse} for syntax, Error{invalid_ifs} for bad maps).
IfsPreset parse_ifs_toml(std::string_view text, const std::string& filename);

// Parses every entry of a Fractint .ifs file: `NAME { a b c d e f p ... }` entries, `;` comments,
// separators of spaces, tabs, commas and newlines; a missing p is accepted (all of an entry's or
// none), a count that fits neither 6 nor 7 per map is rejected, `(3D)` entries are rejected.
std::vector<IfsPreset> parse_fractint(std::string_view text, const std::string& filename);

// The native TOML text of an IFS (what the collage fitter writes; parse_ifs_toml reads it back).
std::string to_toml(const Ifs& ifs, const std::string& description = {});

// A file shipped in presets/, embedded at build time.
struct ShippedFile {
  std::string_view name;  // file name, e.g. "barnsley-fern.toml"
  std::string_view text;
};
const std::vector<ShippedFile>& shipped_files();

// One line per shipped IFS preset, for `ifsfx presets`.
struct PresetSummary {
  std::string name;
  std::size_t maps = 0;
  double contraction = 0;
  std::string description;
};
std::vector<PresetSummary> list_shipped_presets();

// Loads an IFS named on the command line: a shipped preset's name ("barnsley-fern"), a path to a
// .toml or .ifs file, or "FILE.ifs:NAME" for one entry of a Fractint file (the first when no
// name). The IFS is validated (see validate()). Throws Error{not_found} for an unknown name or a
// missing file, naming it, and the parse errors above.
IfsPreset load_ifs(const std::string& spec, const ValidateOptions& options = {});

}  // namespace ifsfx
