// SPDX-License-Identifier: Apache-2.0
// The ifsfx-obs filter inside a real libobs, headless (run by CTest under xvfb-run -a with Mesa's
// llvmpipe): its pictures are `ifsfx filter`'s, its settings change without a restart, a bad
// preset says why in the dialog and keeps the picture, and removing it while frames flow is safe.
// Usage: obs_filter_test MODULE DATA_DIR IFSFX WORK_DIR [gtest flags]
#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/obs/obs_harness.h"
#include "tests/obs/yuv_reference.h"

namespace ifsfx::obs_test {
namespace {

// The filter's settings as obs_data, and the same as `ifsfx filter` flags.
const char* const kFixed = R"({"preset": "maple-leaf", "mix": 0.25, "background": "#336699",
                               "seed": 3})";
const char* const kFixedFlags = "--preset maple-leaf --mix 0.25 --background '#336699' --seed 3";

struct Chain {
  explicit Chain(const char* json) {
    obs_data_t* settings = obs_data_create_from_json(json);
    chain = Obs::get().make_chain(settings);
    obs_data_release(settings);
  }
  ~Chain() { Obs::get().release(chain); }
  Obs::Chain chain;
};

bool same_picture(const Planes& shown, const cv::Mat& bgr) {
  cv::Mat picture;
  cv::cvtColor(shown.planes[0], picture, cv::COLOR_BGRA2BGR);
  return bgr.size() == picture.size() && cv::norm(picture, bgr, cv::NORM_INF) == 0;
}

// Shows `frame` `times` times from timestamp `index` on (`step` frames apart); the frames the
// probe saw then.
std::vector<Planes> show(obs_source_t* source, const Planes& frame, std::int64_t& index, int times,
                         int step = 1) {
  Capture& capture = Obs::get().capture();
  capture.clear();
  for (int i = 0; i < times; ++i, index += step) EXPECT_TRUE(Obs::get().show(source, frame, index));
  return capture.frames();
}

// How long a test waits for the filter's first picture: a 320x240 map takes a fraction of a
// second, but CI machines run other work (at load 16 here, seconds).
constexpr auto kPatience = std::chrono::seconds(20);

bool patient(std::chrono::steady_clock::time_point start) {
  return std::chrono::steady_clock::now() - start < kPatience;
}

// Shows `frame` until the probe sees `expected` (the filter has its maps).
bool show_until(obs_source_t* source, const Planes& frame, std::int64_t& index,
                const cv::Mat& expected, int step = 1) {
  for (const auto start = std::chrono::steady_clock::now(); patient(start);) {
    const std::vector<Planes> seen = show(source, frame, index, 1, step);
    if (!seen.empty() && same_picture(seen.back(), expected)) return true;
  }
  return false;
}

class obs_filter : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!Obs::get().ok()) GTEST_SKIP() << "libobs did not start";
  }
};

TEST_F(obs_filter, is_named_and_described_from_its_locale) {
  // The module's data folder is where OBS was told (plugins/obs/data, installed as
  // share/obs/obs-plugins/ifsfx-obs): its en-US.ini names the filter and its properties.
  EXPECT_STREQ(obs_source_get_display_name("ifsfx_fractal_filter"), "ifsfx fractal");
  obs_properties_t* props = obs_get_source_properties("ifsfx_fractal_filter");
  ASSERT_NE(props, nullptr);
  EXPECT_STREQ(obs_property_description(obs_properties_get(props, "mix")), "Mix with the original");
  obs_properties_destroy(props);
}

TEST_F(obs_filter, bgra_pictures_are_the_clis_bit_for_bit) {
  const std::vector<cv::Mat> frames = {test_frame(0), test_frame(1), test_frame(2)};
  const std::vector<cv::Mat> expected = cli_frames(frames, kFixedFlags, "fixed");
  Chain c(kFixed);
  std::int64_t index = 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    ASSERT_TRUE(show_until(c.chain.source, bgra_frame(frames[k]), index, expected[k])) << k;
    // Once there, every frame shows it (one frame late: the worker's picture of the frame before,
    // which is the same frame).
    for (const Planes& p : show(c.chain.source, bgra_frame(frames[k]), index, 5))
      EXPECT_TRUE(same_picture(p, expected[k])) << "frame " << k;
  }
}

