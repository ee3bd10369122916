// SPDX-License-Identifier: Apache-2.0
#include "video/window_sink.h"

#include <cstdlib>
#include <thread>

#include <fmt/format.h>
#include <opencv2/highgui.hpp>

#include "ifs/error.h"

namespace ifsfx::video {

void require_display(const std::string& what, const std::string& instead) {
  if (std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr) return;
  throw Error(ErrorKind::unsupported,
              fmt::format("{}: no display (neither DISPLAY nor WAYLAND_DISPLAY is set); {}", what,
                          instead));
}

WindowSink::WindowSink(const std::string& title, const WindowSinkOptions& options)
    : title_(title), options_(options) {}

WindowSink::~WindowSink() {
  try {
    close();
  } catch (...) {  // a destructor must not throw; the window is gone either way
  }
}

void WindowSink::write(const Frame& frame) {
  using clock = std::chrono::steady_clock;
  if (!open_) {
    try {
      // GUI_NORMAL: the picture alone, without the Qt backend's toolbar and status bar.
      cv::namedWindow(title_, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
    } catch (const cv::Exception& e) {
      throw Error(ErrorKind::unsupported, fmt::format("window: cannot open one ({})", e.err));
    }
    open_ = true;
    next_due_ = clock::now();
  }
  if (options_.fps > 0) {
    std::this_thread::sleep_until(next_due_);
    next_due_ += std::chrono::duration_cast<clock::duration>(
        std::chrono::duration<double>(1.0 / options_.fps));
    if (next_due_ < clock::now()) next_due_ = clock::now();
  }
  cv::imshow(title_, frame.image);
  const int key = cv::waitKey(1);
  const bool closed = cv::getWindowProperty(title_, cv::WND_PROP_VISIBLE) < 1;
  if ((key == 27 || key == 'q' || closed) && options_.stop != nullptr) *options_.stop = true;
}

void WindowSink::close() {
  if (!open_) return;
  open_ = false;
  cv::destroyWindow(title_);
  cv::waitKey(1);
}

}  // namespace ifsfx::video
