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
// `name` defaults to the file's stem; a colour is "#rrggbb" or [r, g, b] with components in [0, 1];
// numbers may be TOML integers or floats; any other top-level key is an error (a misspelt
// "probabilites" would otherwise silently give default probabilities).
//
//   const IfsPreset fern = load_ifs("barnsley-fern");          // a shipped preset
//   const IfsPreset coral = load_ifs("my.ifs:coral", {.allow_expansive = true});
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
// "FILE:LINE: rule (got X)" (Error{parse} for syntax, a wrong type or a map of the wrong length;
// Error{invalid_ifs} for NaN/inf coefficients, bad probabilities and counts that do not match
// the maps). Contraction is not checked here: load_ifs validates with the caller's options.
IfsPreset parse_ifs_toml(std::string_view text, const std::string& filename);

// Parses every entry of a Fractint .ifs file: `NAME { a b c d e f p ... }` entries, `;` comments,
// separators of spaces, tabs, commas and newlines; a missing p is accepted (all of an entry's or
// none), a count that fits neither 6 nor 7 per map is rejected (Error{parse}), `(3D)` entries are
// rejected (Error{unsupported}); errors read "FILE:LINE: entry 'NAME': rule (got X)". A count
// that is a multiple of both 6 and 7 is read with p when those p sum to 1. An entry's
// description is the comment on the line of its '{'; its origin is "FILE:NAME".
std::vector<IfsPreset> parse_fractint(std::string_view text, const std::string& filename);

// The native TOML text of an IFS (what the collage fitter writes; parse_ifs_toml reads it back
// exactly: numbers are written in their shortest round-trip form).
std::string to_toml(const Ifs& ifs, const std::string& description = {});

// A file shipped in presets/, embedded at build time.
struct ShippedFile {
  std::string_view name;  // file name, e.g. "barnsley-fern.toml"
  std::string_view text;
};
const std::vector<ShippedFile>& shipped_files();

// One line per shipped IFS preset, for `ifsfx presets`: the .toml files (superIFS presets,
// *.super.toml, are not IFSs and are skipped), then the entries of the shipped Fractint files.
struct PresetSummary {
  std::string name;
  std::size_t maps = 0;
  double contraction = 0;
  std::string description;
};
std::vector<PresetSummary> list_shipped_presets();

// Loads an IFS named on the command line: a shipped preset's name ("barnsley-fern"), a path to a
// .toml or .ifs file, or "FILE.ifs:NAME" for one entry of a Fractint file (the first when no
// name). Shipped names are a .toml file's stem or an entry name of a shipped .ifs file, matched
// exactly, else ignoring case; a bare file name that is not on disk may name a shipped file
// ("fractint-classics.ifs:coral"). Only the entry picked from a Fractint file must be usable.
// The IFS is validated (see validate()) with `origin` as the culprit. Throws Error{not_found}
// for an unknown name (suggesting the closest one) or a missing file, naming it, and the parse
// errors above.
IfsPreset load_ifs(const std::string& spec, const ValidateOptions& options = {});

// The colouring IFS G for a drawing IFS F (DESIGN.md §3): default_colouring(N) for an empty spec,
// else the preset `spec` fitted to the unit square. Tilings that contract only over two steps
// (square-tiling-2/3) are accepted; a map count other than F's is refused with Error{invalid_ifs}
// naming `what`: "--colouring sierpinski-triangle: must have as many maps as barnsley-fern (got 3
// for 4)".
Ifs load_colouring(const std::string& spec, const Ifs& F, const std::string& what = "--colouring");

}  // namespace ifsfx
