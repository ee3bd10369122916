// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/picture_maker.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"

namespace ifsfx::obs {
namespace {

const cv::Size kSize(96, 64);

PluginSettings tops(const std::string& background, double mix) {
  PropertyValues v;
  v.preset = "maple-leaf";
  v.mode = "tops";
  v.background = background;
  v.mix = mix;
  return settings_of(v);
}

cv::Mat frame() {
  cv::Mat bgr(kSize, CV_8UC3);
  cv::RNG(5).fill(bgr, cv::RNG::UNIFORM, 0, 256);
  return bgr;
}

// `ifsfx render --mode tops` of the preset, the background where the attractor is not.
cv::Mat render_tops_of(const Rgb& background) {
  cv::Mat bytes;
  tops_picture(load_ifs("maple-leaf").ifs, kSize, {}, background, false)
      .convertTo(bytes, CV_8U, 255);
  return bytes;
}

TEST(picture_maker, tops_is_the_tops_picture_over_the_background) {
  PictureMaker maker(tops("#336699", 0), kSize, 30);
  cv::Mat out;
  maker.make(frame(), 0, out);
  EXPECT_EQ(cv::norm(out, render_tops_of({0x33 / 255.0, 0x66 / 255.0, 0x99 / 255.0}), cv::NORM_INF),
            0);
}

TEST(picture_maker, tops_with_mix_one_is_the_frame_and_keeps_its_fourth_channel) {
  PictureMaker maker(tops("black", 1), kSize, 30);
  cv::Mat bgra, out;
  cv::cvtColor(frame(), bgra, cv::COLOR_BGR2BGRA);
  bgra.col(3).setTo(cv::Scalar(1, 2, 3, 77));
  maker.make(bgra, 0, out);
  EXPECT_EQ(cv::norm(out, bgra, cv::NORM_INF), 0);
}

TEST(picture_maker, tops_refuses_an_animation) {
  PropertyValues v;
  v.mode = "tops";
  v.animate = "drift";
  EXPECT_THROW(settings_of(v), Error);
}

}  // namespace
}  // namespace ifsfx::obs
