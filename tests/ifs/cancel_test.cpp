// SPDX-License-Identifier: Apache-2.0
// Cooperative cancellation (ifs/cancel.h, issue 12): every long computation of the library
// honours a stop request with Error{interrupted}.
#include "ifs/cancel.h"

#include <atomic>

#include <gtest/gtest.h>

#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "ifs/view.h"
#include "interrupted.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

using testing::interrupted;

// A stop request is honoured by every long computation of the library: here the flag is set
// before the call, so that the test proves the polling without timing anything.
TEST(cancel, every_long_computation_stops_with_interrupted) {
  std::atomic<bool> stop{true};
  const CancelToken cancel(&stop);
  const Ifs fern = testing::barnsley_fern();
  EXPECT_TRUE(interrupted([&] {
    render_measure(fern, {64, 64}, {.sampling = {.cancel = cancel}});
  }));
  EXPECT_TRUE(interrupted([&] {
    render_attractor(fern, {64, 64}, {.sampling = {.cancel = cancel}});
  }));
  EXPECT_TRUE(interrupted([&] {
    top_symbols(fern, {64, 64}, {.sampling = {.cancel = cancel}, .exact = false});
  }));
  EXPECT_TRUE(interrupted([&] {
    top_symbols(fern, {64, 64}, {.sampling = {.cancel = cancel}, .exact = true});
  }));
  EXPECT_TRUE(interrupted([&] {
    compute_steal_map(fern, default_colouring(4), {64, 64},
                      {.sampling = {.cancel = cancel}, .exact = false});
  }));
  EXPECT_TRUE(interrupted([&] {
    compute_steal_map(fern, default_colouring(4), {64, 64},
                      {.sampling = {.cancel = cancel}, .exact = true});
  }));
  EXPECT_TRUE(interrupted([&] { attractor_bounds(fern, 1, cancel); }));
  EXPECT_TRUE(interrupted([&] { chaos_game_samples(fern, 1000, {.cancel = cancel}); }));
  stop = false;  // the same calls run to the end without a request
  EXPECT_NO_THROW(top_symbols(fern, {64, 64}, {.sampling = {.cancel = cancel}, .exact = true}));
}

}  // namespace
}  // namespace ifsfx
