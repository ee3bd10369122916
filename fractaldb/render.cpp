// SPDX-License-Identifier: Apache-2.0
#include "fractaldb/render.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "ifs/detail/fractaldb_chaos.h"
#include "ifs/detail/numpy_random.h"
#include "ifs/error.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::fractaldb {
namespace {

constexpr std::array<std::pair<const char*, DrawType>, 4> kDrawTypes{{
    {"point_gray", DrawType::point_gray},
    {"point_color", DrawType::point_color},
    {"patch_gray", DrawType::patch_gray},
    {"patch_color", DrawType::patch_color},
}};

// NumPy's float64 → uint16 cast on x86-64 (a C cast: a 32-bit truncation, its low 16 bits),
// which the reference applies to its fitted coordinates; NaN and values past 32 bits give 0.
std::uint16_t numpy_uint16(double t) {
  if (!(t > -2147483649.0 && t < 2147483648.0)) return 0;
  return static_cast<std::uint16_t>(static_cast<std::int32_t>(t));
}

// np.min and np.max of a range, NaN when it holds a NaN.
struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};
Extent extent_of(const std::vector<double>& v, std::size_t count, double shift = 0) {
  Extent e;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = v[i] - shift;
    if (std::isnan(x)) return {std::nan(""), std::nan("")};
    e.lo = std::min(e.lo, x);
    e.hi = std::max(e.hi, x);
  }
  return e;
}

// The reference's __rescale on one axis: pixel coordinates of the first `count` values.
template <class Store>
void fit_axis(const std::vector<double>& v, std::size_t count, int size, int pad, Store store) {
  const Extent raw = extent_of(v, count);
  // `if np.min(xs) < 0.0: xs -= np.min(xs)`, then the extent of what is left.
  const bool shift = raw.lo < 0.0;
  const double m = raw.lo;
  const Extent e = shift ? extent_of(v, count, m) : raw;
  const double range = e.hi - e.lo;
  const double scale = static_cast<double>(size - 2 * pad), offset = static_cast<double>(pad);
  for (std::size_t i = 0; i < count; ++i) {
    const double x = shift ? v[i] - m : v[i];
    store(i, numpy_uint16(x / range * scale + offset));
  }
}

// convert_color(i, 128) of the reference: a hue per point index, (R, G, B).
std::array<std::uint8_t, 3> convert_color(int colour) {
  constexpr double pi = 3.141592653589793;  // math.pi
  const double S = 0.75;
  double H = 2.0 * pi * (static_cast<double>(colour % 128) / 128.0);
  if (H >= 2.0 * pi) H -= 2.0 * pi;
  const double h = std::floor((3.0 / pi) * H);
  const double I = 0.75;
  const double P = I * (1.0 - S);
  const double Q = I * (1.0 - S * ((3.0 / pi) * H - h));
  const double T = I * (1.0 - S * ((1.0 - (3.0 / pi) * H) + h));
  const auto u8 = [](double x) { return static_cast<std::uint8_t>(x * 255.0); };
  const std::uint8_t i = u8(I), p = u8(P), q = u8(Q), t = u8(T);
  switch (static_cast<int>(h)) {
    case 0:
      return {p, t, i};
    case 1:
      return {p, i, q};
    case 2:
      return {t, i, p};
    case 3:
      return {i, q, p};
    case 4:
      return {i, p, t};
    default:
      return {q, p, i};
  }
}

// The hash of a category's name, for its mask seeds (FNV-1a).
std::uint64_t name_hash(const std::string& name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char ch : name) h = (h ^ ch) * 0x100000001b3ULL;
  return h;
}

// Masks uniform in 1..511, seven from each 64-bit draw (a zero chunk is skipped).
class MaskStream {
 public:
  explicit MaskStream(std::uint64_t seed) : rng_(seed) {}
  unsigned next() {
    for (;;) {
      if (left_ == 0) {
        bits_ = rng_.next();
        left_ = 7;
      }
      const auto v = static_cast<unsigned>(bits_ & 511);
      bits_ >>= 9;
      --left_;
      if (v != 0) return v;
    }
  }

