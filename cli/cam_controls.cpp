// SPDX-License-Identifier: Apache-2.0
#include "cli/cam_controls.h"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "video/image_sequence.h"

namespace ifsfx::app {
namespace {

// The shipped presets the n/p keys step through: the drawing IFSs (the factor-1 square tilings
// are colouring IFSs only and are refused as F).
std::vector<std::string> cycle_presets() {
  std::vector<std::string> names;
  for (const PresetSummary& p : list_shipped_presets()) {
    if (p.contraction < 1) names.push_back(p.name);
  }
  return names;
}

// The first file of the --snapshot pattern, counting from 1, that does not exist yet.
std::filesystem::path next_snapshot(const std::string& pattern) {
  for (std::int64_t n = 1;; ++n) {
    std::filesystem::path p = video::sequence_path(pattern, n);
    if (!std::filesystem::exists(p)) return p;
  }
}

}  // namespace

void Notices::operator()(const std::string& text) {
  if (!quiet_) std::fprintf(stderr, "cam: %s\n", text.c_str());
  text_ = text;
  until_ = std::chrono::steady_clock::now() + std::chrono::seconds(3);
}

std::string Notices::current() const {
  return std::chrono::steady_clock::now() < until_ ? text_ : std::string();
}

CamControls::CamControls(const CamControlsSetup& setup, CamRecording& recording, Notices& notice)
    : setup_(setup),
      recording_(recording),
      notice_(notice),
      filter_(std::make_unique<LiveFilter>(*setup.fractal, setup.fade_frames, setup.fractal->preset,
                                           setup.size, setup.animate, setup.fps)),
      animate_(setup.animate),
      presets_(cycle_presets()) {
  for (std::size_t i = 0; i < presets_.size(); ++i) {
    if (presets_[i] == setup.fractal->preset) index_ = i;
  }
}

void CamControls::key(int key, const cv::Mat& shown) {
  switch (key) {
    case 'n':
      step_preset(true);
      break;
    case 'p':
      step_preset(false);
      break;
    case 'a':
      animate_ = !animate_;
      drift_maps_ += filter_->maps_built();
      filter_->set_animate(animate_);
      notice_(animate_ ? "animation on (drift)" : "animation off");
      break;
    case 's':
      snapshot(shown);
      break;
    case 'r':
      toggle_recording();
      break;
    default:
      break;
  }
}

void CamControls::step_preset(bool forward) {
  if (presets_.empty()) return;
  const std::size_t n = presets_.size();
  std::size_t i = wanted_    ? *wanted_
                  : pending_ ? pending_->index
                             : index_.value_or(forward ? n - 1 : 0);
  i = forward ? (i + 1) % n : (i + n - 1) % n;
  if (pending_) {
    wanted_ = i;
  } else {
    start_switch(i);
  }
}

void CamControls::start_switch(std::size_t index) {
  notice_(fmt::format("computing the map of {}", presets_[index]));
  pending_ = Switch{index, std::async(std::launch::async, [setup = setup_, name = presets_[index],
                                                           animate = animate_] {
                      return std::make_unique<LiveFilter>(*setup.fractal, setup.fade_frames, name,
                                                          setup.size, animate, setup.fps);
                    })};
}

void CamControls::poll() {
  using namespace std::chrono_literals;
  if (!pending_ || pending_->filter.wait_for(0s) != std::future_status::ready) return;
  const std::size_t i = pending_->index;
  index_ = i;  // also when it failed: n and p go on from there
  try {
    std::unique_ptr<LiveFilter> next = pending_->filter.get();
    next->set_animate(animate_);  // the a key may have been pressed meanwhile
    drift_maps_ += filter_->maps_built();
    filter_ = std::move(next);
    notice_(fmt::format("preset {} ({}/{})", presets_[i], i + 1, presets_.size()));
  } catch (const Error& e) {
    notice_(fmt::format("preset {} not shown: {}", presets_[i], e.what()));
  }
  pending_.reset();
  if (wanted_) {
    start_switch(*wanted_);
    wanted_.reset();
  }
}

void CamControls::snapshot(const cv::Mat& image) {
  try {
    const std::filesystem::path path = next_snapshot(setup_.snapshot);
    write_image(path, image);
    notice_(fmt::format("snapshot {}", path.string()));
  } catch (const Error& e) {
    notice_(fmt::format("snapshot failed: {}", e.what()));
  }
}

void CamControls::toggle_recording() {
  if (recording_.recording()) {
    recording_.stop();
    notice_(fmt::format("recording stopped: {} ({} frames)", recording_.path().string(),
                        recording_.frames()));
    return;
  }
  try {
    recording_.start();
    notice_(fmt::format("recording {}", recording_.path().string()));
  } catch (const Error& e) {
    notice_(fmt::format("recording failed: {}", e.what()));
  }
}

}  // namespace ifsfx::app
