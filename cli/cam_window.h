// SPDX-License-Identifier: Apache-2.0
// The interactive window of `ifsfx cam`: the filtered frame with a readout drawn in its top-left
// corner (frame rate, preset, recording state, and the last action for a moment), and the keys the
// user pressed.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::app {

class CamWindow {
 public:
  static constexpr const char* kTitle = "ifsfx cam";
  // What show() returns when the user closed the window (its close button, the window manager).
  static constexpr int kClosed = -2;

  // Throws Error{unsupported} when no window can be opened (no display, no GUI backend).
  CamWindow();
  ~CamWindow();
  CamWindow(const CamWindow&) = delete;
  CamWindow& operator=(const CamWindow&) = delete;

  // Shows `image` with `lines` drawn over its top-left corner; returns the key pressed (its low
  // byte, -1 for none) or kClosed.
  int show(const cv::Mat& image, const std::vector<std::string>& lines);

 private:
  cv::Mat canvas_;
  bool shown_ = false;
};

// Draws `lines` top-left on `image`, white on a black outline so they read on any picture, scaled
// to the image's width. Returns the rectangle drawn into (empty for no lines).
cv::Rect draw_readout(cv::Mat& image, const std::vector<std::string>& lines);

}  // namespace ifsfx::app