 private:
  Rng rng_;
  std::uint64_t bits_ = 0;
  int left_ = 0;
};

void draw_points(const Points& points, bool colour, cv::Mat& canvas) {
  const auto width = static_cast<unsigned>(canvas.cols),
             height = static_cast<unsigned>(canvas.rows);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Pixel p = points[i];
    // The reference indexes image[y, x]; a point on the far edge (padding 0) is dropped here.
    if (p.x >= width || p.y >= height) continue;
    canvas.ptr<std::uint8_t>(p.y)[p.x] = colour ? static_cast<std::uint8_t>(1 + (i & 127)) : 1;
  }
}

// image.paste(patch, (x + 1, y + 1)): the 3×3 block replaced, its pixel (row r, column j) lit by
// bit 8 − (3r + j) of the mask ('{:09b}'.format(mask)[3r + j]).
void draw_patches(const Points& points, bool colour, std::uint64_t seed, cv::Mat& canvas) {
  // Row patterns: 3 bits, the first pixel in the highest, as bytes 0/1 in memory order.
  std::array<std::uint32_t, 8> rows{};
  for (unsigned bits = 0; bits < 8; ++bits) {
    const std::uint8_t bytes[4] = {static_cast<std::uint8_t>(bits >> 2 & 1),
                                   static_cast<std::uint8_t>(bits >> 1 & 1),
                                   static_cast<std::uint8_t>(bits & 1), 0};
    std::memcpy(&rows[bits], bytes, 4);
  }
  MaskStream masks(seed);
  const int width = canvas.cols, height = canvas.rows;
  const auto step = static_cast<std::ptrdiff_t>(canvas.step);
  std::uint8_t* const base = canvas.data;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const unsigned mask = masks.next();
    const std::uint32_t value = colour ? static_cast<std::uint32_t>(1 + (i & 127)) : 1;
    const int x = points[i].x + 1, y = points[i].y + 1;
    if (x + 3 <= width && y + 3 <= height) {
      std::uint8_t* at = base + y * step + x;
      for (int r = 0; r < 3; ++r, at += step) {
        const std::uint32_t row = rows[mask >> (6 - 3 * r) & 7] * value;
        std::memcpy(at, &row, 3);
      }
      continue;
    }
    // PIL clips a paste at the picture's edges.
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < 3; ++j)
        if (x + j < width && y + r < height)
          canvas.ptr<std::uint8_t>(y + r)[x + j] =
              (mask >> (8 - (3 * r + j)) & 1) ? static_cast<std::uint8_t>(value) : 0;
  }
}

}  // namespace

const char* to_string(DrawType draw) {
  for (const auto& [name, type] : kDrawTypes)
    if (type == draw) return name;
  return "?";
}

DrawType parse_draw_type(std::string_view text, const std::string& what) {
  for (const auto& [name, type] : kDrawTypes)
    if (text == name) return type;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: must be one of point_gray, point_color, patch_gray, patch_color "
                          "(got '{}')",
                          what, text));
}

bool is_patch(DrawType draw) {
  return draw == DrawType::patch_gray || draw == DrawType::patch_color;
}
bool is_colour(DrawType draw) {
  return draw == DrawType::point_color || draw == DrawType::patch_color;
}

void check(const DrawSettings& s) {
  check_size(s.size, "size");
  if (s.padding.width < 0 || s.padding.height < 0 || 2 * s.padding.width >= s.size.width ||
      2 * s.padding.height >= s.size.height)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("padding: must be ≥ 0 and leave pixels inside {}x{} (got {}x{})",
                            s.size.width, s.size.height, s.padding.width, s.padding.height));
  if (s.iterations < 1 || s.iterations > 1'000'000'000)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("iterations: must be 1..1000000000 (got {})", s.iterations));
}

std::vector<double> reference_draws(int iterations) {
  detail::NumpyRandom random(100);
  std::vector<double> draws(static_cast<std::size_t>(std::max(iterations, 0)));
  for (double& r : draws) r = random.random();
  return draws;
}

