// SPDX-License-Identifier: Apache-2.0
// Textures: the identity oracle of the steal map through a superIFS, agreement with the IFS core's
// exact steal map, determinism, sequences and crossfades.
#include "superifs/texture.h"

#include <atomic>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/rng.h"
#include "interrupted.h"
#include "same_bytes.h"
#include "superifs/superifs_file.h"
#include "superifs_fixtures.h"

namespace ifsfx {
namespace {

using testing::iou;
using testing::paper_fig4;
using testing::sierpinski_triangle;
using testing::square_grid;

// Noise: every pixel differs from its neighbours, so any misplaced coordinate shows.
cv::Mat noise_image(cv::Size size, std::uint64_t seed) {
  cv::Mat m(size, CV_8UC3);
  Rng rng(seed);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      for (int k = 0; k < 3; ++k) m.at<cv::Vec3b>(r, c)[k] = static_cast<uchar>(rng.below(256));
  return m;
}

// The quadrant tiling with its maps in another order and turned: still a tiling of the square.
Ifs turned_quadrants() {
  return {"turned",
          {{0, -0.5, 0.5, 0, 0.5, 0},
           {-0.5, 0, 0, -0.5, 1, 0.5},
           {0, 0.5, -0.5, 0, 0, 1},
           {0.5, 0, 0, 0.5, 0.5, 0.5}},
          {},
          {}};
}

void expect_identity(const SuperIfs& s, cv::Size size) {
  Buffers k(s, size, {.count = 3, .sampling = {.seed = 4}, .history = 10});
  k.run(12);
  const StealMap map = steal_map(k, 1);
  ASSERT_EQ(cv::countNonZero(map.coverage), size.area());
  double worst = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const cv::Vec2f uv = map.source_uv.at<cv::Vec2f>(r, c);
      worst = std::max({worst, std::abs(uv[0] * size.width - (c + 0.5)),
                        std::abs(uv[1] * size.height - (r + 0.5))});
    }
  EXPECT_LT(worst, 1e-3) << "pixels";
  const cv::Mat source = noise_image(size, 7);
  EXPECT_EQ(cv::norm(apply(map, source), source, cv::NORM_INF), 0);
}

TEST(texture, identity_superifs_returns_the_source) {
  // Every IFS a tiling of the square and the colouring the same tiling for each n ⇒ T(x) = x.
  SuperIfs s;
  s.ifs = {square_grid(2), turned_quadrants()};
  s.colouring = s.ifs;
  s.view = Box{0, 0, 1, 1};
  expect_identity(s, {160, 120});
}

TEST(texture, identity_superifs_with_the_default_colouring_returns_the_source) {
  SuperIfs s;
  s.ifs = {default_colouring(4), default_colouring(4)};
  s.view = Box{0, 0, 1, 1};
  expect_identity(s, {128, 128});
}

TEST(texture, a_turned_tiling_does_not_return_the_source) {
  // The oracle can fail: colour through the plain tiling what the turned one drew.
  SuperIfs s;
  s.ifs = {turned_quadrants()};
  s.colouring = {square_grid(2)};
  s.view = Box{0, 0, 1, 1};
  Buffers k(s, {64, 64}, {.count = 1, .history = 8});
  k.run(8);
  const cv::Mat source = noise_image({64, 64}, 7);
  EXPECT_GT(cv::norm(apply(steal_map(k, 0), source), source, cv::NORM_INF), 100);
}

// T(x) for an IFS whose attractor is the whole unit square, in plain double arithmetic: the top
// map at each level is the highest m with f_m⁻¹(x) in the square (no raster at all).
Point reference_steal(const Ifs& f, const Ifs& g, Point x) {
  std::vector<std::size_t> word;
  for (int level = 0; level < 40; ++level) {
    for (std::size_t m = f.size(); m-- > 0;) {
      const Point y = (*f.maps[m].inverse())(x);
      if (y.x >= -1e-12 && y.y >= -1e-12 && y.x <= 1 + 1e-12 && y.y <= 1 + 1e-12) {
        word.push_back(m);
        x = y;
        break;
      }
    }
  }
  for (std::size_t i = word.size(); i-- > 0;) x = g.maps[word[i]](x);
  return x;
}

TEST(texture, one_ifs_one_buffer_steals_like_exact_arithmetic) {
  // N = 1, V = 1 is the ordinary IFS. The turned quadrants fill the square and are coloured by
  // the plain tiling, so T is far from the identity and known without any raster.
  SuperIfs s;
  s.ifs = {turned_quadrants()};
  s.view = Box{0, 0, 1, 1};
  const cv::Size size{96, 80};
  // 30 levels: the starting buffer's coordinates (the identity) matter less than 2^-30.
  Buffers k(s, size, {.count = 1, .history = 30});
  k.run(30);
  const StealMap mine = steal_map(k, 0);
  EXPECT_EQ(cv::countNonZero(mine.coverage), size.area());
  const Ifs g = colouring_ifs(s, 0);
  double far = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const Point t =
          reference_steal(s.ifs[0], g, {(c + 0.5) / size.width, 1 - (r + 0.5) / size.height});
      const cv::Vec2f uv = mine.source_uv.at<cv::Vec2f>(r, c);
      far = std::max({far, std::abs(uv[0] - t.x), std::abs(uv[1] - (1 - t.y))});
    }
  EXPECT_LT(far, 1e-5);
}

