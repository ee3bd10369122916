// SPDX-License-Identifier: Apache-2.0
// Loops of textures (docs/design.md §12): with periodic choices the buffers close, so texture N is
// texture 0 — stepping on from texture N − 1, not by definition — in every mode, and the last step
// of the loop is one V-variable step like the others.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/rng.h"
#include "same_bytes.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "superifs_fixtures.h"

namespace ifsfx {
namespace {

using testing::paper_fig4;

cv::Mat noise_image(cv::Size size, std::uint64_t seed) {
  cv::Mat m(size, CV_8UC3);
  Rng rng(seed);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      for (int k = 0; k < 3; ++k) m.at<cv::Vec3b>(r, c)[k] = static_cast<uchar>(rng.below(256));
  return m;
}

double mean_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / d.channels();
}

struct LoopCase {
  const char* preset;
  TextureMode mode;
};

class texture_loop : public ::testing::TestWithParam<LoopCase> {};

TEST_P(texture_loop, stepping_on_from_the_last_texture_gives_the_first_exactly) {
  const LoopCase c = GetParam();
  const SuperIfs super = load_superifs(c.preset).super;
  const cv::Size size{96, 80};
  const std::int64_t n = 6;
  TextureSequence seq(
      super, size,
      {.sampling = {.seed = 11}, .mode = c.mode, .source = noise_image({64, 64}, 3), .loop = n});
  ASSERT_TRUE(seq.loop_closed());
  std::vector<cv::Mat> frames;
  for (std::int64_t k = 0; k < n; ++k) frames.push_back(seq.frame_at(k).clone());
  // Texture N − 1, then one more V-variable step of the buffers: texture 0 again.
  (void)seq.frame_at(n - 1);
  seq.step();
  const cv::Mat after = seq.frame();
  EXPECT_TRUE(testing::same_bytes(after, frames[0]));
  // ... and on around the loop once more.
  for (std::int64_t k = 1; k < n; ++k) {
    seq.step();
    EXPECT_TRUE(testing::same_bytes(seq.frame(), frames[static_cast<std::size_t>(k)])) << k;
  }
  // Textures are asked for by number too: k + N is k.
  EXPECT_TRUE(testing::same_bytes(seq.frame_at(n + 2), frames[2]));
  EXPECT_TRUE(testing::same_bytes(seq.frame_at(5 * n), frames[0]));
  // The last step, N − 1 → 0, changes the picture about as much as the others. It is one
  // V-variable step like them (above), so its size is one more draw from theirs: with five others
  // it may fall a little outside their range (paper-fig4's attractor: 48 against 11..40 levels).
  double smallest = 1e9, largest = 0;
  for (std::int64_t k = 0; k + 1 < n; ++k) {
    const double d = mean_difference(frames[static_cast<std::size_t>(k)],
                                     frames[static_cast<std::size_t>(k + 1)]);
    smallest = std::min(smallest, d);
    largest = std::max(largest, d);
  }
  const double wrap = mean_difference(frames[static_cast<std::size_t>(n - 1)], frames[0]);
  EXPECT_GT(smallest, 0) << "every step is a new texture";
  EXPECT_GE(wrap, 0.5 * smallest) << smallest << ".." << largest;
  EXPECT_LE(wrap, 1.5 * largest) << smallest << ".." << largest;
}

INSTANTIATE_TEST_SUITE_P(every_mode, texture_loop,
                         ::testing::Values(LoopCase{"paper-fig4", TextureMode::attractor},
                                           LoopCase{"carpet-lace", TextureMode::attractor},
                                           LoopCase{"paper-fig4", TextureMode::tops},
                                           LoopCase{"vicsek-weave", TextureMode::tops},
                                           LoopCase{"paper-fig4", TextureMode::steal},
                                           LoopCase{"carpet-lace", TextureMode::steal}),
                         [](const auto& param_info) {
                           std::string name = std::string(param_info.param.preset) + "_" +
                                              to_string(param_info.param.mode);
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

TEST(texture_loop_measure, the_measure_comes_back_to_within_its_rounding) {
  const SuperIfs super = load_superifs("carpet-lace").super;
  const std::int64_t n = 4;
  TextureSequence seq(super, {96, 96},
                      {.sampling = {.seed = 2}, .mode = TextureMode::measure, .loop = n});
  ASSERT_TRUE(seq.loop_closed());
  const cv::Mat first = seq.frame_at(0).clone();
  (void)seq.frame_at(n - 1);
  seq.step();
  cv::Mat d;
  cv::absdiff(seq.frame(), first, d);
  double worst = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &worst);
  EXPECT_LE(worst, 1);  // a float's last bits, below 8-bit resolution but for a rounding
  EXPECT_TRUE(testing::same_bytes(seq.frame_at(n), first));  // by number: the same texture
}

TEST(texture_loop_choices, a_periodic_stream_repeats_its_choices) {
  Buffers k(paper_fig4(), {32, 32}, {.count = 3, .sampling = {.seed = 5}, .period = 3});
  std::vector<StepChoices> seen;
  for (int i = 0; i < 7; ++i) {
    k.step();
    seen.push_back(k.last_choices());
  }
  for (int i = 3; i < 7; ++i) {
    EXPECT_EQ(seen[static_cast<std::size_t>(i)].ifs, seen[static_cast<std::size_t>(i - 3)].ifs);
    EXPECT_EQ(seen[static_cast<std::size_t>(i)].source,
              seen[static_cast<std::size_t>(i - 3)].source);
  }
  EXPECT_NE(seen[0].source, seen[1].source);
}

TEST(texture_loop_choices, a_loop_does_not_depend_on_the_thread_count) {
  const SuperIfs super = load_superifs("carpet-lace").super;
  std::vector<cv::Mat> frames;
  for (int threads : {1, 2, 3}) {
    TextureSequence seq(
        super, {80, 64},
        {.sampling = {.seed = 4, .threads = threads}, .mode = TextureMode::tops, .loop = 5});
    frames.push_back(seq.frame_at(3).clone());
  }
  EXPECT_TRUE(testing::same_bytes(frames[0], frames[1]));
  EXPECT_TRUE(testing::same_bytes(frames[0], frames[2]));
}

TEST(texture_loop_choices, a_bad_loop_is_refused_with_the_option_named) {
  try {
    TextureSequence seq(paper_fig4(), {32, 32}, {.loop = -1});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "loop: must be 0..1000000 textures, 0 for none (got -1)");
  }
}

}  // namespace
}  // namespace ifsfx