TEST_F(obs_filter, drift_is_keyed_on_the_frame_timestamps) {
  constexpr int kFrames = 24;
  // One picture throughout, so that a picture names the time of its maps alone: a live source
  // whose next keyframe is late shows the newest ready one over the frame of now (the maps of an
  // earlier frame, engine/map_schedule.h "Live"), which `ifsfx filter` gives for no frame of a
  // changing sequence.
  const std::vector<cv::Mat> frames(kFrames, test_frame(0));
  const std::vector<cv::Mat> expected = cli_frames(
      frames, "--preset maple-leaf --animate drift --drift-amount 0.3 --drift-speed 1", "drift");
  Chain c(R"({"preset": "maple-leaf", "animate": "drift", "drift_amount": 0.3,
              "drift_speed": 1.0})");
  // The first frame again until the maps are ready, at timestamp 0: the animation's clock starts
  // at the first frame the filter sees.
  std::int64_t index = 0;
  ASSERT_TRUE(show_until(c.chain.source, bgra_frame(frames[0]), index, expected[0], 0));
  // Then frame i at timestamp i: each picture is the CLI's frame j for the newest j the worker
  // finished (or the keyframe before it, when the next one was late), never later than i and never
  // going back.
  int last = 0, distinct = 0;
  for (int i = 1; i < kFrames; ++i) {
    std::int64_t at = i;
    const std::vector<Planes> seen = show(c.chain.source, bgra_frame(frames[i]), at, 1);
    ASSERT_EQ(seen.size(), 1u);
    int j = i;
    while (j >= last && !same_picture(seen[0], expected[j])) --j;
    ASSERT_GE(j, last) << "frame " << i << " shows no CLI frame in [" << last << ", " << i << "]";
    distinct += j > last;
    last = j;
  }
  EXPECT_GE(distinct, kFrames / 3) << "most frames show their own picture";
}

TEST_F(obs_filter, changed_settings_apply_without_a_restart) {
  const cv::Mat frame = test_frame(4);
  const cv::Mat fern = cli_frames({frame}, "--preset barnsley-fern", "fern")[0];
  const cv::Mat maple = cli_frames({frame}, "--preset maple-leaf", "maple")[0];
  Chain c(R"({"preset": "barnsley-fern"})");
  std::int64_t index = 0;
  ASSERT_TRUE(show_until(c.chain.source, bgra_frame(frame), index, fern));
  // mix 1: the original frame over the fractal.
  obs_data_t* settings = obs_data_create_from_json(R"({"mix": 1.0})");
  obs_source_update(c.chain.filter, settings);
  obs_data_release(settings);
  EXPECT_TRUE(show_until(c.chain.source, bgra_frame(frame), index, frame));
  settings = obs_data_create_from_json(R"({"mix": 0.0, "preset": "maple-leaf"})");
  obs_source_update(c.chain.filter, settings);
  obs_data_release(settings);
  EXPECT_TRUE(show_until(c.chain.source, bgra_frame(frame), index, maple));
}

std::string status_line(obs_source_t* filter) {
  obs_properties_t* props = obs_source_properties(filter);
  obs_property_t* status = obs_properties_get(props, "status");
  std::string line = status && obs_property_visible(status) ? obs_property_description(status) : "";
  obs_properties_destroy(props);
  return line;
}

TEST_F(obs_filter, a_bad_preset_shows_its_error_and_keeps_the_picture) {
  const cv::Mat frame = test_frame(5);
  const cv::Mat expected = cli_frames({frame}, kFixedFlags, "bad_preset")[0];
  Chain c(kFixed);
  std::int64_t index = 0;
  ASSERT_TRUE(show_until(c.chain.source, bgra_frame(frame), index, expected));
  EXPECT_EQ(status_line(c.chain.filter), "");
  obs_data_t* settings = obs_data_create_from_json(R"({"preset": "no-such-preset"})");
  obs_source_update(c.chain.filter, settings);
  obs_data_release(settings);
  EXPECT_EQ(status_line(c.chain.filter), cli_error("--preset no-such-preset"));
  for (const Planes& p : show(c.chain.source, bgra_frame(frame), index, 10))
    EXPECT_TRUE(same_picture(p, expected));
  settings = obs_data_create_from_json(R"({"preset": "maple-leaf"})");
  obs_source_update(c.chain.filter, settings);
  obs_data_release(settings);
  EXPECT_EQ(status_line(c.chain.filter), "");
}

