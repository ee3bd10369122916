// SPDX-License-Identifier: Apache-2.0
#include "ifs/tops.h"

#include <cmath>

#include <fmt/format.h>

#include "ifs/detail/address_raster.h"
#include "ifs/detail/preconditions.h"
#include "ifs/error.h"
#include "ifs/render.h"

namespace ifsfx {

TopSymbols top_symbols(const Ifs& F, cv::Size size, const TopsOptions& options) {
  detail::check_chaos_game(
      {.ifs = F, .contracting = true, .size = size, .sampling = &options.sampling});
  const Viewport viewport = framed_viewport(F, size, options.sampling);
  detail::ChaosTopsStats chaos;
  const detail::AddressRaster tops =
      options.exact ? detail::exact_descent(F, nullptr, viewport,
                                            {.levels = 2,
                                             .seed = options.sampling.seed,
                                             .threads = options.sampling.threads,
                                             .cancel = options.sampling.cancel},
                                            &chaos)
                          .tops
                    : detail::chaos_tops(F, viewport,
                                         {.quality = options.sampling.quality,
                                          .seed = options.sampling.seed,
                                          .threads = options.sampling.threads,
                                          .key_bits = 32,  // 32/b ≥ 2 symbols for any N ≤ 65536
                                          .cancel = options.sampling.cancel},
                                         &chaos);
  TopSymbols out;
  out.view = viewport.view;
  out.points = chaos.points;
  out.first = cv::Mat(size, CV_16UC1, cv::Scalar::all(0));
  out.second = cv::Mat(size, CV_16UC1, cv::Scalar::all(0));
  out.coverage = cv::Mat(size, CV_8UC1, cv::Scalar::all(0));
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const std::uint64_t key = tops.at(c, r);
      if (key == 0) continue;
      out.first.at<std::uint16_t>(r, c) = static_cast<std::uint16_t>(tops.symbol(key, 0));
      out.second.at<std::uint16_t>(r, c) = static_cast<std::uint16_t>(tops.symbol(key, 1));
      out.coverage.at<std::uint8_t>(r, c) = 255;
    }
  return out;
}

cv::Mat render_tops(const Ifs& F, cv::Size size, const TopsOptions& options,
                    std::uint64_t* points) {
  const TopSymbols tops = top_symbols(F, size, options);
  if (points) *points = tops.points;
  std::vector<cv::Vec4f> palette(F.size());
  for (std::size_t n = 0; n < F.size(); ++n) {
    const Rgb c = F.colours.empty() ? palette_colour(n, F.size()) : F.colours[n];
    palette[n] =
        cv::Vec4f(static_cast<float>(c.b), static_cast<float>(c.g), static_cast<float>(c.r), 1.0f);
  }
  cv::Mat out(size, CV_32FC4, cv::Scalar::all(0));
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      if (!tops.coverage.at<std::uint8_t>(r, c)) continue;
      const cv::Vec4f& first = palette[tops.first.at<std::uint16_t>(r, c)];
      out.at<cv::Vec4f>(r, c) =
          options.second_symbol
              ? (2.0f * first + palette[tops.second.at<std::uint16_t>(r, c)]) / 3.0f
              : first;
    }
  return out;
}

}  // namespace ifsfx
