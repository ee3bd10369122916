// SPDX-License-Identifier: Apache-2.0
// The frame size a movie's encoder takes, shared by the movie filter and texture movies: 4:2:0
// encoders (H.264 in yuv420p, MPEG-4, VP9) need even sides, so an odd side is made one pixel
// smaller and the caller's `note` is told why, in one line.
#pragma once

#include <functional>
#include <string>

#include <opencv2/core.hpp>

namespace ifsfx::app {

cv::Size encodable_movie_size(const std::string& output, const std::string& codec, cv::Size size,
                              const std::function<void(const std::string&)>& note);

}  // namespace ifsfx::app