TEST_F(obs_filter, removing_the_filter_while_frames_flow_is_safe) {
  Chain c(kFixed);
  std::atomic<bool> stop = false;
  std::atomic<std::int64_t> seen = 0;  // frames the probe saw
  std::thread camera([&] {
    const Planes frame = bgra_frame(test_frame(6));
    for (std::int64_t i = 0; !stop; ++i) seen += Obs::get().show(c.chain.source, frame, i);
  });
  auto wait_for = [&](std::int64_t frames) {
    const auto start = std::chrono::steady_clock::now();
    while (seen < frames && patient(start))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return seen >= frames;
  };
  const bool flowing = wait_for(15);
  obs_source_filter_remove(c.chain.source, c.chain.filter);
  obs_source_release(c.chain.filter);
  c.chain.filter = nullptr;
  const bool went_on = wait_for(seen + 10);
  stop = true;
  camera.join();
  EXPECT_TRUE(flowing);
  EXPECT_TRUE(went_on) << "frames went on after the filter was removed";
  const std::vector<Planes> frames = Obs::get().capture().frames();
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(same_picture(frames.back(), test_frame(6))) << "unfiltered after removal";
}

TEST_F(obs_filter, nv12_pictures_are_the_clis_within_rounding) {
  const Planes nv12 = nv12_of(test_frame(7));
  // The CLI filters what the NV12 frame shows; the plugin's picture is that, coded back to NV12.
  const cv::Mat shown = bgr_of(nv12);
  const Planes expected = nv12_of(cli_frames({shown}, kFixedFlags, "nv12")[0]);
  Chain c(kFixed);
  std::int64_t index = 0;
  int worst = 255;
  for (const auto start = std::chrono::steady_clock::now(); worst > 2 && patient(start);) {
    const std::vector<Planes> seen = show(c.chain.source, nv12, index, 1);
    ASSERT_EQ(seen.size(), 1u);
    worst = std::max(cv::norm(seen[0].planes[0], expected.planes[0], cv::NORM_INF),
                     cv::norm(seen[0].planes[1], expected.planes[1], cv::NORM_INF));
  }
  EXPECT_LE(worst, 2) << "largest difference of a Y, U or V sample";
}

TEST_F(obs_filter, obs_draws_the_filtered_source) {
  const cv::Mat frame = test_frame(8);
  const cv::Mat expected = cli_frames({frame}, kFixedFlags, "screenshot")[0];
  Chain c(kFixed);
  std::int64_t index = 0;
  ASSERT_TRUE(show_until(c.chain.source, bgra_frame(frame), index, expected));
  show(c.chain.source, bgra_frame(frame), index, 10);  // through OBS's render and readback
  cv::Mat output;
  cv::cvtColor(Obs::get().output(), output, cv::COLOR_BGRA2BGR);
  ASSERT_EQ(output.size(), expected.size());
  cv::imwrite(paths().work + "/obs-screenshot.png", output);
  EXPECT_LE(cv::norm(output, expected, cv::NORM_INF), 2) << paths().work << "/obs-screenshot.png";
}

}  // namespace
}  // namespace ifsfx::obs_test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (argc != 5) {
    std::fprintf(stderr, "usage: obs_filter_test MODULE DATA_DIR IFSFX WORK_DIR [gtest flags]\n");
    return 2;
  }
  ifsfx::obs_test::paths() = {argv[1], argv[2], argv[3], argv[4]};
  std::filesystem::create_directories(argv[4]);
  const int result = RUN_ALL_TESTS();
  ifsfx::obs_test::Obs::get().shutdown();
  return result;
}
