// SPDX-License-Identifier: Apache-2.0
#include "video/pipeline.h"

#include <atomic>

#include <gtest/gtest.h>

#include "ifs/cancel.h"
#include "ifs/error.h"
#include "tests/video/test_frames.h"

namespace ifsfx::video {
namespace {

using testing::MemorySink;
using testing::MemorySource;

cv::Mat invert(const Frame& f) {
  cv::Mat out;
  cv::bitwise_not(f.image, out);
  return out;
}

TEST(pipeline, every_frame_is_filtered_in_order_and_the_sink_closed) {
  MemorySource source({16, 8}, 40);
  MemorySink sink;
  const PipelineResult result = run_pipeline(source, sink, invert, {.queue_depth = 2});
  EXPECT_EQ(result.frames_written, 40);
  EXPECT_FALSE(result.interrupted);
  ASSERT_EQ(sink.frames.size(), 40u);
  EXPECT_EQ(sink.closes, 1);
  for (std::int64_t i = 0; i < 40; ++i) {
    const Frame& f = sink.frames[static_cast<std::size_t>(i)];
    EXPECT_EQ(f.index, i);
    EXPECT_DOUBLE_EQ(f.timestamp, i / 25.0);
    cv::Mat expected;
    cv::bitwise_not(testing::test_frame({16, 8}, i), expected);
    EXPECT_EQ(cv::norm(f.image, expected, cv::NORM_INF), 0.0);
  }
}

TEST(pipeline, range_gives_exactly_its_frames_with_source_indices) {
  MemorySource source({16, 8}, 40);
  MemorySink sink;
  PipelineOptions o;
  o.range = parse_frame_range("10:20");
  const PipelineResult result = run_pipeline(source, sink, invert, o);
  ASSERT_EQ(result.frames_written, 11);
  ASSERT_EQ(sink.frames.size(), 11u);
  EXPECT_EQ(sink.frames.front().index, 10);
  EXPECT_EQ(sink.frames.back().index, 20);
  EXPECT_EQ(source.reads(), 21);  // stops reading after the range
}

// A stop request ends every stage at its next frame; the output, incomplete, is abandoned (an
// existing file is left as it was, the frames done kept apart).
TEST(pipeline, stop_flag_ends_promptly_and_abandons_the_output) {
  MemorySource source({16, 8}, 1000);
  MemorySink sink;
  std::atomic<bool> stop{false};
  std::atomic<int> filtered{0};
  PipelineOptions o;
  o.stop = &stop;
  const PipelineResult result = run_pipeline(
      source, sink,
      [&](const Frame& f) {
        if (++filtered == 25) stop = true;
        return invert(f);
      },
      o);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(filtered.load(), 25);  // no frame is filtered after the request
  EXPECT_LE(result.frames_written, 25);
  EXPECT_EQ(static_cast<std::int64_t>(sink.frames.size()), result.frames_written);
  EXPECT_EQ(sink.closes, 0);
  EXPECT_EQ(sink.abandons, 1);
  EXPECT_TRUE(result.partial.empty());
}

class FailingSource final : public FrameSource {
 public:
  std::optional<Frame> read() override {
    if (next_ == 7)
      throw Error(ErrorKind::io, "broken.avi: truncated or corrupt: decoded 7 of 20 frames");
    return Frame{testing::test_frame({8, 8}, next_), next_++, 0};
  }
  cv::Size size() const override { return {8, 8}; }
  double fps() const override { return 25; }
  std::string name() const override { return "broken.avi"; }

 private:
  std::int64_t next_ = 0;
};

TEST(pipeline, source_error_keeps_the_frames_before_it_apart_and_is_rethrown) {
  FailingSource source;
  MemorySink sink;
  sink.partial = "out.partial.mkv";
  try {
    run_pipeline(source, sink, invert);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_STREQ(e.what(),
                 "broken.avi: truncated or corrupt: decoded 7 of 20 frames; 7 frames kept in "
                 "out.partial.mkv");
  }
  EXPECT_EQ(sink.frames.size(), 7u);
  EXPECT_EQ(sink.closes, 0);
  EXPECT_EQ(sink.abandons, 1);
  // A sink that keeps nothing: the error as it came.
  FailingSource again;
  MemorySink nothing;
  try {
    run_pipeline(again, nothing, invert);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "broken.avi: truncated or corrupt: decoded 7 of 20 frames");
  }
}

// A stage that sees the stop request through a cancellation (an animation's map being built)
// was stopped, not failed.
TEST(pipeline, an_interrupted_stage_after_a_stop_request_is_a_stop) {
  MemorySource source({8, 8}, 1000);
  MemorySink sink;
  std::atomic<bool> stop{false};
  PipelineOptions o;
  o.stop = &stop;
  const auto filter = [&](const Frame& f) -> cv::Mat {
    if (f.index == 4) {
      stop = true;
      CancelToken(&stop).check("keyframe");
    }
    return f.image;
  };
  const PipelineResult result = run_pipeline(source, sink, filter, o);
  EXPECT_TRUE(result.interrupted);
  EXPECT_LE(result.frames_written, 4);
  EXPECT_EQ(sink.abandons, 1);
}

TEST(pipeline, filter_error_stops_every_stage) {
  MemorySource source({8, 8}, 100000);
  MemorySink sink;
  auto failing = [](const Frame& f) -> cv::Mat {
    if (f.index == 3) throw Error(ErrorKind::invalid_argument, "filter: bad frame");
    return f.image;
  };
  EXPECT_THROW(run_pipeline(source, sink, failing), Error);
  EXPECT_EQ(sink.frames.size(), 3u);
  EXPECT_LT(source.reads(), 100);
  EXPECT_EQ(sink.abandons, 1);
}

TEST(pipeline, progress_reports_end_with_the_total) {
  MemorySource source({8, 8}, 30);
  MemorySink sink;
  std::vector<Progress> reports;
  PipelineOptions o;
  o.progress = [&](const Progress& p) { reports.push_back(p); };
  o.progress_interval = 0;
  o.range = {5, -1};
  run_pipeline(source, sink, invert, o);
  ASSERT_FALSE(reports.empty());
  EXPECT_TRUE(reports.back().finished);
  EXPECT_EQ(reports.back().done, 25);
  EXPECT_EQ(reports.back().total, 25);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GE(reports[i].done, reports[i - 1].done);
}

TEST(pipeline, parse_frame_range_reads_both_ends) {
  EXPECT_EQ(parse_frame_range("10:20").first, 10);
  EXPECT_EQ(parse_frame_range("10:20").last, 20);
  EXPECT_EQ(parse_frame_range("5:").last, -1);
  EXPECT_EQ(parse_frame_range(":7").first, 0);
  EXPECT_TRUE(parse_frame_range("10:20").contains(20));
  EXPECT_FALSE(parse_frame_range("10:20").contains(21));
  try {
    parse_frame_range("20:10");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "frames: END must not be before START (got '20:10')");
  }
  EXPECT_THROW(parse_frame_range("10"), Error);
  EXPECT_THROW(parse_frame_range("a:b"), Error);
  EXPECT_THROW(parse_frame_range("-3:4"), Error);
}

}  // namespace
}  // namespace ifsfx::video