// Every texture mode, superIFSs of M = 3 to 8 maps, several sizes and seeds: 1, 2, 3 and 5 threads
// give the same bytes.
TEST(texture, every_mode_gives_the_same_bytes_for_any_thread_count) {
  struct Case {
    const char* preset;
    cv::Size size;
    std::uint64_t seed;
  };
  const Case cases[] = {{"paper-fig4", {150, 130}, 8},       // M = 3
                        {"quadrant-shuffle", {97, 131}, 3},  // M = 4
                        {"vicsek-weave", {128, 96}, 5},      // M = 5
                        {"carpet-lace", {120, 120}, 2}};     // M = 8
  const cv::Mat source = noise_image({90, 70}, 3);
  for (const Case& c : cases) {
    const SuperIfs s = load_superifs(c.preset).super;
    for (TextureMode mode :
         {TextureMode::attractor, TextureMode::tops, TextureMode::steal, TextureMode::measure}) {
      TextureOptions o{
          .sampling = {.seed = c.seed, .threads = 1}, .count = 3, .mode = mode, .source = source};
      const cv::Mat one = render_texture(s, c.size, o);
      ASSERT_FALSE(one.empty());
      for (int threads : {2, 3, 5}) {
        o.sampling.threads = threads;
        EXPECT_TRUE(testing::same_bytes(one, render_texture(s, c.size, o)))
            << c.preset << " in mode " << to_string(mode) << ": 1 thread vs " << threads;
      }
    }
  }
}

TEST(texture, modes_cover_the_set_and_only_the_set) {
  const SuperIfs s = paper_fig4();
  const cv::Size size{128, 128};
  const TextureOptions base{.sampling = {.seed = 2}, .count = 3};
  const cv::Mat set = render_texture(s, size, base);
  ASSERT_EQ(set.type(), CV_8UC1);
  for (auto mode : {TextureMode::tops, TextureMode::measure, TextureMode::steal}) {
    TextureOptions o = base;
    o.mode = mode;
    o.source = cv::Mat(40, 40, CV_8UC3, cv::Scalar(10, 200, 30));
    const cv::Mat image = render_texture(s, size, o);
    cv::Mat on(size, CV_8UC1, cv::Scalar(0));  // a pixel with any channel not 0
    for (int c = 0; c < image.channels(); ++c) {
      cv::Mat channel;
      cv::extractChannel(image, channel, c);
      on |= channel != 0;
    }
    EXPECT_EQ(cv::countNonZero(on != set), 0) << to_string(mode);
  }
}

TEST(texture, every_step_of_a_sequence_is_a_new_texture) {
  const SuperIfs s = paper_fig4();
  TextureSequence seq(s, {128, 128},
                      {.sampling = {.seed = 5}, .count = 3, .mode = TextureMode::tops});
  EXPECT_EQ(seq.burn_in(), default_steps(s, {128, 128}));
  std::vector<cv::Mat> masks;
  for (int i = 0; i < 6; ++i) masks.push_back(seq.next_map().coverage);
  EXPECT_EQ(seq.steps_done(), seq.burn_in() + 6);
  for (std::size_t i = 1; i < masks.size(); ++i)
    EXPECT_GT(cv::countNonZero(masks[i] != masks[i - 1]), 0) << i;
}

TEST(texture, map_at_is_a_function_of_the_step) {
  const SuperIfs s = paper_fig4();
  const TextureOptions o{.sampling = {.seed = 6}, .count = 3, .mode = TextureMode::steal};
  TextureSequence a(s, {64, 64}, o), b(s, {64, 64}, o);
  const StealMap a1 = a.map_at(1), a3 = a.map_at(3);
  const StealMap a2 = a.map_at(2);  // stepped past, but kept
  b.step();
  const StealMap b1 = b.steal_map();
  b.step();
  const StealMap b2 = b.steal_map();
  EXPECT_EQ(cv::norm(a1.source_uv, b1.source_uv, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a2.source_uv, b2.source_uv, cv::NORM_INF), 0);
  EXPECT_GT(cv::countNonZero(a2.coverage != a3.coverage), 0);
  for (int k = 4; k < 12; ++k) a.map_at(k);
  // Step 1 is long gone: made again from the burn-in, the same map.
  EXPECT_EQ(cv::norm(a.map_at(1).source_uv, b1.source_uv, cv::NORM_INF), 0);
  EXPECT_THROW(a.map_at(-1), Error);
}

