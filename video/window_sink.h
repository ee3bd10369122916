// SPDX-License-Identifier: Apache-2.0
// A window on the screen as a frame sink (`ifsfx filter --preview`): shows frames at the source's
// frame rate; closing the window or pressing Esc or q asks the pipeline to stop.
#pragma once

#include <atomic>
#include <chrono>
#include <string>

#include "video/frame_io.h"

namespace ifsfx::video {

// Throws Error{unsupported} "WHAT: no display (neither DISPLAY nor WAYLAND_DISPLAY is set);
// INSTEAD" when there is no display to open a window on: checked before any work, and before a GUI
// toolkit that aborts the process without a display is loaded.
void require_display(const std::string& what, const std::string& instead);

struct WindowSinkOptions {
  double fps = 25;                    // pace of display; 0 = as fast as frames come
  std::atomic<bool>* stop = nullptr;  // set when the user closes the window
};

// The window opens on the first frame, on the thread that writes (OpenCV's HighGUI). Throws
// Error{unsupported} when no window can be opened (no display, no GUI backend).
class WindowSink final : public FrameSink {
 public:
  WindowSink(const std::string& title, const WindowSinkOptions& options = {});
  ~WindowSink() override;
  void write(const Frame& frame) override;
  void close() override;
  std::string name() const override { return title_; }

 private:
  std::string title_;
  WindowSinkOptions options_;
  bool open_ = false;
  std::chrono::steady_clock::time_point next_due_;
};

}  // namespace ifsfx::video
