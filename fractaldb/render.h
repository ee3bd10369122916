// SPDX-License-Identifier: Apache-2.0
// FractalDB's pictures, as the reference generator draws them (fractal_renderer/ifs_function.py
// and make_fractaldb.py of hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch;
// docs/dataset.md says what is the same and what is not):
//
//  - the chaos game starts at the origin and draws `iterations` points, the origin included, no
//    burn-in, from numpy.random.seed(100): the same draws for every category, weight and
//    instance, so a category's instances differ only in their patches;
//  - the points are fitted to the picture: shifted so that the smallest x and y are 0 (the origin
//    is among them), scaled by (size − 2·padding) / extent, offset by the padding, truncated to
//    whole pixels (y down); a walk that overflows loses its points from 100 before its first NaN;
//  - `point` sets each point's pixel; `patch` pastes a 3×3 patch at (x + 1, y + 1) per point, in
//    order, each of its 9 pixels on or off by a random 9-bit mask in 1..511 (off pixels are pasted
//    black too); grey is (127, 127, 127), colour is point i's hue convert_color(i, 128);
//  - the picture is flipped top to bottom (y up), then written as 4 flips: as is, top-bottom,
//    left-right, both.
//
// The chaos game and the fit are the reference's double-precision operations in its order, so a
// `point` picture equals the reference's pixel for pixel. Its patch masks come from Python's
// unseeded `random` module; here they come from `seed` (mask_seed), so a dataset is the same
// from run to run, whatever the thread count.
//
// Pictures are kept as palette indices ("canvases", CV_8UC1, y down, before the flips): 0 black,
// 1 grey, or 1 + (i mod 128) for point i's hue.
//   const auto draws = fractaldb::reference_draws(settings.iterations);
//   const fractaldb::Points points = fractaldb::walk(category, weight, settings, draws);
//   const cv::Mat canvas = fractaldb::draw(points, settings, seed);
//   cv::Mat bgr; fractaldb::to_image(canvas, 0, settings.draw, false, bgr);   // flip 0
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/fractaldb_csv.h"

namespace ifsfx::fractaldb {

// make_fractaldb.py's --draw_type.
enum class DrawType { point_gray, point_color, patch_gray, patch_color };
const char* to_string(DrawType draw);
// "patch_gray", ... Throws Error{invalid_argument} naming `what`.
DrawType parse_draw_type(std::string_view text, const std::string& what = "draw");
bool is_patch(DrawType draw);
bool is_colour(DrawType draw);

// make_fractaldb.py's arguments and defaults.
struct DrawSettings {
  cv::Size size{512, 512};  // --image_size_x, --image_size_y
  cv::Size padding{6, 6};   // --pad_size_x, --pad_size_y: pixels left free at each side
  int iterations = 100000;  // --iteration: points drawn, the origin included
  DrawType draw = DrawType::patch_gray;  // --draw_type
};
// Throws Error{invalid_argument} for a size outside 1..32768 a side, padding below 0 or not
// leaving a pixel (2·padding ≥ size), iterations outside 1..10^9.
void check(const DrawSettings& settings);

// numpy.random.seed(100); numpy.random.random(iterations): the draws of every walk.
std::vector<double> reference_draws(int iterations);

// A point in the picture: column x, row y (y down, before the flips).
struct Pixel {
  std::uint16_t x = 0, y = 0;
  friend bool operator==(const Pixel&, const Pixel&) = default;
};
using Points = std::vector<Pixel>;

// The chaos game of `category` with every coefficient multiplied by `weight`, fitted to the
// picture; `draws` (at least iterations − 1 of them) pick the maps. At most `iterations` points
// (fewer when the walk overflowed).
Points walk(const Category& category, const Weight& weight, const DrawSettings& settings,
            std::span<const double> draws);
// The same into `points`, with the walk's coordinates kept in `buffers`: a thread that walks
// many times keeps both, and saves their allocation (and page faults) per walk.
struct WalkBuffers {
  std::vector<double> x, y;
};
void walk(const Category& category, const Weight& weight, const DrawSettings& settings,
          std::span<const double> draws, Points& points, WalkBuffers& buffers);

// The canvas of one picture: the points drawn by settings.draw, patches masked from `mask_seed`.
cv::Mat draw(const Points& points, const DrawSettings& settings, std::uint64_t mask_seed);
// The same into `canvas` (reallocated only when its size or type differ).
void draw(const Points& points, const DrawSettings& settings, std::uint64_t mask_seed,
          cv::Mat& canvas);

// The colours of the palette indices, (R, G, B): 2 entries for the grey types (black, 127), 129
// for the colour ones (black, then the reference's convert_color(i, 128) for i = 0..127).
std::vector<std::array<std::uint8_t, 3>> palette(DrawType draw);

// The 4 flips, as the reference writes them: 0 as is (y up), 1 top-bottom, 2 left-right, 3 both.
inline constexpr int kFlips = 4;

// Flip `flip` of a canvas as the file shows it: CV_8UC3, BGR (or RGB with `rgb`), into `out`
// (allocated when it is not of that size and type).
void to_image(const cv::Mat& canvas, int flip, DrawType draw, bool rgb, cv::Mat& out);

// The reference's weight step K (its weights_0.1.csv): the weights of a dataset whose command,
// Python call or studio request names none are weights_table(kDefaultWeightStep).
inline constexpr double kDefaultWeightStep = 0.1;

// A dataset: categories × weights × instances × flips (make_fractaldb.py's loops).
struct DatasetSpec {
  std::vector<Category> categories;  // label = index; names must differ
  std::vector<Weight> weights;       // e.g. weights_table(kDefaultWeightStep)
  DrawSettings settings;
  int instances = 10;      // --instance: pictures per category and weight (patch types only; the
                           // point types draw one, as the reference does)
  std::uint64_t seed = 1;  // the patch masks
};

struct ImageKey {
  std::size_t category = 0, weight = 0;
  int instance = 0, flip = 0;
  friend bool operator==(const ImageKey&, const ImageKey&) = default;
};

// Throws Error{invalid_argument} for no categories, two of the same name, no weights, instances
// outside 1..100000, and what check(settings) throws.
void check(const DatasetSpec& spec);
// The pictures per category and weight: `instances` for the patch types, 1 for the point types.
int instances_drawn(const DatasetSpec& spec);
// categories × weights × instances_drawn × 4.
std::int64_t image_count(const DatasetSpec& spec);
// Image `index` in the reference's order: category, weight, instance, flip (the last fastest).
ImageKey image_key(const DatasetSpec& spec, std::int64_t index);
std::int64_t image_index(const DatasetSpec& spec, const ImageKey& key);
// Its file, relative to the dataset's folder, as the reference names it:
// "NAME/NAME_WW_count_I_flipT.png", WW the weight's index in two digits (more past 99).
std::string image_path(const DatasetSpec& spec, const ImageKey& key);
// The seed of the patch masks of (category name, weight, instance): a picture does not depend
// on which other categories a run holds, nor on its flip.
std::uint64_t mask_seed(const DatasetSpec& spec, const ImageKey& key);

}  // namespace ifsfx::fractaldb
