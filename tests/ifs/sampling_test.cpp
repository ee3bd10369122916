// SPDX-License-Identifier: Apache-2.0
// One sampling struct for every picture: the options types hold it with the same defaults, and
// framed_viewport frames as the renderers do (docs/design.md §7).
#include "ifs/sampling.h"

#include <gtest/gtest.h>

#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

TEST(sampling, every_options_type_starts_from_the_same_defaults) {
  const Sampling s;
  EXPECT_FALSE(s.view.has_value());
  EXPECT_EQ(s.margin, 0.05);
  EXPECT_EQ(s.quality, 64);
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.threads, 0);
  EXPECT_FALSE(s.cancel.requested());
  EXPECT_EQ(RenderOptions{}.sampling, s);
  EXPECT_EQ(TopsOptions{}.sampling, s);
  EXPECT_EQ(StealMapOptions{}.sampling, s);
  // The commands' default is the exact descent; the library's is the same.
  EXPECT_TRUE(TopsOptions{}.exact);
  EXPECT_TRUE(StealMapOptions{}.exact);
}

TEST(sampling, framed_viewport_is_the_view_or_the_attractor_with_its_margin) {
  const Ifs fern = testing::barnsley_fern();
  const cv::Size size{300, 200};
  const Viewport given = framed_viewport(fern, size, {.view = Box{-1, -2, 3, 4}});
  EXPECT_EQ(given.view, (Box{-1, -2, 3, 4}));
  EXPECT_EQ(given.size, size);
  for (const double margin : {0.0, 0.05, 0.5}) {
    const Sampling s{.margin = margin, .seed = 3};
    EXPECT_EQ(framed_viewport(fern, size, s).view,
              fit_view(attractor_bounds(fern, 3), size, margin))
        << margin;
  }
  // What render reports as shown is this framing.
  RenderStats stats;
  render_attractor(fern, size, {.sampling = {.quality = 1, .seed = 3}}, &stats);
  EXPECT_EQ(stats.view, framed_viewport(fern, size, {.seed = 3}).view);
}

}  // namespace
}  // namespace ifsfx
