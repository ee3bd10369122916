// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/filter_worker.h"

#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx::obs {
namespace {

const cv::Size kSize(64, 48);

cv::Mat test_picture() {
  cv::Mat bgra(kSize, CV_8UC4);
  cv::RNG(3).fill(bgra, cv::RNG::UNIFORM, 0, 256);
  return bgra;
}

// Exchanges copies of `picture` at 30 fps timestamps until one comes back filtered (at most 10 s).
Shown exchange_until_filtered(FilterWorker& worker, const cv::Mat& picture, cv::Mat& out,
                              std::uint64_t& timestamp, bool flip = false) {
  for (int i = 0; i < 1000; ++i) {
    out = picture.clone();
    FrameData f{.format = PixelFormat::bgra,
                .size = kSize,
                .flip = flip,
                .timestamp = timestamp,
                .planes = {out}};
    timestamp += 1'000'000'000 / 30;
    const Shown shown = worker.exchange(f);
    if (shown.written) return shown;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return {};
}

PluginSettings preset(const std::string& name) {
  PropertyValues v;
  v.preset = name;
  return settings_of(v);
}

TEST(filter_worker, pictures_are_the_engines) {
  FilterWorker worker(30);
  worker.configure(preset("maple-leaf"));
  const cv::Mat picture = test_picture();
  cv::Mat out;
  std::uint64_t t = 0;
  ASSERT_TRUE(exchange_until_filtered(worker, picture, out, t).written);
  engine::FractalEngine engine(preset("maple-leaf").engine, kSize, kSize, 30);
  EXPECT_EQ(cv::norm(out, engine.filter(picture, 0), cv::NORM_INF), 0);
  EXPECT_GE(worker.stats().passed, 1) << "frames before the maps were ready pass unchanged";
}

TEST(filter_worker, a_frame_stored_upside_down_is_filtered_upright) {
  FilterWorker worker(30);
  worker.configure(preset("maple-leaf"));
  const cv::Mat upright = test_picture();
  cv::Mat stored, out;
  cv::flip(upright, stored, 0);
  std::uint64_t t = 0;
  ASSERT_TRUE(exchange_until_filtered(worker, stored, out, t, true).written);
  engine::FractalEngine engine(preset("maple-leaf").engine, kSize, kSize, 30);
  cv::Mat expected;
  cv::flip(engine.filter(upright, 0), expected, 0);  // stored as the frame is
  EXPECT_EQ(cv::norm(out, expected, cv::NORM_INF), 0);
}

TEST(filter_worker, rejected_settings_keep_the_last_good_picture) {
  FilterWorker worker(30);
  worker.configure(preset("maple-leaf"));
  const cv::Mat picture = test_picture();
  cv::Mat first, later;
  std::uint64_t t = 0;
  ASSERT_TRUE(exchange_until_filtered(worker, picture, first, t).written);
  worker.reject("preset: no such preset");
  EXPECT_EQ(worker.status(), "preset: no such preset");
  ASSERT_TRUE(exchange_until_filtered(worker, picture, later, t).written);
  EXPECT_EQ(cv::norm(first, later, cv::NORM_INF), 0);
}

TEST(filter_worker, a_preset_that_fails_to_build_says_why) {
  FilterWorker worker(30);
  // Settings the worker cannot build (the colouring IFS must have as many maps as F), given to it
  // although check_settings, OBS's update's check, refuses them too.
  PluginSettings s = preset("sierpinski-triangle");
  s.engine.colouring = load_ifs("barnsley-fern").ifs;
  EXPECT_THROW(check_settings(s), Error) << "checked at once, in OBS's update";
  worker.configure(s);
  const cv::Mat picture = test_picture();
  cv::Mat out;
  std::uint64_t t = 0;
  for (int i = 0; i < 300 && worker.status().empty(); ++i) {
    out = picture.clone();
    FrameData f{.format = PixelFormat::bgra, .size = kSize, .timestamp = t++, .planes = {out}};
    EXPECT_FALSE(worker.exchange(f).written);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_NE(worker.status(), "");
}

TEST(settings, the_filter_is_a_live_source) {
  // The plugin's frames never wait for a drift keyframe (engine/map_schedule.h, "Live").
  PropertyValues v;
  v.animate = "drift";
  EXPECT_TRUE(settings_of(v).engine.live);
}

TEST(settings, a_loop_needs_an_animation) {
  PropertyValues v;
  v.loop = 48;
  EXPECT_THROW(settings_of(v), Error);
  v.animate = "drift";
  EXPECT_EQ(settings_of(v).engine.loop, 48);
}

TEST(settings, a_preset_file_replaces_the_preset) {
  const std::string file = ::testing::TempDir() + "obs_settings_square.toml";
  std::ofstream(file) << "name = \"square\"\nmaps = [[0.5, 0, 0, 0.5, 0, 0], "
                         "[0.5, 0, 0, 0.5, 0.5, 0.5]]\n";
  PropertyValues v;
  v.preset_file = file;
  EXPECT_EQ(engine::map_count(settings_of(v).engine.drawing), 2u);
  v.preset_file = "/no/such/preset.toml";
  EXPECT_THROW(settings_of(v), Error);
  v.preset_file = file;
  v.view = "0,0,1";
  EXPECT_THROW(settings_of(v), Error);
}

}  // namespace
}  // namespace ifsfx::obs
