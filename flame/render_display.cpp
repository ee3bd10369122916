// SPDX-License-Identifier: Apache-2.0
// Step 4 of flame/render_tone.h: the display of the log density (Draves & Reckase §4: gamma on
// the density, not per channel; vibrancy; flam3 3's highlight power).
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "flame/render_tone.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::flame {
namespace {

// α^g, made linear below `threshold` so that faint densities are not lifted by the steep start
// of the power curve: the line through 0 with the curve's value at the threshold, blended into
// the curve as α rises to it.
double gamma_curve(double a, double g, double threshold) {
  if (!(a > 0)) return 0;
  if (a >= threshold) return std::pow(a, g);
  const double frac = a / threshold;
  return (1 - frac) * a * std::pow(threshold, g) / threshold + frac * std::pow(a, g);
}

using Rgb3 = std::array<double, 3>;

Rgb3 to_hsv(const Rgb3& c) {
  const double mx = std::max({c[0], c[1], c[2]}), mn = std::min({c[0], c[1], c[2]});
  const double d = mx - mn;
  double h = 0;
  if (d > 0) {
    if (mx == c[0])
      h = (c[1] - c[2]) / d;
    else if (mx == c[1])
      h = 2 + (c[2] - c[0]) / d;
    else
      h = 4 + (c[0] - c[1]) / d;
    if (h < 0) h += 6;
  }
  return {h, mx > 0 ? d / mx : 0, mx};
}

Rgb3 from_hsv(const Rgb3& hsv) {
  const double h = hsv[0], s = hsv[1], v = hsv[2];
  const int i = static_cast<int>(std::floor(h)) % 6;
  const double f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (i) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

// The colour c (channels in density units) scaled by ls onto the display's 0…256. A channel
// past 255 is clipped later; with highlight_power ≥ 0 the colour is instead scaled so its
// largest channel is 255 and desaturated by (that scale / ls)^power, keeping its hue.
Rgb3 highlight(const Rgb3& c, double ls, double power) {
  const double maxc = std::max({c[0], c[1], c[2]});
  if (ls == 0 || !(maxc > 0)) return {0, 0, 0};
  const double maxa = ls * maxc, newls = 255 / maxc;
  if (maxa > 255 && power >= 0) {
    Rgb3 hsv = to_hsv({c[0] * newls / 255, c[1] * newls / 255, c[2] * newls / 255});
    hsv[1] *= std::pow(newls / ls, power);
    const Rgb3 rgb = from_hsv(hsv);
    return {rgb[0] * 255, rgb[1] * 255, rgb[2] * 255};
  }
  // −1 < power < 0 blends the clipping scale with the plain one; −1 and below: plain.
  const double adj = maxa <= 255 ? 1 : std::min(1.0, -power);
  const double k = (1 - adj) * newls + adj * ls;
  return {k * c[0], k * c[1], k * c[2]};
}

}  // namespace

DisplayPixel display_pixel(const double* rgba, const ToneMapping& tone) {
  const double a = rgba[3];
  if (!(a > 0)) return {};
  const double g = 1 / tone.gamma;
  const double alpha = gamma_curve(a, g, tone.gamma_threshold);
  const double ls = tone.vibrancy * 256 * alpha / a;
  Rgb3 c = highlight({rgba[0], rgba[1], rgba[2]}, ls, tone.highlight_power);
  // Full vibrancy (the usual 1) adds 0·(…): skipping the three pow calls keeps the bits.
  if (tone.vibrancy == 1) return {c[0], c[1], c[2], std::clamp(alpha, 0.0, 1.0)};
  for (int k = 0; k < 3; ++k)
    c[static_cast<std::size_t>(k)] +=
        (1 - tone.vibrancy) * 256 * std::pow(std::max(rgba[k], 0.0), g);
  return {c[0], c[1], c[2], std::clamp(alpha, 0.0, 1.0)};
}

cv::Mat display(const FlameHistogram& pixels, const ToneMapping& tone, int channels, int depth,
                int threads) {
  if (channels != 3 && channels != 4)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("channels: 3 (BGR) or 4 (BGRA) are needed (got {})", channels));
  if (depth != CV_8U && depth != CV_16U && depth != CV_32F)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("depth: CV_8U, CV_16U or CV_32F is needed (got {})", depth));
  cv::Mat out(pixels.height, pixels.width, CV_MAKETYPE(depth, channels));
  const Rgba& bg = tone.background;
  parallel_rows(pixels.height, 32, threads, [&](cv::Range rows) {
    for (int i = rows.start; i < rows.end; ++i)
      for (int j = 0; j < pixels.width; ++j) {
        const DisplayPixel p = display_pixel(pixels.at(i, j), tone);
        // On the display's 0…255 scale, the background behind what is not covered: opaque in a
        // picture without alpha; with alpha, the flame over the background's own alpha, its
        // colour straight (divided by the alpha, as flam3 writes a transparent picture), so
        // that a viewer compositing the file does not darken the flame's edges twice.
        const double under = 1 - p.alpha;
        const double cover = channels == 4 ? p.alpha + under * bg.a : 1;
        const double behind = channels == 4 ? under * bg.a : under;
        const double straight = cover > 0 ? 1 / cover : 0;
        const double v[4] = {std::clamp((p.b + behind * 255 * bg.b) * straight, 0.0, 255.0),
                             std::clamp((p.g + behind * 255 * bg.g) * straight, 0.0, 255.0),
                             std::clamp((p.r + behind * 255 * bg.r) * straight, 0.0, 255.0),
                             255 * cover};
        for (int k = 0; k < channels; ++k) {
          if (depth == CV_8U)  // truncated, as flam3 writes its 8-bit pictures
            out.ptr<std::uint8_t>(i)[j * channels + k] = static_cast<std::uint8_t>(v[k]);
          else if (depth == CV_16U)
            out.ptr<std::uint16_t>(i)[j * channels + k] =
                cv::saturate_cast<std::uint16_t>(v[k] * 65535 / 255);
          else
            out.ptr<float>(i)[j * channels + k] = static_cast<float>(v[k] / 255);
        }
      }
  });
  return out;
}

}  // namespace ifsfx::flame
