// SPDX-License-Identifier: Apache-2.0
#include "cli/cam_window.h"

#include <algorithm>

#include <fmt/format.h>
#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "video/window_sink.h"

namespace ifsfx::app {

CamWindow::CamWindow() {
  video::require_display("--window", "run headless with --output or --record");
  try {
    // GUI_NORMAL: the picture alone, without the Qt backend's toolbar and status bar.
    cv::namedWindow(kTitle, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  } catch (const cv::Exception& e) {
    throw Error(ErrorKind::unsupported,
                fmt::format("--window: cannot open a window: {}; run headless with --output or "
                            "--record",
                            e.err));
  }
}

CamWindow::~CamWindow() {
  try {
    cv::destroyWindow(kTitle);
    cv::waitKey(1);
  } catch (const cv::Exception&) {  // already gone with the display; nothing left to close
  }
}

int CamWindow::show(const cv::Mat& image, const std::vector<std::string>& lines) {
  image.copyTo(canvas_);
  draw_readout(canvas_, lines);
  cv::imshow(kTitle, canvas_);
  const int key = cv::waitKey(1);
  // Once shown, a window that is no longer visible was closed by the user.
  const bool closed = shown_ && cv::getWindowProperty(kTitle, cv::WND_PROP_VISIBLE) < 1;
  shown_ = true;
  if (closed) return kClosed;
  return key < 0 ? -1 : key & 0xff;
}

cv::Rect draw_readout(cv::Mat& image, const std::vector<std::string>& lines) {
  constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
  // 0.6 on a 640-wide frame, never too small to read nor larger than on a 1080p frame.
  const double scale = std::clamp(image.cols / 1066.0, 0.35, 1.2);
  const int outline = std::max(2, static_cast<int>(std::lround(4 * scale)));
  int baseline = 0;
  const cv::Size glyph = cv::getTextSize("Ag", kFont, scale, 1, &baseline);
  const int step = glyph.height + baseline + outline;
  const int left = std::max(4, image.cols / 64);
  int y = left + glyph.height;
  cv::Rect drawn;
  for (const std::string& line : lines) {
    if (line.empty()) continue;
    const cv::Size size = cv::getTextSize(line, kFont, scale, 1, &baseline);
    cv::putText(image, line, {left, y}, kFont, scale, cv::Scalar::all(0), outline, cv::LINE_AA);
    cv::putText(image, line, {left, y}, kFont, scale, cv::Scalar::all(255), 1, cv::LINE_AA);
    drawn |= cv::Rect(left - outline, y - size.height - outline, size.width + 2 * outline,
                      size.height + baseline + 2 * outline);
    y += step;
  }
  return drawn & cv::Rect(0, 0, image.cols, image.rows);
}

}  // namespace ifsfx::app
