// SPDX-License-Identifier: Apache-2.0
// Flame files: the <flame> XML of flam3 (flam3-genome's output, Debian's test.flam3), Apophysis
// 2.x/7X, JWildfire and Fractorium/Ember (docs/flames.md says what is read and how it maps onto
// flame/flame.h). A file holds one flame or many (<flames>, <pick>, any wrapper, or a bare
// sequence of <flame> elements); "FILE.flame:NAME" or "FILE.flame:INDEX" (0-based) picks one.
//
//   const Flame f = read_flame("packs/sheep.flame:244");
//   for (const FlameEntry& e : list_flames("packs/sheep.flame")) ...
//
// Errors are ifsfx::Error of kind parse, one line naming the file, the flame and the attribute:
//   sheep.flame: flame "244": xform 1: unknown variation "crackle2"
// (not_found for a missing file, a missing palette library or an unknown NAME/INDEX).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flame/flame.h"

namespace ifsfx::flame {

// Where Debian's flam3-palette package installs flam3's palette library.
inline constexpr const char* kDefaultPaletteFile = "/usr/share/flam3/flam3-palettes.xml";

struct FlameReadOptions {
  // flam3's palette library, read (at run time, only when a flame says palette="N" and has no
  // palette of its own) for flam3's numbered palettes.
  std::string palette_file = kDefaultPaletteFile;
};

// Every flame of an XML text, in document order. `where` (a file name) starts every message.
// Throws Error{parse} at the first flame that cannot be read.
std::vector<Flame> parse_flames(std::string_view xml, const std::string& where,
                                const FlameReadOptions& options = {});

// "FILE.flame:NAME" split into the file and the selector (empty when there is none). Only a
// colon after a flame file's extension (.flame, .flam3) splits.
struct FlameSpec {
  std::string path;
  std::string selector;
};
FlameSpec split_flame_spec(const std::string& spec);

// True when `spec` names a flame file (extension .flame or .flam3, optionally with a selector).
bool is_flame_spec(const std::string& spec);

// The flame a spec picks: by NAME (exactly), else by INDEX when the selector is a number; a file
// of one flame needs no selector. Throws Error{not_found} for an unknown name or index, and for a
// file of several flames without a selector, listing what the file holds.
Flame read_flame(const std::string& spec, const FlameReadOptions& options = {});

// All the flames of a file.
std::vector<Flame> read_flames(const std::string& path, const FlameReadOptions& options = {});

// One flame of a file, for `ifsfx presets FILE.flame`: its name and index, and why it cannot be
// rendered (the one-line message read_flame would throw; empty: it can).
struct FlameEntry {
  std::string name;
  std::size_t index = 0;
  std::size_t xforms = 0;  // 0 when it could not be read
  std::string problem;
};
// Throws only for a file that cannot be read at all (missing, not XML, no <flame>).
std::vector<FlameEntry> list_flames(const std::string& path, const FlameReadOptions& options = {});

// flam3's palette library: the 256 colours of palette `number`, hue-rotated by `hue` turns.
// Throws Error{not_found} naming the file when it is missing or has no such palette.
std::array<Rgba, 256> library_palette(const std::string& palette_file, int number, double hue);

}  // namespace ifsfx::flame
