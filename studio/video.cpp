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
#include "studio/fields.h"
#include "studio/http.h"
#include "studio/render.h"

namespace ifsfx::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Forgets the entry of `map` used longest ago while there are more than `most`.
template <class Map>
void forget_oldest(Map& map, std::size_t most) {
  while (map.size() > most) {
    auto oldest = map.begin();
    for (auto it = map.begin(); it != map.end(); ++it)
      if (it->second->used < oldest->second->used) oldest = it;
    map.erase(oldest);
  }
}

std::string encode_jpeg(const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, 90}))
    throw Error(ErrorKind::io, "preview: cannot encode the frame as JPEG");
  return {bytes.begin(), bytes.end()};
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
  std::unique_ptr<Cursor> cursor;
  {
    std::lock_guard lock(mutex_);
    if (auto it = cursors_.find(client); it != cursors_.end()) {
      Cursor& c = *it->second;
      if (c.movie == movie && index >= c.next && index - c.next <= kReadOn)
        cursor = std::move(it->second);
      cursors_.erase(it);
    }
  }
  if (!cursor) {
    cursor = std::make_unique<Cursor>();
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
  cursor->used = ++clock_;
  cursors_[client] = std::move(cursor);
  forget_oldest(cursors_, kMaxTabs);
  return std::move(frame->image);
}

std::string FilterPreviews::jpeg(const std::string& channel, const json& body, const cv::Mat& frame,
                                 std::int64_t index, double seconds, double fps) {
  const int width = static_cast<int>(integer_field(body, "width", 640, 16, 1920));
  cv::Size size = frame.size();
  if (size.width > width)
    size = {width,
            std::max(1, static_cast<int>(std::lround(1.0 * frame.rows * width / frame.cols)))};
  if (!bool_field(body, "filter", true)) {
    cv::Mat scaled;
    cv::resize(frame, scaled, size, 0, 0, cv::INTER_AREA);
    return encode_jpeg(scaled);
  }
  // The settings of `ifsfx filter` (run/fractal_filter_options.h) that the page sets.
  const IfsPreset preset = preset_from_json(body);
  // The editor's colouring IFS G, when it sends one (steal mode), fitted as `--colouring` is.
  const std::optional<IfsPreset> colouring = colouring_preset(body, preset.ifs.name + "-colouring");
  engine::FractalSettings s;
  s.drawing = preset.ifs;
  s.colouring = colouring_from_json(body, preset.ifs);  // the count checked
  s.exact = bool_field(body, "exact", true);
  s.sampling.view = view_option(text_field(body, "view", ""), "view");
  s.animate = choice_field(body, "animate", "none", {"none", "drift"}) == "drift"
                  ? engine::Animate::drift
                  : engine::Animate::none;
  s.drift_amount = number_field(body, "drift_amount", s.drift_amount, 0, engine::kMaxDriftAmount);
  s.drift_speed = number_field(body, "drift_speed", s.drift_speed, 0, engine::kMaxDriftSpeed);
  s.keyframe_interval = static_cast<int>(integer_field(
      body, "keyframe_interval", s.keyframe_interval, 1, engine::kMaxKeyframeInterval));
  s.sampling.seed = static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  const double mix = number_field(body, "mix", 0, 0, 1);
  const engine::Background background =
      engine::parse_background(text_field(body, "background", "black"), "background");
  const std::string key = json{channel,
                               preset.text,
                               colouring ? colouring->text : std::string(),
                               s.exact,
                               text_field(body, "view", ""),
                               static_cast<int>(s.animate),
                               s.drift_amount,
                               s.drift_speed,
                               s.keyframe_interval,
                               s.sampling.seed,
                               frame.cols,
                               frame.rows,
                               size.width,
                               size.height,
                               fps}
                              .dump();

  std::shared_ptr<Entry> entry;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) throw Error(ErrorKind::interrupted, "preview: the server is stopping");
    auto& slot = entries_[channel];
    if (!slot || slot->key != key) {
      if (slot) slot->stop = true;  // its maps in flight stop (409)
      slot = std::make_shared<Entry>();
      slot->key = key;
    }
    slot->used = ++clock_;
    entry = slot;
    while (entries_.size() > kMaxEntries) {  // forget the one used longest ago
      auto oldest = entries_.begin();
      for (auto it = entries_.begin(); it != entries_.end(); ++it)
        if (it->second->used < oldest->second->used) oldest = it;
      oldest->second->stop = true;
      entries_.erase(oldest);
    }
  }
  std::lock_guard use(entry->use);
  if (!entry->engine) {
    s.sampling.cancel = CancelToken(&entry->stop);
    auto engine = std::make_unique<engine::FractalEngine>(s);
    engine->prepare(frame.size(), size, fps > 0 ? fps : 25);
    entry->engine = std::move(engine);
  }
  entry->engine->set_look(mix, background);
  cv::Mat out;
  if (seconds >= 0)
    entry->engine->filter_at(frame, seconds, out);
  else
    entry->engine->filter(frame, index, out);
  return encode_jpeg(out);
}

void FilterPreviews::stop_all() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  for (auto& [channel, entry] : entries_) entry->stop = true;
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
