// SPDX-License-Identifier: Apache-2.0
#include "studio/video.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "engine/drift.h"
#include "engine/fractal_filter.h"
#include "ifs/error.h"
#include "ifs/output_file.h"
#include "run/arguments.h"
#include "run/fractal_filter_options.h"
#include "studio/fields.h"
#include "studio/http.h"
#include "studio/render.h"

namespace ifsfx::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::string encode_jpeg(const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, 90}))
    throw Error(ErrorKind::io, "preview: cannot encode the frame as JPEG");
  return {bytes.begin(), bytes.end()};
}

// The frame's size scaled to body["width"] (default 640) at most, the aspect kept.
cv::Size preview_size(const json& body, const cv::Mat& frame) {
  const int width = static_cast<int>(integer_field(body, "width", 640, 16, 1920));
  if (frame.cols <= width) return frame.size();
  return {width, std::max(1, static_cast<int>(std::lround(1.0 * frame.rows * width / frame.cols)))};
}

// The settings of `ifsfx filter` (run/fractal_filter_options.h) that the page sets, and what
// tells one look from another (the texts of the presets and the view).
struct FilterSettings {
  engine::FractalSettings engine;
  double mix = 0;
  engine::Background background;
  std::string preset_text, colouring_text, view_text;
};

FilterSettings filter_settings(const json& body) {
  FilterSettings out;
  engine::FractalSettings& s = out.engine;
  s.drawing = drawing_from_json(body, &out.preset_text);
  // The editor's colouring IFS G, when it sends one (steal mode), fitted as `--colouring` is.
  const std::optional<IfsPreset> colouring =
      colouring_preset(body, engine::name_of(s.drawing) + "-colouring");
  s.colouring = colouring_for_drawing(body, s.drawing);  // the count checked
  s.exact = bool_field(body, "exact", true);
  refuse_named_exact(s.drawing, s.exact, body.contains("exact"), "exact");  // as the job does
  out.view_text = text_field(body, "view", "");
  s.sampling.view = view_option(out.view_text, "view");
  s.animate = choice_field(body, "animate", "none", {"none", "drift"}) == "drift"
                  ? engine::Animate::drift
                  : engine::Animate::none;
  s.drift_amount = number_field(body, "drift_amount", s.drift_amount, 0, engine::kMaxDriftAmount);
  s.drift_speed = number_field(body, "drift_speed", s.drift_speed, 0, engine::kMaxDriftSpeed);
  s.keyframe_interval = static_cast<int>(integer_field(
      body, "keyframe_interval", s.keyframe_interval, 1, engine::kMaxKeyframeInterval));
  s.sampling.seed = static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  out.mix = number_field(body, "mix", 0, 0, 1);
  out.background = engine::parse_background(text_field(body, "background", "black"), "background");
  if (colouring) out.colouring_text = colouring->text;
  return out;
}

}  // namespace

json MovieFrames::info(const fs::path& movie, const std::string& name) {
  video::FileSource source(movie, {.threads = 1});
  const std::int64_t frames = source.count_frames();
  const cv::Size size = source.size();
  return {{"movie", name},
          {"frames", frames},
          {"fps", source.frame_rate().value()},
          {"width", size.width},
          {"height", size.height}};
}

cv::Mat MovieFrames::frame(const std::string& client, const fs::path& movie, std::int64_t index,
                           double& fps) {
  const auto beyond = [&] {
    return Error(ErrorKind::invalid_argument, fmt::format("frame: beyond the end of {} (got {})",
                                                          movie.filename().string(), index));
  };
  // Reading on costs a frame's decoding per frame skipped; a seek costs about a keyframe
  // interval's, which most movies keep under a few dozen frames.
  constexpr std::int64_t kReadOn = 48;
  std::shared_ptr<Cursor> cursor;
  {
    std::lock_guard lock(mutex_);
    cursor = cursors_.take(client);
    if (cursor &&
        !(cursor->movie == movie && index >= cursor->next && index - cursor->next <= kReadOn))
      cursor.reset();
  }
  if (!cursor) {
    cursor = std::make_shared<Cursor>();
    cursor->movie = movie;
    cursor->source = std::make_unique<video::FileSource>(movie, video::FileSourceOptions{});
    if (!cursor->source->seek(index)) throw beyond();
    cursor->next = index;
  }
  for (; cursor->next < index; ++cursor->next)
    if (!cursor->source->skip()) throw beyond();
  std::optional<video::Frame> frame = cursor->source->read();
  if (!frame) throw beyond();
  cursor->next = index + 1;
  fps = cursor->source->frame_rate().value();
  std::lock_guard lock(mutex_);
  cursors_.put(client, std::move(cursor));  // a tab forgotten to make room closes its movie
  return std::move(frame->image);
}

std::string FilterPreviews::jpeg(const std::string& channel, const json& body, const cv::Mat& frame,
                                 std::int64_t index, double seconds, double fps) {
  const cv::Size size = preview_size(body, frame);
  if (!bool_field(body, "filter", true)) {
    cv::Mat scaled;
    cv::resize(frame, scaled, size, 0, 0, cv::INTER_AREA);
    return encode_jpeg(scaled);
  }
  FilterSettings s = filter_settings(body);
  const engine::FractalSettings& e = s.engine;
  const std::string key = json{channel,         s.preset_text, s.colouring_text,
                               e.exact,         s.view_text,   static_cast<int>(e.animate),
                               e.drift_amount,  e.drift_speed, e.keyframe_interval,
                               e.sampling.seed, frame.cols,    frame.rows,
                               size.width,      size.height,   fps}
                              .dump();
  const std::shared_ptr<Entry> entry = this->entry(channel, key);
  std::lock_guard use(entry->use);
  if (!entry->engine) {
    s.engine.sampling.cancel = CancelToken(&entry->stop);
    auto engine = std::make_unique<engine::FractalEngine>(s.engine);
    engine->prepare(frame.size(), size, fps > 0 ? fps : 25);
    entry->engine = std::move(engine);
  }
  entry->engine->set_look(s.mix, s.background);
  cv::Mat out;
  if (seconds >= 0)
    entry->engine->filter_at(frame, seconds, out);
  else
    entry->engine->filter(frame, index, out);
  return encode_jpeg(out);
}

std::shared_ptr<FilterPreviews::Entry> FilterPreviews::entry(const std::string& channel,
                                                             const std::string& key) {
  std::lock_guard lock(mutex_);
  if (stopping_) throw Error(ErrorKind::interrupted, "preview: the server is stopping");
  return entry_for(entries_, channel, key);
}

void FilterPreviews::stop_all() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  entries_.for_each([](Entry& entry) { entry.stop = true; });
}

cv::Mat CameraFeed::frame(double& seconds) {
  std::lock_guard lock(mutex_);
  try {
    if (!camera_) camera_ = std::make_unique<video::V4l2Capture>(device_);
    std::optional<video::Frame> frame = camera_->read();
    if (!frame)
      throw Error(ErrorKind::device, fmt::format("{}: the camera stopped sending", device_));
    seconds = frame->timestamp;
    return std::move(frame->image);
  } catch (const Error& e) {
    camera_.reset();
    throw RequestError(503,
                       fmt::format("camera: {} (the studio keeps running: check the camera and "
                                   "try again)",
                                   e.what()));
  }
}

void CameraFeed::close() {
  std::lock_guard lock(mutex_);
  camera_.reset();
}

}  // namespace ifsfx::app