Points walk(const Category& category, const Weight& weight, const DrawSettings& settings,
            std::span<const double> draws) {
  Points points;
  WalkBuffers buffers;
  walk(category, weight, settings, draws, points, buffers);
  return points;
}

void walk(const Category& category, const Weight& weight, const DrawSettings& settings,
          std::span<const double> draws, Points& points, WalkBuffers& buffers) {
  // set_param: every coefficient times its weight; p as written.
  std::vector<AffineMap> maps;
  for (const AffineMap& f : category.maps)
    maps.push_back({f.a * weight[0], f.b * weight[1], f.c * weight[2], f.d * weight[3],
                    f.e * weight[4], f.f * weight[5]});
  const detail::ReferenceMaps reference(maps, category.probabilities);
  const auto n = static_cast<std::size_t>(settings.iterations);
  if (draws.size() + 1 < n)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("draws: a walk of {} points needs {} draws (got {})", n, n - 1, draws.size()));
  std::vector<double>& xs = buffers.x;
  std::vector<double>& ys = buffers.y;
  xs.resize(n);
  ys.resize(n);
  xs[0] = ys[0] = 0;
  // calculate(): from the origin; when no map is picked, `next_x` keeps its last value.
  double x = 0, y = 0, next_x = 0, next_y = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const int j = reference.pick(draws[i]);
    if (j >= 0) {
      const AffineMap& f = reference.maps[static_cast<std::size_t>(j)];
      next_x = x * f.a + y * f.b + f.e;
      next_y = x * f.c + y * f.d + f.f;
    }
    xs[i + 1] = x = next_x;
    ys[i + 1] = y = next_y;
  }
  // __rescale's NaN rule: the 100 points before the first NaN of x (else of y) go with it and
  // everything after. Once x or y is NaN, both are from the next point on.
  const auto first_nan = [](const std::vector<double>& v) {
    return static_cast<std::size_t>(
        std::find_if(v.begin(), v.end(), [](double t) { return std::isnan(t); }) - v.begin());
  };
  std::size_t k = first_nan(xs);
  if (k == n) k = first_nan(ys);
  const std::size_t kept = k == n ? n : k >= 100 ? k - 100 : 0;  // none: the reference fails
  points.resize(kept);
  fit_axis(xs, kept, settings.size.width, settings.padding.width,
           [&](std::size_t i, std::uint16_t v) { points[i].x = v; });
  fit_axis(ys, kept, settings.size.height, settings.padding.height,
           [&](std::size_t i, std::uint16_t v) { points[i].y = v; });
}

cv::Mat draw(const Points& points, const DrawSettings& settings, std::uint64_t mask_seed) {
  cv::Mat canvas;
  draw(points, settings, mask_seed, canvas);
  return canvas;
}

void draw(const Points& points, const DrawSettings& settings, std::uint64_t mask_seed,
          cv::Mat& canvas) {
  canvas.create(settings.size, CV_8UC1);
  canvas.setTo(0);
  if (is_patch(settings.draw))
    draw_patches(points, is_colour(settings.draw), mask_seed, canvas);
  else
    draw_points(points, is_colour(settings.draw), canvas);
}

std::vector<std::array<std::uint8_t, 3>> palette(DrawType draw) {
  std::vector<std::array<std::uint8_t, 3>> colours{{0, 0, 0}};
  if (!is_colour(draw)) {
    colours.push_back({127, 127, 127});
    return colours;
  }
  for (int i = 0; i < 128; ++i) colours.push_back(convert_color(i));
  return colours;
}

