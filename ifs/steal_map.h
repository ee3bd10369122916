// SPDX-License-Identifier: Apache-2.0
// The steal map of colour stealing (paper §4, Fig. 3; docs/design.md §3): per output pixel, the
// source coordinate T(x) = π_G(τ_F(x)) — the top address of x under the drawing IFS F, followed
// to a point under the colouring IFS G — and whether the pixel lies on the attractor at all.
// T depends on F, G and the output grid, never on the source pixels: computed once, it colours
// any number of images (video frames) by one remap each.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/ifs.h"
#include "ifs/output_file.h"
#include "ifs/sampling.h"
#include "ifs/view.h"

namespace ifsfx {

namespace detail {
struct CompactRemap;
}

// Coordinates in `source_uv` are normalised *image* coordinates of the source: u ∈ [0,1] left to
// right, v ∈ [0,1] top to bottom, so the source pixel is (u·W − 0.5, v·H − 0.5) for a W×H source.
// (The colouring IFS G itself lives on the unit square with y up: v = 1 − y.)
struct StealMap {
  cv::Mat source_uv;  // CV_32FC2, one (u, v) per output pixel
  cv::Mat coverage;   // CV_8UC1, 255 where the pixel lies on the attractor, 0 elsewhere

  cv::Size size() const { return coverage.size(); }
  bool empty() const { return coverage.empty(); }
};

struct StealMapOptions {
  // The plane rectangle of F shown, the chaos game's points per pixel before the coverage policy
  // (the exact map's attractor mask uses 4 per pixel plus growth), seed, threads, and the stop
  // flag, polled between chunks of work (the attractor raster, the chaos game, the descent).
  Sampling sampling;
  bool exact = true;  // per-pixel descent (docs/design.md §3); false: the chaos game
};

// What compute_steal_map did. The chaos game's coverage policy: `quality` points per pixel,
// then rounds of quality/4 more while a round adds more than 0.1 % to the pixels hit (at most 8);
// then up to 4 Hutchinson passes, one more chaos-game step from the point of every pixel by every
// map into the pixels still empty (it reaches what the invariant measure barely visits, and
// never leaves the attractor); then pixels still empty but lying between covered neighbours
// (along a row, a column or a diagonal) take the largest address among them (the tops rule,
// eq. 7). The exact map rasters its attractor mask the same way.
struct StealMapStats {
  std::uint64_t points = 0;    // chaos-game points plotted (for the exact map: its attractor mask)
  int rounds = 0;              // chaos-game rounds run (the first included)
  double hit = 0;              // chaos game: fraction of output pixels some point reached
  std::size_t propagated = 0;  // chaos game: pixels reached by the Hutchinson passes
  std::size_t filled = 0;      // chaos game: pixels filled from their neighbours
  double coverage = 0;         // fraction of output pixels on the attractor, in the map
  int levels = 0;              // symbols of the address followed per pixel
  double seconds = 0;          // wall time
  Box view;                    // the plane rectangle of F shown
};

// The steal map of F coloured through G on `size` pixels. G must have as many maps as F and is
// used as given on the unit square (see fit_to_unit_square). Throws Error{invalid_ifs} when the
// map counts differ.
//   auto T = compute_steal_map(fern, default_colouring(4), {1920, 1080}, {.exact = true});
StealMap compute_steal_map(const Ifs& F, const Ifs& G, cv::Size size,
                           const StealMapOptions& options = {}, StealMapStats* stats = nullptr);

// The default colouring IFS for N maps: a shipped square tiling for N = 2, 3, 4, 9, otherwise a
// strip or grid tiling of the unit square generated for N.
Ifs default_colouring(std::size_t n);

// G conjugated onto the unit square: its attractor's bounding box stretched onto [0,1]².
Ifs fit_to_unit_square(const Ifs& g);

enum class Interpolation { nearest, bilinear };

// What a remap does with an output pixel that reads nothing from the source (off the attractor),
// as cv::remap's border mode says.
enum class RemapBorder {
  constant,     // cv::BORDER_CONSTANT: the pixel gets ApplyOptions::background
  transparent,  // cv::BORDER_TRANSPARENT: the pixel (and any whose bilinear square leaves the
                // source) keeps what the output held: the video filter draws its background or
                // the original frame there first
};

struct ApplyOptions {
  Interpolation interpolation = Interpolation::bilinear;
  RemapBorder border = RemapBorder::constant;
  // Colour of the pixels that read nothing under a constant border: per channel, in the source's
  // channel order and value range (default black).
  cv::Scalar background = cv::Scalar::all(0);
  int threads = 0;  // workers that prepare and remap; 0 = all cores
};

// Colours the map's pixels from `source` (any size, CV_8UC3/CV_8UC4/CV_16U/CV_32F): returns an
// image of the map's size and the source's type (under a transparent border, zero where the map
// reads nothing).
cv::Mat apply(const StealMap& map, const cv::Mat& source, const ApplyOptions& options = {});

// A steal map made ready for sources of one size: the fixed-point remap tables (cv::convertMaps),
// computed once and reused for every frame — the one remap of `apply`, the video filter, the
// camera and the frei0r plugins. Covered pixels read the source clamped inside it; uncovered ones
// are sent off it, where options.border decides. 8-bit sources go through `compact`, the same
// table reduced to the covered pixels (the bytes cv::remap gives, on our own workers); other
// types through cv::remap.
//   const auto prepared = prepare_apply(T, frame.size());
//   for (...) apply(prepared, frame, out);
struct PreparedStealMap {
  cv::Size source_size;
  ApplyOptions options;
  cv::Mat xy;    // CV_16SC2: integer source pixel per output pixel
  cv::Mat frac;  // CV_16UC1: bilinear sub-pixel index (empty for nearest)
  // Null where the table needs cv::remap's general border handling (a source below 2×2).
  std::shared_ptr<const detail::CompactRemap> compact;

