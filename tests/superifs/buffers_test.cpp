// SPDX-License-Identifier: Apache-2.0
// The V-variable step (eq. 14) against known answers: an IFS alone gives its attractor, pieces
// are images of previous buffers, at most V distinct sub-shapes, burn-in forgets the start, and
// threads never change a pixel.
#include "superifs/buffers.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/render.h"
#include "superifs_fixtures.h"

namespace ifsfx {
namespace {

using testing::iou;
using testing::paper_fig4;
using testing::sierpinski_triangle;
using testing::triangle_corner;

// Slow, plain reference (docs/design.md §3): the attractor by the deterministic set iteration
// M_{k+1} = ∪ f_m(M_k) from the full raster, a pixel set when the pixel under f_m⁻¹ of its centre
// meets M_k dilated by r (cv::dilate), iterated until nothing changes.
cv::Mat reference_attractor(const Ifs& f, const Viewport& vp, int r) {
  cv::Mat m(vp.size, CV_8UC1, cv::Scalar(255));
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {2 * r + 1, 2 * r + 1});
  for (int k = 0; k < 200; ++k) {
    cv::Mat d;
    cv::dilate(m, d, kernel);
    cv::Mat next(vp.size, CV_8UC1, cv::Scalar(0));
    for (int row = 0; row < vp.size.height; ++row)
      for (int col = 0; col < vp.size.width; ++col)
        for (const auto& map : f.maps) {
          const Point y = vp.to_pixel((*map.inverse())(vp.pixel_centre(col, row)));
          const int c = static_cast<int>(std::floor(y.x)), q = static_cast<int>(std::floor(y.y));
          if (c >= 0 && q >= 0 && c < vp.size.width && q < vp.size.height && d.at<uchar>(q, c))
            next.at<uchar>(row, col) = 255;
        }
    if (cv::countNonZero(next != m) == 0) break;
    m = next;
  }
  return m;
}

// Starting buffers that differ: the full raster, a small disc, the left half, ...
std::vector<cv::Mat> varied_starts(cv::Size size, int count) {
  std::vector<cv::Mat> starts;
  for (int v = 0; v < count; ++v) {
    cv::Mat m(size, CV_8UC1, cv::Scalar(0));
    switch (v % 3) {
      case 0:
        m.setTo(255);
        break;
      case 1:
        cv::circle(m, {size.width / 3, size.height / 2}, size.width / 10, 255, -1);
        break;
      default:
        m.colRange(0, size.width / 2).setTo(255);
        break;
    }
    starts.push_back(m);
  }
  return starts;
}

TEST(buffers, one_ifs_gives_its_attractor_for_every_v) {
  SuperIfs s;
  s.ifs = {sierpinski_triangle()};
  const cv::Size size{192, 192};
  cv::Mat reference;
  for (int v_count : {1, 3, 7}) {
    Buffers k(s, size,
              {.count = v_count, .sampling = {.seed = static_cast<std::uint64_t>(v_count)}});
    if (reference.empty()) reference = reference_attractor(s.ifs[0], k.viewport(), k.dilation());
    k.set_masks(varied_starts(size, v_count));
    k.run(default_steps(s, size));
    for (std::size_t v = 0; v < k.count(); ++v)
      EXPECT_GE(iou(k.mask(v), reference), 0.99) << "V = " << v_count << ", buffer " << v;
    // Independent of the raster iteration: every chaos-game point lies in the set (nothing
    // eroded), and the set is the fattened attractor, not much more.
    RenderOptions chaos;
    chaos.sampling.view = k.viewport().view;
    const cv::Mat points = render_attractor(s.ifs[0], size, chaos);
    cv::Mat inside;
    cv::bitwise_and(points, k.mask(0), inside);
    EXPECT_GE(cv::countNonZero(inside), 0.999 * cv::countNonZero(points));
    cv::Mat near;
    cv::dilate(points, near, cv::Mat::ones(2 * k.dilation() + 3, 2 * k.dilation() + 3, CV_8U));
    EXPECT_EQ(cv::countNonZero(k.mask(0) & ~near), 0);
  }
}

// Marks f(centre of p) for every set pixel p of `previous`: the forward image f(K), an oracle
// independent of the inverse-mapping raster.
cv::Mat forward_image(const cv::Mat& previous, const AffineMap& f, const Viewport& vp) {
  cv::Mat out(previous.size(), CV_8UC1, cv::Scalar(0));
  for (int row = 0; row < previous.rows; ++row)
    for (int col = 0; col < previous.cols; ++col) {
      if (!previous.at<uchar>(row, col)) continue;
      const Point y = vp.to_pixel(f(vp.pixel_centre(col, row)));
      const int c = static_cast<int>(std::floor(y.x)), q = static_cast<int>(std::floor(y.y));
      if (c >= 0 && q >= 0 && c < out.cols && q < out.rows) out.at<uchar>(q, c) = 255;
    }
  return out;
}

double contained(const cv::Mat& part, const cv::Mat& whole) {
  cv::Mat both;
  cv::bitwise_and(part, whole, both);
  return static_cast<double>(cv::countNonZero(both)) / std::max(1, cv::countNonZero(part));
}

TEST(buffers, with_one_buffer_every_piece_is_an_image_of_the_previous_buffer) {
  const SuperIfs s = paper_fig4();
  const cv::Size size{256, 256};
  Buffers k(s, size, {.count = 1, .sampling = {.seed = 5}});
  k.run(6);
  for (int step = 0; step < 4; ++step) {
    const cv::Mat before = k.mask(0).clone();
    k.step();
    const std::uint32_t n = k.last_choices().ifs[0];
    cv::Mat pieces(size, CV_8UC1, cv::Scalar(0));
    for (std::size_t m = 0; m < 3; ++m) {
      // Piece m is f^n_m(K): all of its forward image is in the new buffer ...
      const cv::Mat piece = forward_image(before, s.ifs[n].maps[m], k.viewport());
      EXPECT_GE(contained(piece, k.mask(0)), 0.999) << "step " << step << " piece " << m;
      // ... and the other IFS's map would not do (the test can tell n apart).
      const cv::Mat wrong = forward_image(before, s.ifs[1 - n].maps[m], k.viewport());
      EXPECT_LT(contained(wrong, k.mask(0)), 0.9) << "step " << step << " piece " << m;
      pieces |= piece;
    }
    // ... and the buffer holds nothing but the pieces, up to the conservative lookup's margin.
    cv::Mat near;
    const int w = 2 * k.dilation() + 3;
    cv::dilate(pieces, near, cv::Mat::ones(w, w, CV_8U));
    EXPECT_EQ(cv::countNonZero(k.mask(0) & ~near), 0) << "step " << step;
  }
}

// The sub-shape of piece m of a buffer pulled back to the plane: a coarse grid over the view,
// cell set when a set pixel x of `mask` has f⁻¹(x) in the cell and inside the triangle (the
// pieces of the Sierpinski triangles meet only at corners, so other pieces do not leak in).
cv::Mat pulled_back(const cv::Mat& mask, const AffineMap& f, const Viewport& vp, int cells) {
  const AffineMap inverse = *f.inverse();
  cv::Mat grid(cells, cells, CV_8UC1, cv::Scalar(0));
  const double h = std::sqrt(3.0) / 2;
  for (int row = 0; row < mask.rows; ++row)
    for (int col = 0; col < mask.cols; ++col) {
      if (!mask.at<uchar>(row, col)) continue;
      const Point y = inverse(vp.pixel_centre(col, row));
      const double slack = 0.01;
      if (y.y < -slack || y.y > h * (1 - std::abs(2 * y.x - 1)) + slack) continue;
      const Point p = vp.to_pixel(y);
      const int c = static_cast<int>(p.x * cells / mask.cols);
      const int q = static_cast<int>(p.y * cells / mask.rows);
      if (c >= 0 && q >= 0 && c < cells && q < cells) grid.at<uchar>(q, c) = 255;
    }
  return grid;
}

// Whether two coarse shapes are within one cell of each other (Hausdorff distance ≤ 1 cell): the
// conservative raster fattens a piece by a pixel or two, a third of a cell at most.
bool same_shape(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat a1, b1;
  cv::dilate(a, a1, cv::Mat::ones(3, 3, CV_8U));
  cv::dilate(b, b1, cv::Mat::ones(3, 3, CV_8U));
  return cv::countNonZero(a & ~b1) == 0 && cv::countNonZero(b & ~a1) == 0;
}

TEST(buffers, at_most_v_distinct_sub_shapes_at_the_first_level) {
  const SuperIfs s = paper_fig4();
  const cv::Size size{384, 384};
  constexpr int v_count = 3, cells = 24;
  Buffers k(s, size, {.count = v_count, .sampling = {.seed = 11}});
  k.run(default_steps(s, size));
  std::vector<cv::Mat> before;
  for (std::size_t v = 0; v < k.count(); ++v)
    before.push_back(pulled_back(k.mask(v), AffineMap{}, k.viewport(), cells));
  k.step();
  std::vector<cv::Mat> distinct;
  for (std::size_t v = 0; v < k.count(); ++v) {
    const std::uint32_t n = k.last_choices().ifs[v];
    for (std::size_t m = 0; m < 3; ++m) {
      const cv::Mat shape = pulled_back(k.mask(v), s.ifs[n].maps[m], k.viewport(), cells);
      // The sub-shape is the source buffer the step chose for it ...
      const std::uint32_t source = k.last_choices().source[v * 3 + m];
      EXPECT_TRUE(same_shape(shape, before[source])) << "buffer " << v << " piece " << m;
      bool seen = false;
      for (const auto& d : distinct) seen = seen || same_shape(shape, d);
      if (!seen) distinct.push_back(shape);
    }
  }
  // ... so the V·M = 9 pieces show at most V shapes; and the buffers did differ.
  EXPECT_LE(distinct.size(), static_cast<std::size_t>(v_count));
  EXPECT_GE(distinct.size(), 2u);
}

TEST(buffers, burn_in_forgets_the_starting_buffers) {
  const SuperIfs s = paper_fig4();
  const cv::Size size{256, 256};
  Buffers full(s, size, {.count = 3, .sampling = {.seed = 21}});
  Buffers disc(s, size, {.count = 3, .sampling = {.seed = 21}});
  cv::Mat small(size, CV_8UC1, cv::Scalar(0));
  cv::circle(small, {100, 140}, 6, 255, -1);
  disc.set_masks({small, small, small});
  full.run(default_steps(s, size));
  disc.run(default_steps(s, size));
  for (std::size_t v = 0; v < 3; ++v) EXPECT_GE(iou(full.mask(v), disc.mask(v)), 0.99) << v;
}

TEST(buffers, thread_count_does_not_change_pixels) {
  const SuperIfs s = paper_fig4();
  const cv::Size size{200, 150};
  std::vector<std::vector<cv::Mat>> results;
  for (int threads : {1, 2, 3}) {
    Buffers k(s, size, {.count = 4, .sampling = {.seed = 9, .threads = threads}, .density = true});
    k.run(9);
    std::vector<cv::Mat> r;
    for (std::size_t v = 0; v < k.count(); ++v) r.push_back(k.mask(v)), r.push_back(k.density(v));
    results.push_back(r);
  }
  for (std::size_t t = 1; t < results.size(); ++t)
    for (std::size_t i = 0; i < results[0].size(); ++i)
      EXPECT_EQ(cv::norm(results[0][i], results[t][i], cv::NORM_INF), 0) << t << " " << i;
}

TEST(buffers, the_seed_decides_the_texture) {
  const SuperIfs s = paper_fig4();
  Buffers a(s, {128, 128}, {.count = 3, .sampling = {.seed = 1}});
  Buffers b(s, {128, 128}, {.count = 3, .sampling = {.seed = 2}});
  a.run(10);
  b.run(10);
  double worst = 1;
  for (std::size_t v = 0; v < 3; ++v) worst = std::min(worst, iou(a.mask(v), b.mask(v)));
  EXPECT_LT(worst, 0.95);
}

TEST(buffers, density_is_a_probability_on_the_set_with_the_self_similar_weights) {
  SuperIfs s;
  s.ifs = {sierpinski_triangle()};
  const cv::Size size{256, 256};
  Buffers k(s, size, {.count = 2, .sampling = {.seed = 3}, .density = true});
  k.run(default_steps(s, size));
  const cv::Mat& rho = k.density(0);
  EXPECT_NEAR(cv::sum(rho)[0], 1.0, 1e-4);
  // The support of μ is the set (same lookups, same reach).
  EXPECT_EQ(cv::countNonZero((rho > 0) != k.mask(0)), 0);
  // Equal map probabilities ⇒ μ(f_m(A)) = 1/3 for each corner piece, the points nearer to
  // corner m than to the others.
  double mass[3] = {0, 0, 0};
  for (int row = 0; row < size.height; ++row)
    for (int col = 0; col < size.width; ++col) {
      const Point p = k.viewport().pixel_centre(col, row);
      int nearest = 0;
      for (int m = 1; m < 3; ++m) {
        const Point a = triangle_corner(m), b = triangle_corner(nearest);
        if (std::hypot(p.x - a.x, p.y - a.y) < std::hypot(p.x - b.x, p.y - b.y)) nearest = m;
      }
      mass[nearest] += rho.at<float>(row, col);
    }
  for (int m = 0; m < 3; ++m) EXPECT_NEAR(mass[m], 1.0 / 3, 0.01) << "corner " << m;
}

// The palette coordinate carried with the measure: for the quadrant tiling (map m = i + 2j for
// the quadrant at column i, row j; c_m = m / 3), a point of address σ1σ2… has
// c = Σ c_σk / 2^k = (x + 2y) / 3, so each pixel's mean coordinate is that of its centre.
TEST(buffers, colour_mass_carries_the_palette_coordinate_of_the_addresses) {
  SuperIfs s;
  s.ifs = {testing::square_grid(2)};
  s.view = Box{0, 0, 1, 1};
  const cv::Size size{64, 64};
  Buffers k(s, size, {.count = 1, .sampling = {.seed = 4}, .density = true});
  k.run(16);
  const cv::Mat& rho = k.density(0);
  const cv::Mat& colour = k.colour_mass(0);
  double worst = 0;
  for (int row = 0; row < size.height; ++row)
    for (int col = 0; col < size.width; ++col) {
      ASSERT_GT(rho.at<float>(row, col), 0) << row << "," << col;
      const Point p = k.viewport().pixel_centre(col, row);
      const double c = colour.at<float>(row, col) / rho.at<float>(row, col);
      worst = std::max(worst, std::abs(c - (p.x + 2 * p.y) / 3));
    }
  EXPECT_LT(worst, 0.03);
  EXPECT_NEAR(cv::sum(colour)[0], 0.5, 0.01);  // the mean of (x + 2y) / 3 over the square
}

TEST(buffers, rejects_bad_arguments) {
  const SuperIfs s = paper_fig4();
  EXPECT_THROW(Buffers(s, {64, 64}, {.count = 0}), Error);
  EXPECT_THROW(Buffers(s, {0, 64}), Error);
  EXPECT_THROW(Buffers(s, {64, 64}, {.sampling = {.threads = -1}}), Error);
  Buffers k(s, {64, 64});
  EXPECT_THROW(k.set_masks({cv::Mat(64, 64, CV_8UC1)}), Error);  // V = 3 needs three
  k.step();
  try {
    k.set_masks(std::vector<cv::Mat>(3, cv::Mat(64, 64, CV_8UC1, cv::Scalar(255))));
    FAIL() << "set_masks after a step must throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
  }
}

}  // namespace
}  // namespace ifsfx
