// SPDX-License-Identifier: Apache-2.0
#include "ifs/chaos_game.h"

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/render.h"
#include "ifs/rng.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

TEST(chaos_game, fern_invariant_measure_has_the_known_mean) {
  const auto samples = chaos_game_samples(testing::barnsley_fern(), 4'000'000, {.seed = 7});
  double sx = 0, sy = 0;
  for (const auto& s : samples) sx += s.p.x, sy += s.p.y;
  EXPECT_NEAR(sx / samples.size(), 0.7968, 0.01);
  EXPECT_NEAR(sy / samples.size(), 6.1676, 0.01);
}

TEST(chaos_game, points_fall_in_each_piece_with_its_probability) {
  // Right Sierpinski: the pieces f_n(A) are the three quadrants it touches, so where a point lies
  // tells which map put it there, independently of the sampler's own bookkeeping.
  Ifs ifs = testing::right_sierpinski();
  ifs.probabilities = {0.2, 0.3, 0.5};
  const auto samples = chaos_game_samples(ifs, 1'000'000, {.seed = 3});
  std::array<double, 3> share{};
  for (const auto& s : samples) {
    const int piece = s.p.x >= 0.5 ? 1 : s.p.y >= 0.5 ? 2 : 0;
    share[piece] += 1.0 / samples.size();
  }
  EXPECT_NEAR(share[0], 0.2, 0.005);
  EXPECT_NEAR(share[1], 0.3, 0.005);
  EXPECT_NEAR(share[2], 0.5, 0.005);
}

TEST(chaos_game, thread_count_does_not_change_the_samples) {
  const auto one =
      chaos_game_samples(testing::barnsley_fern(), 9'000'000, {.seed = 5, .threads = 1});
  const auto four =
      chaos_game_samples(testing::barnsley_fern(), 9'000'000, {.seed = 5, .threads = 4});
  ASSERT_EQ(one.size(), four.size());
  for (std::size_t i = 0; i < one.size(); i += 997) {
    ASSERT_EQ(one[i].p, four[i].p) << "sample " << i;
    ASSERT_EQ(one[i].map, four[i].map);
  }
}

TEST(chaos_game, burn_in_brings_points_onto_the_attractor) {
  // Contraction 1/2: 1e-9 needs 30 steps, but never fewer than 64.
  EXPECT_EQ(default_burn_in(testing::right_sierpinski()), 64);
  Ifs slow = testing::right_sierpinski();
  for (auto& m : slow.maps) m.a = m.d = 0.9;
  EXPECT_EQ(default_burn_in(slow), 197);  // ceil(log 1e-9 / log 0.9)
}

// wyrand's stream from seed 1: the state advanced by 0xa0761d6478bd642f, each draw the high
// and low halves of state · (state ^ 0xe7037ed1a0b428db) xor-ed (the values from Python's exact
// integers). Every picture's bytes depend on these bits.
TEST(rng, draws_wyrands_stream) {
  Rng rng(1);
  EXPECT_EQ(rng.next(), 0xcdef1695e1f8ed2cULL);
  EXPECT_EQ(rng.next(), 0x61d6d24b1c9aad40ULL);
  EXPECT_EQ(rng.next(), 0x8cf880c22eebfadfULL);
}

TEST(map_picker, draws_maps_with_their_probabilities) {
  const MapPicker pick({0.1, 0.2, 0.0, 0.7});
  Rng rng(11);
  std::array<int, 4> hits{};
  constexpr int kDraws = 2'000'000;
  const MapPicker::View view = pick.view();
  for (int i = 0; i < kDraws; ++i) {
    const std::uint64_t r = rng.next();
    const std::uint32_t map = pick(r);
    ++hits[map];
    if (view.branch_free(r) != map) ADD_FAILURE() << "branch_free differs at draw " << i;
  }
  EXPECT_NEAR(hits[0] / double(kDraws), 0.1, 0.002);
  EXPECT_NEAR(hits[1] / double(kDraws), 0.2, 0.002);
  EXPECT_EQ(hits[2], 0);
  EXPECT_NEAR(hits[3] / double(kDraws), 0.7, 0.002);
}

TEST(rng, streams_of_one_seed_differ_and_repeat) {
  Rng a(stream_seed(1, 0)), b(stream_seed(1, 1)), a2(stream_seed(1, 0));
  int equal = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next();
    equal += x == b.next();
    ASSERT_EQ(x, a2.next());
  }
  EXPECT_EQ(equal, 0);
}

// Every chaos-game entry point checks its inputs first, with one helper: a probability vector of
// the wrong length (which would make the map picker read past its table), a NaN coefficient, a
// negative thread count — each refused with the same message naming the library's parameter.
TEST(chaos_game, every_entry_point_refuses_what_the_walk_cannot_run) {
  Ifs short_p = testing::barnsley_fern();
  short_p.probabilities.pop_back();
  Ifs nan = testing::right_sierpinski();
  nan.maps[1].e = std::nan("");
  const Ifs fern = testing::barnsley_fern();
  const Viewport view{{0, 0, 1, 1}, {16, 16}};
  using Call = std::function<void(const Ifs&, int threads)>;
  const std::pair<const char*, Call> calls[] = {
      {"chaos_game_samples",
       [](const Ifs& f, int t) { chaos_game_samples(f, 100, {.threads = t}); }},
      {"visit_counts", [&](const Ifs& f, int t) { visit_counts(f, view, 100, {.threads = t}); }},
      {"render_attractor",
       [](const Ifs& f, int t) {
         render_attractor(f, {16, 16}, {.sampling = {.quality = 1, .threads = t}});
       }},
      {"render_measure",
       [](const Ifs& f, int t) {
         render_measure(f, {16, 16}, {.sampling = {.quality = 1, .threads = t}});
       }},
      {"top_symbols",
       [](const Ifs& f, int t) {
         top_symbols(f, {16, 16}, {.sampling = {.quality = 1, .threads = t}, .exact = false});
       }},
      {"compute_steal_map",
       [](const Ifs& f, int t) {
         compute_steal_map(f, default_colouring(f.size()), {16, 16},
                           {.sampling = {.quality = 1, .threads = t}, .exact = false});
       }},
  };
  const auto message = [](const Call& call, const Ifs& f, int threads) -> std::string {
    try {
      call(f, threads);
    } catch (const Error& e) {
      return std::string(to_string(e.kind())) + ": " + e.what();
    }
    return "accepted";
  };
  for (const auto& [name, call] : calls) {
    EXPECT_EQ(message(call, short_p, 0),
              "invalid IFS: barnsley-fern: probabilities: one per map is needed (got 3 for 4 maps)")
        << name;
    EXPECT_EQ(message(call, nan, 0),
              "invalid IFS: right-sierpinski: map 2: coefficients must be finite numbers (got NaN "
              "or inf)")
        << name;
    EXPECT_EQ(message(call, fern, -1),
              "invalid argument: threads: must be 0 (all cores) to 256 (got -1)")
        << name;
  }
  EXPECT_THROW(chaos_game_samples(fern, 100, {.burn_in = -3}), Error);
  EXPECT_THROW(render_measure(fern, {16, 16}, {.sampling = {.quality = 0}}), Error);
  EXPECT_THROW(attractor_bounds(Ifs{}), Error);  // would read maps[0]
}

}  // namespace
}  // namespace ifsfx
