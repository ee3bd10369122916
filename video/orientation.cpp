// SPDX-License-Identifier: Apache-2.0
#include "video/orientation.h"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

extern "C" {
#include <libavutil/display.h>
}

#include "ifs/error.h"

namespace ifsfx::video {

cv::Size Orientation::displayed(cv::Size coded) const {
  return transpose ? cv::Size(coded.height, coded.width) : coded;
}

cv::Mat Orientation::apply(const cv::Mat& coded) const {
  if (identity()) return coded;
  cv::Mat turned = coded;
  if (transpose) cv::transpose(coded, turned);
  // cv::flip codes: 1 mirrors left-right, 0 top-bottom, -1 both.
  if (flip_x && flip_y)
    cv::flip(turned, turned, -1);
  else if (flip_x)
    cv::flip(turned, turned, 1);
  else if (flip_y)
    cv::flip(turned, turned, 0);
  return turned;
}

std::string Orientation::describe() const {
  // The eight orientations as a user would name them.
  if (!transpose) {
    if (flip_x && flip_y) return "turned 180°";
    if (flip_x) return "mirrored left-right";
    if (flip_y) return "mirrored top-bottom";
    return "upright";
  }
  if (flip_x && !flip_y) return "turned 90° clockwise";
  if (flip_y && !flip_x) return "turned 90° counterclockwise";
  if (flip_x && flip_y) return "turned 90° clockwise and mirrored top-bottom";
  return "transposed";
}

Orientation orientation_from_matrix(const std::int32_t matrix[9], const std::string& what) {
  // Only the 2×2 part matters for the picture; the translation places it. A quarter-turn family
  // matrix has exactly one non-zero entry in each row: a, d (no transpose) or b, c (transpose).
  const double a = matrix[0], b = matrix[1], c = matrix[3], d = matrix[4];
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d)});
  if (scale == 0) return {};  // a degenerate matrix shows nothing: treat as absent
  const double eps = 1e-3 * scale;
  const bool straight = std::abs(b) < eps && std::abs(c) < eps;
  const bool quarter = std::abs(a) < eps && std::abs(d) < eps;
  if (!straight && !quarter)
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: the video is to be shown turned by {:.1f}° clockwise; only multiples "
                    "of 90° are supported",
                    what, -av_display_rotation_get(matrix)));
  Orientation o;
  o.transpose = quarter;
  // After the transpose the display x is c·y (or a·x), the display y is b·x (or d·y): a negative
  // factor mirrors that axis.
  o.flip_x = (quarter ? c : a) < 0;
  o.flip_y = (quarter ? b : d) < 0;
  return o;
}

Orientation orientation_from_rotate_tag(const std::string& degrees, const std::string& what) {
  char* end = nullptr;
  const long turn = std::strtol(degrees.c_str(), &end, 10);
  if (end == degrees.c_str() || *end != '\0' || turn % 90 != 0)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: rotate tag: only multiples of 90° are supported (got '{}')", what,
                            degrees));
  // The tag turns clockwise, as older FFmpeg reported a phone's portrait clip ("rotate=90" for
  // the `tkhd` matrix {0 1; −1 0}): a = cos t, b = sin t, c = −sin t, d = cos t.
  const long quarter = ((turn / 90) % 4 + 4) % 4;
  constexpr std::int32_t one = 1 << 16;
  const std::int32_t cos_t[4] = {one, 0, -one, 0};
  const std::int32_t sin_t[4] = {0, one, 0, -one};
  const std::int32_t matrix[9] = {
      cos_t[quarter], sin_t[quarter], 0, -sin_t[quarter], cos_t[quarter], 0, 0, 0, 1 << 30};
  return orientation_from_matrix(matrix, what);
}

}  // namespace ifsfx::video
