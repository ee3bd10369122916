// SPDX-License-Identifier: Apache-2.0
// IFS preset files: the native TOML format and Fractint's .ifs format, and finding a preset by
// name among the shipped ones (embedded in the library at build time) or by path.
//
// Native format (one IFS per file, extension .toml):
//   name = "barnsley-fern"
//   description = "Barnsley's fern"           # optional, one line
//   allow_expansive = false                    # optional: true accepts maps of factor ≥ 1
//                                              # when the IFS contracts on average
//   maps = [ [0.00, 0.00, 0.00, 0.16, 0.00, 0.00],  # a b c d e f
//            [0.85, 0.04, -0.04, 0.85, 0.00, 1.60], ... ]
//   probabilities = [0.01, 0.85, 0.07, 0.07]   # optional; default ∝ |det| with a floor
//   colours = ["#1b5e20", "#43a047", ...]      # optional, one per map
//   [seamless]                                 # optional: offered as a seamless tile
//   view = [x0, y0, x1, y1]                    # optional tile (default: the attractor framed)
//   offset = [0.5, 0.5]                        # optional: where the picture starts in it
// `name` defaults to the file's stem; a colour is "#rrggbb" or [r, g, b] with components in [0, 1];
// numbers may be TOML integers or floats; any other top-level key is an error (a misspelt
// "probabilites" would otherwise silently give default probabilities).
//
//   const IfsPreset fern = load_ifs("barnsley-fern");          // a shipped preset
//   const IfsPreset coral = load_ifs("my.ifs:coral", {.allow_expansive = true});
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ifs/ifs.h"
#include "ifs/tiles.h"

namespace ifsfx {

enum class PresetFormat { toml, fractint, fractaldb };

struct IfsPreset {
  Ifs ifs;
  std::string description;
  std::string origin;  // where it came from: "shipped:fern.toml", a path, "FILE.ifs:NAME"
  std::string text;    // the preset's own text (the TOML file, or the Fractint entry)
  PresetFormat format = PresetFormat::toml;
  // The file accepts maps of factor ≥ 1 when the IFS contracts on average: a TOML preset that
  // says `allow_expansive = true`. (Fractint entries are accepted so too, as Fractint renders
  // them, but with a warning: see load_ifs.)
  bool allow_expansive = false;
  // Offered as a seamless tile (`ifsfx render --seamless`, docs/seamless.md): the tile and the
  // offset it is shown at. Empty: not offered (--seamless still works, with the framed attractor).
  std::optional<SeamlessTile> seamless;
  // What the caller should tell the user, one line each (the library never prints): load_ifs
  // fills it.
  std::vector<std::string> warnings;
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
// description is the comment on the line of its '{'; its origin is "FILE:NAME". The p listed are
// turned into the probabilities Fractint draws with (fractint_probabilities); any finite p is
// read, negative ones included, as long as they are not all zero. Contraction is not checked
// here: load_ifs accepts an entry whose maps contract only on average, with a warning.
std::vector<IfsPreset> parse_fractint(std::string_view text, const std::string& filename);

// Fractint's selection rule: a uniform r in [0, 1] is walked along the cumulative sums of the
// listed weights, and the first map whose sum reaches r is drawn; when none does, the last map.
// So the weights need not be probabilities: the effective probability of map k < N−1 is
// L_k − L_{k−1}, with L_k the largest of the cumulative sums S_0..S_k clamped to [0, 1]
// (L_{−1} = 0), and the last map takes 1 − L_{N−2}. A negative weight takes nothing itself and
// shortens the share of the map after it (weights 0.3, −0.1, 0.3, 0.5 give 0.3, 0, 0.2, 0.5);
// weights past a sum of 1 are cut; a sum below 1 leaves the rest to the last map. Weights that are
// already probabilities (non-negative, sum 1 to 1e-9) are returned unchanged.
std::vector<double> fractint_probabilities(const std::vector<double>& weights);

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
  std::string problem;    // list_presets_in: why the entry cannot be loaded (empty: it can)
  bool seamless = false;  // offered as a seamless tile (IfsPreset::seamless)
};
std::vector<PresetSummary> list_shipped_presets();

// The presets of one file, for `ifsfx presets FILE`: each entry of a Fractint file (usable or
// not, with the reason, as load_ifs("FILE.ifs:NAME", options) would give it), or the one preset
// of a .toml file. Throws as load_ifs does for a file that cannot be read at all.
std::vector<PresetSummary> list_presets_in(const std::string& path,
                                           const ValidateOptions& options = {});

// Loads an IFS named on the command line: a shipped preset's name ("barnsley-fern"), a path to a
// .toml or .ifs file, "FILE.ifs:NAME" for one entry of a Fractint file (the first when no
// name), or a FractalDB category file, FILE.csv (rows a,b,c,d,e,f,p: fractaldb::read_category;
// named by its stem, its p normalised). Shipped names are a .toml file's stem or an entry name of a
// shipped .ifs file, matched exactly, else ignoring case; a bare file name that is not on disk may
// name a shipped file
// ("fractint-classics.ifs:coral"). Only the entry picked from a Fractint file must be usable.
// The IFS is validated (see validate()) with `origin` as the culprit: maps must contract
// (factor < 1) unless options.allow_expansive or the preset's own allow_expansive key says that
// contracting on average is enough. A Fractint entry whose maps contract only on average (a map
// of factor ≥ 1, such as a point reflection) is accepted as Fractint renders it, with one line in
// `warnings` saying so, and so is a FractalDB category (its search keeps random IFSs that contract
// on average); an IFS that does not contract on average is refused in every case.
// Throws Error{not_found} for an unknown name (suggesting the closest one) or a missing file,
// naming it, and the parse errors above.
IfsPreset load_ifs(const std::string& spec, const ValidateOptions& options = {});

// The colouring IFS G for a drawing IFS F (docs/design.md §3): default_colouring(N) for an empty
// spec, else the preset `spec` fitted to the unit square. Tilings that contract only over two steps
// (square-tiling-2/3) are accepted; a map count other than F's is refused with Error{invalid_ifs}
// naming `what`: "colouring: sierpinski-triangle must have as many maps as barnsley-fern (got 3
// for 4)".
Ifs load_colouring(const std::string& spec, const Ifs& F, const std::string& what = "colouring");

}  // namespace ifsfx