void to_image(const cv::Mat& canvas, int flip, DrawType draw, bool rgb, cv::Mat& out) {
  if (canvas.type() != CV_8UC1 || flip < 0 || flip >= kFlips)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("flip: a canvas (CV_8UC1) has flips 0..3 (got type {}, flip {})",
                            canvas.type(), flip));
  out.create(canvas.size(), CV_8UC3);
  // Each index as 4 bytes B, G, R, (next): stored overlapping, 3 bytes apart.
  const auto colours = palette(draw);
  std::array<std::uint32_t, 256> lut{};
  for (std::size_t k = 0; k < colours.size(); ++k) {
    const auto& c = colours[k];
    lut[k] = rgb ? (c[0] | c[1] << 8 | c[2] << 16) : (c[2] | c[1] << 8 | c[0] << 16);
  }
  const int width = canvas.cols, height = canvas.rows;
  // The canvas is y down; flip 0 is the picture turned y up (FLIP_TOP_BOTTOM).
  const bool upside_down = flip == 0 || flip == 2, mirrored = flip >= 2;
  for (int r = 0; r < height; ++r) {
    const std::uint8_t* src = canvas.ptr<std::uint8_t>(upside_down ? height - 1 - r : r);
    std::uint8_t* dst = out.ptr<std::uint8_t>(r);
    const int last = width - 1;  // written apart: its 4th byte would pass the row's end
    for (int c = 0; c < last; ++c) {
      const std::uint32_t v = lut[src[mirrored ? width - 1 - c : c]];
      std::memcpy(dst + 3 * c, &v, 4);
    }
    const std::uint32_t v = lut[src[mirrored ? 0 : last]];
    std::memcpy(dst + 3 * last, &v, 3);
  }
}

void check(const DatasetSpec& spec) {
  check(spec.settings);
  if (spec.categories.empty())
    throw Error(ErrorKind::invalid_argument, "categories: a dataset needs at least one (got none)");
  std::set<std::string> names;
  for (const Category& c : spec.categories)
    if (!names.insert(c.name).second)
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("categories: two are named {}: their images would share a folder", c.name));
  if (spec.weights.empty())
    throw Error(ErrorKind::invalid_argument, "weights: a dataset needs at least one (got none)");
  if (spec.instances < 1 || spec.instances > 100000)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("instances: must be 1..100000 (got {})", spec.instances));
}

int instances_drawn(const DatasetSpec& spec) {
  return is_patch(spec.settings.draw) ? spec.instances : 1;
}

std::int64_t image_count(const DatasetSpec& spec) {
  return static_cast<std::int64_t>(spec.categories.size()) *
         static_cast<std::int64_t>(spec.weights.size()) * instances_drawn(spec) * kFlips;
}

ImageKey image_key(const DatasetSpec& spec, std::int64_t index) {
  if (index < 0 || index >= image_count(spec))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("index: the dataset has images 0..{} (got {})", image_count(spec) - 1, index));
  const std::int64_t instances = instances_drawn(spec);
  const auto weights = static_cast<std::int64_t>(spec.weights.size());
  ImageKey key;
  key.flip = static_cast<int>(index % kFlips);
  index /= kFlips;
  key.instance = static_cast<int>(index % instances);
  index /= instances;
  key.weight = static_cast<std::size_t>(index % weights);
  key.category = static_cast<std::size_t>(index / weights);
  return key;
}

std::int64_t image_index(const DatasetSpec& spec, const ImageKey& key) {
  return ((static_cast<std::int64_t>(key.category) *
               static_cast<std::int64_t>(spec.weights.size()) +
           static_cast<std::int64_t>(key.weight)) *
              instances_drawn(spec) +
          key.instance) *
             kFlips +
         key.flip;
}

std::string image_path(const DatasetSpec& spec, const ImageKey& key) {
  const std::string& name = spec.categories.at(key.category).name;
  return fmt::format("{}/{}_{:02}_count_{}_flip{}.png", name, name, key.weight, key.instance,
                     key.flip);
}

std::uint64_t mask_seed(const DatasetSpec& spec, const ImageKey& key) {
  const std::uint64_t category = name_hash(spec.categories.at(key.category).name);
  return stream_seed(
      stream_seed(spec.seed, category),
      (static_cast<std::uint64_t>(key.weight) << 32) | static_cast<std::uint32_t>(key.instance));
}

}  // namespace ifsfx::fractaldb
