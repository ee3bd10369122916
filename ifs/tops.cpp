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
  TopSymbols out = detail::symbols_of(tops);
  out.points = chaos.points;
  return out;
}

namespace detail {

TopSymbols symbols_of(const AddressRaster& tops) {
  const cv::Size size = tops.viewport.size;
  TopSymbols out;
  out.view = tops.viewport.view;
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

}  // namespace detail

std::vector<Rgb> map_colours(const Ifs& F) {
  if (!F.colours.empty()) return F.colours;
  std::vector<Rgb> out;
  for (std::size_t n = 0; n < F.size(); ++n) out.push_back(palette_colour(n, F.size()));
  return out;
}

cv::Mat render_tops(const Ifs& F, cv::Size size, const TopsOptions& options,
                    std::uint64_t* points) {
  const TopSymbols tops = top_symbols(F, size, options);
  if (points) *points = tops.points;
  return render_tops(tops, map_colours(F), options.second_symbol);
}

cv::Mat render_tops(const TopSymbols& tops, const std::vector<Rgb>& colours, bool second_symbol) {
  std::vector<cv::Vec4f> palette;
  for (const Rgb& c : colours)
    palette.emplace_back(static_cast<float>(c.b), static_cast<float>(c.g), static_cast<float>(c.r),
                         1.0f);
  const cv::Size size = tops.coverage.size();
  cv::Mat out(size, CV_32FC4, cv::Scalar::all(0));
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      if (!tops.coverage.at<std::uint8_t>(r, c)) continue;
      const cv::Vec4f& first = palette.at(tops.first.at<std::uint16_t>(r, c));
      out.at<cv::Vec4f>(r, c) =
          second_symbol ? (2.0f * first + palette.at(tops.second.at<std::uint16_t>(r, c))) / 3.0f
                        : first;
    }
  return out;
}

}  // namespace ifsfx