TEST(texture, frames_asked_for_in_reverse_order_are_the_frames_in_order) {
  const SuperIfs s = paper_fig4();
  const TextureOptions o{.sampling = {.seed = 4}, .count = 2, .mode = TextureMode::tops};
  TextureSequence forward(s, {48, 48}, o), backward(s, {48, 48}, o);
  std::vector<cv::Mat> frames;
  for (int j = 0; j < 14; ++j) frames.push_back(forward.frame_at(position_of_frame(j, 2)).clone());
  for (int j = 13; j >= 0; --j)
    EXPECT_EQ(cv::norm(backward.frame_at(position_of_frame(j, 2)), frames[j], cv::NORM_INF), 0)
        << "frame " << j;
  // Frame 1 is halfway between textures 0 and 1.
  EXPECT_EQ(cv::norm(frames[1], crossfade(frames[0], frames[2], 0.5), cv::NORM_INF), 0);
}

TEST(texture, crossfade_blends_linearly) {
  const cv::Mat a(4, 4, CV_8UC3, cv::Scalar(0, 100, 200)), b(4, 4, CV_8UC3, cv::Scalar(200, 0, 0));
  EXPECT_EQ(cv::norm(crossfade(a, b, 0), a, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(crossfade(a, b, 1), b, cv::NORM_INF), 0);
  EXPECT_EQ(crossfade(a, b, 0.25).at<cv::Vec3b>(2, 1), cv::Vec3b(50, 75, 150));
  EXPECT_THROW(crossfade(a, cv::Mat(4, 5, CV_8UC3), 0.5), Error);
  EXPECT_THROW(crossfade(a, b, 1.5), Error);
}

TEST(texture, rejects_bad_options_with_the_option_named) {
  const SuperIfs s = paper_fig4();
  const auto kind_and_text = [&](const TextureOptions& o, const std::string& text) {
    try {
      render_texture(s, {32, 32}, o);
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  kind_and_text({.count = 2, .buffer = 2}, "buffer: must be 0..1 for count = 2 (got 2)");
  kind_and_text({.mode = TextureMode::steal}, "source: steal mode needs a source image");
  kind_and_text({.count = 0}, "count: the number of buffers must be ≥ 1 (got 0)");
  try {
    parse_texture_mode("stealing");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_STREQ(e.what(), "mode: must be attractor, tops, steal or measure (got 'stealing')");
  }
  EXPECT_EQ(parse_texture_mode("measure"), TextureMode::measure);
}

}  // namespace
}  // namespace ifsfx

namespace ifsfx {
namespace {

using testing::interrupted;

// A stop request ends the burn-in, a step and the descent with Error{interrupted} (issue 12).
TEST(texture, a_stop_request_ends_the_burn_in_the_steps_and_the_descent) {
  std::atomic<bool> stop{true};
  EXPECT_TRUE(interrupted([&] {
    TextureSequence(paper_fig4(), {64, 64},
                    {.sampling = {.cancel = CancelToken(&stop)}, .steps = 4});
  }));
  stop = false;
  TextureSequence seq(
      paper_fig4(), {64, 64},
      {.sampling = {.cancel = CancelToken(&stop)}, .steps = 4, .mode = TextureMode::steal});
  stop = true;
  EXPECT_TRUE(interrupted([&] { seq.step(); }));
  EXPECT_TRUE(interrupted([&] { seq.steal_map(); }));
}

// Textures sample as every other picture: the same defaults, and a view given in the options
// wins over the superIFS's own (and over the framing of one that has none).
TEST(texture, sampling_defaults_and_the_view) {
  EXPECT_EQ(TextureOptions{}.sampling, Sampling{});
  EXPECT_EQ(BufferOptions{}.sampling, Sampling{});
  SuperIfs s;
  s.ifs = {testing::square_grid(2)};
  const cv::Size size{32, 32};
  EXPECT_EQ(buffer_view(s, size), fit_view(attractor_bounds(union_ifs(s)), size, 0.05));
  s.view = Box{0, 0, 1, 1};
  EXPECT_EQ(buffer_view(s, size), (Box{0, 0, 1, 1}));
  EXPECT_EQ(buffer_view(s, size, {.view = Box{0, 0, 2, 2}}), (Box{0, 0, 2, 2}));
  const Buffers k(s, size, {.count = 1, .sampling = {.view = Box{0, 0, 2, 2}}});
  EXPECT_EQ(k.viewport().view, (Box{0, 0, 2, 2}));
  EXPECT_THROW(Buffers(s, size, {.sampling = {.view = Box{1, 0, 0, 1}}}), Error);
}

}  // namespace
}  // namespace ifsfx