  cv::Size size() const { return xy.size(); }  // the output's, the map's
};
// Throws Error{invalid_argument} for an empty or malformed map, or a source size outside 1 to
// 32766 pixels a side (2 to 32766 under a transparent border).
PreparedStealMap prepare_apply(const StealMap& map, cv::Size source_size,
                               const ApplyOptions& options = {});

// The precondition of every remap through a prepared map: a non-empty source of 1 to 4 channels
// of 8/16-bit integers or floats, of the size the map was prepared for. Throws
// Error{invalid_argument} or Error{unsupported} "source image: ...".
void check_apply_source(const PreparedStealMap& map, const cv::Mat& source);

// Colours into `out` (reallocated only when its size or type differ; under a transparent border
// the pixels that read nothing keep what it held). Checks the source (check_apply_source).
void apply(const PreparedStealMap& map, const cv::Mat& source, cv::Mat& out);

// Output rows `rows` only, on the calling thread, for a caller that runs its own bands of rows
// (the video filter draws its background, remaps and blends band by band). The caller has checked
// the source (check_apply_source) and made `out` of map.size() and the source's type.
void apply_rows(const PreparedStealMap& map, const cv::Mat& source, cv::Mat& out, cv::Range rows);

// save/load: a versioned binary file; load throws Error{io} or Error{unsupported} for a file that
// is not a steal map, of another version, truncated, or corrupt (a coverage byte other than 0 and
// 255, a covered pixel whose source point is not finite), naming the path (and the pixel).
// With `expected_size`, a map of another size is refused (Error{invalid_argument}).
// save writes through the output policy (ifs/output_file.h): `output` names the inputs the map
// must not replace.
void save(const StealMap& map, const std::filesystem::path& path, const OutputOptions& output = {});
// The same into the temporary file of `out`, not committed (see commit_together).
void save(const StealMap& map, OutputFile& out);
StealMap load_steal_map(const std::filesystem::path& path,
                        std::optional<cv::Size> expected_size = std::nullopt);

}  // namespace ifsfx
