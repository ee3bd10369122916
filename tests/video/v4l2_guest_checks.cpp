// SPDX-License-Identifier: Apache-2.0
// Checks against real kernel V4L2 drivers, run inside the VM of tests/v4l2-vm/run-vm-tests.sh:
// vivid (a virtual webcam showing 75% colour bars) and v4l2loopback (the virtual webcam that
// `ifsfx cam --output` feeds). Not part of the host suite: the host kernel has no V4L2.
//
// Environment: V4L2_CAPTURE_DEV (vivid capture), V4L2_LOOPBACK_DEV, IFSFX_BIN (the ifsfx
// binary), VM_SHARE (a folder shared with the host, for artefacts).
#include <fcntl.h>
#include <linux/videodev2.h>
#include <signal.h>
#include <spawn.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "engine/fractal_filter.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "video/v4l2_capture.h"
#include "video/v4l2_convert.h"
#include "video/v4l2_device.h"
#include "video/v4l2_output.h"

extern char** environ;

namespace ifsfx::video {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using engine::filter_frame;
using engine::prepare_filter;

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A child process with stdout and stderr in files, never waited on forever.
class Child {
 public:
  // Runs argv[0] (found on PATH) in `cwd` (this process's when empty).
  Child(const std::vector<std::string>& argv, const std::string& tag,
        const std::filesystem::path& cwd = {}) {
    out_ = std::filesystem::temp_directory_path() / (tag + ".out");
    err_ = std::filesystem::temp_directory_path() / (tag + ".err");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
    posix_spawn_file_actions_addopen(&fa, 1, out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    if (posix_spawnp(&pid_, args[0], &fa, nullptr, args.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&fa);
  }
  ~Child() {
    if (pid_ > 0 && !done_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }
  // Waits up to `timeout`; returns false (and kills the child) if it is still running: a hang.
  bool wait(std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (!done_) {
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        done_ = true;
        rc_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        break;
      }
      if (Clock::now() > deadline) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
        done_ = true;
        rc_ = -1;
        return false;
      }
      std::this_thread::sleep_for(20ms);
    }
    return true;
  }
  bool running() {
    if (done_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      done_ = true;
      rc_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    return !done_;
  }
  int rc() const { return rc_; }
  pid_t pid() const { return pid_; }
  std::string out() const { return read_text(out_); }
  std::string err() const { return read_text(err_); }

 private:
  pid_t pid_ = -1;
  bool done_ = false;
  int rc_ = -1;
  std::filesystem::path out_, err_;
};

int run(const std::vector<std::string>& argv, const std::string& tag, std::string* err = nullptr,
        std::string* out = nullptr) {
  Child c(argv, tag);
  EXPECT_TRUE(c.started()) << argv[0];
  EXPECT_TRUE(c.wait(120s)) << tag << ": still running after 120 s (a hang)";
  if (err) *err = c.err();
  if (out) *out = c.out();
  return c.rc();
}

// N of "recording kept: PATH (N frames; ...)" in an error message; -1 when absent.
int frames_reported(const std::string& err) {
  const auto at = err.find("recording kept: ");
  if (at == std::string::npos) return -1;
  const auto open = err.find(" (", at);
  return open == std::string::npos ? -1 : std::atoi(err.c_str() + open + 2);
}

class VividTest : public ::testing::Test {
 protected:
  void SetUp() override {
    cap_ = env("V4L2_CAPTURE_DEV");
    loop_ = env("V4L2_LOOPBACK_DEV");
    ifsfx_ = env("IFSFX_BIN");
    share_ = env("VM_SHARE");
    if (cap_.empty() || loop_.empty() || ifsfx_.empty()) {
      GTEST_FAIL() << "run inside tests/v4l2-vm/run-vm-tests.sh with IFSFX_BIN set";
    }
    // Webcam input, no text overlay: vivid's frames are then the same still colour bars every
    // time, so a frame captured here is the frame `ifsfx cam` captures later.
    ASSERT_EQ(run({"v4l2-ctl", "-d", cap_, "-i", "0", "-c", "osd_text_mode=2"}, "v4l2-ctl"), 0);
  }

  // The newest of a few frames, through our own capture.
  cv::Mat grab(const std::string& dev, cv::Size size, PixelFormat format) {
    V4l2Capture camera(dev, {.size = size, .fps = 0, .formats = {format}});
    EXPECT_EQ(camera.size(), size);
    EXPECT_EQ(camera.format(), format);
    cv::Mat last;
    for (int i = 0; i < 3; ++i) last = camera.read()->image;
    return last;
  }

  // The filter `ifsfx cam` applies for these options, on the host's library.
  static cv::Mat expected_filter(const cv::Mat& frame, const std::string& preset,
                                 const StealMapOptions& o) {
    const Ifs F = load_ifs(preset).ifs;
    const Ifs G = default_colouring(F.size());
    const PreparedStealMap table =
        prepare_filter(compute_steal_map(F, G, frame.size(), o), frame.size());
    return filter_frame(frame, table);
  }

  // What a frame looks like after the YUYV trip to the loopback device and back.
  static cv::Mat through_yuyv(const cv::Mat& bgr) {
    std::vector<std::uint8_t> yuyv;
    from_bgr(bgr, PixelFormat::yuyv, yuyv);
    return to_bgr(yuyv, {PixelFormat::yuyv, bgr.size()}, "yuyv");
  }

  // Frames read back from the loopback device while `producer` feeds it. Waits for the producer
  // to set the device up (it computes its steal map first).
  std::vector<cv::Mat> read_loopback(Child& producer, cv::Size size, int n) {
    std::vector<cv::Mat> frames;
    const auto deadline = Clock::now() + 90s;
    while (Clock::now() < deadline && producer.running()) {
      try {
        V4l2Capture reader(
            loop_, {.size = size, .fps = 0, .formats = {PixelFormat::yuyv}, .timeout_ms = 5000});
        if (reader.size() != size) {
          std::this_thread::sleep_for(200ms);
          continue;
        }
        while (static_cast<int>(frames.size()) < n) frames.push_back(reader.read()->image);
        return frames;
      } catch (const Error&) {
        frames.clear();
        std::this_thread::sleep_for(200ms);
      }
    }
    ADD_FAILURE() << "no frames from " << loop_ << "; producer stderr: " << producer.err();
    return frames;
  }

  void save(const std::string& name, const cv::Mat& image) {
    if (!share_.empty()) cv::imwrite(share_ + "/" + name, image);
  }

  std::string cap_, loop_, ifsfx_, share_;
};

// vivid's 75% colour bars, left to right, in BGR: white, yellow, cyan, green, magenta, red,
// blue, black at 75% amplitude (191 of 255).
void expect_colour_bars(const cv::Mat& frame, const std::string& what) {
  ASSERT_FALSE(frame.empty()) << what;
  const cv::Vec3d bars[8] = {{191, 191, 191}, {0, 191, 191}, {191, 191, 0}, {0, 191, 0},
                             {191, 0, 191},   {0, 0, 191},   {191, 0, 0},   {0, 0, 0}};
  cv::Scalar mean, stddev;
  cv::meanStdDev(frame, mean, stddev);
  EXPECT_GT(mean[0] + mean[1] + mean[2], 3 * 60.0) << what << ": frame is (nearly) black";
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 3 * 40.0) << what << ": frame is flat";
  const int w = frame.cols / 8;
  for (int k = 0; k < 8; ++k) {
    // The middle half of bar k, middle half of the height (clear of any overlay).
    const cv::Rect r(k * w + w / 4, frame.rows / 4, w / 2, frame.rows / 2);
    const cv::Scalar m = cv::mean(frame(r));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(m[c], bars[k][c], 12) << what << ": bar " << k << " channel " << c;
    }
  }
}

double psnr(const cv::Mat& a, const cv::Mat& b) {
  return cv::PSNR(a, b);
}

TEST_F(VividTest, list_shows_vivid_and_the_loopback_with_formats_sizes_and_rates) {
  const auto devices = list_v4l2_devices();
  bool vivid = false;
  for (const V4l2ListEntry& e : devices) {
    if (e.info.path != cap_) continue;
    vivid = true;
    EXPECT_TRUE(e.error.empty()) << e.error;
    EXPECT_TRUE(e.info.capture);
    bool yuyv_640 = false;
    for (const V4l2Format& f : e.info.capture_formats) {
      if (pixel_format_from_fourcc(f.fourcc) != PixelFormat::yuyv) continue;
      for (const V4l2FrameSize& s : f.sizes) {
        if (s.size == cv::Size(640, 480)) yuyv_640 = !s.fps.empty() && s.fps.front() >= 25;
      }
    }
    EXPECT_TRUE(yuyv_640) << "vivid lists YUYV 640x480 at 25 fps";
  }
  EXPECT_TRUE(vivid) << cap_ << " not listed";

  std::string out, err;
  ASSERT_EQ(run({ifsfx_, "cam", "--list"}, "list", &err, &out), 0) << err;
  EXPECT_NE(out.find(cap_ + ": vivid"), std::string::npos) << out;
  EXPECT_NE(out.find("capture YUYV"), std::string::npos) << out;
  EXPECT_NE(out.find("640x480 (25, 15"), std::string::npos) << out;
  EXPECT_NE(out.find(loop_ + ": ifsfx-loopback"), std::string::npos) << out;
}

TEST_F(VividTest, yuyv_capture_at_two_sizes_shows_the_colour_bars) {
  for (const cv::Size size : {cv::Size(640, 480), cv::Size(1280, 720)}) {
    V4l2Capture camera(cap_, {.size = size, .fps = 0, .formats = {PixelFormat::yuyv}});
    ASSERT_EQ(camera.size(), size);
    ASSERT_EQ(camera.format(), PixelFormat::yuyv);
    EXPECT_GT(camera.fps(), 0);
    std::int64_t last_index = -1;
    for (int i = 0; i < 5; ++i) {
      const Frame f = *camera.read();
      ASSERT_EQ(f.image.size(), size);
      EXPECT_GT(f.index, last_index) << "frames come in order";
      last_index = f.index;
      expect_colour_bars(f.image, fmt::format("{}x{} frame {}", size.width, size.height, i));
    }
    save(fmt::format("vivid-{}x{}.png", size.width, size.height), camera.read()->image);
  }
}

// The rate and size asked for are negotiated with the driver, and what it granted is what
// `ifsfx cam` reports: vivid's webcam has 640x480 at 25 and 15 fps, and no 1000x600.
TEST_F(VividTest, requested_rate_and_size_are_negotiated_and_the_granted_ones_reported) {
  for (const double fps : {15.0, 25.0}) {
    V4l2Capture camera(cap_, {.size = {640, 480}, .fps = fps, .formats = {PixelFormat::yuyv}});
    EXPECT_EQ(camera.size(), cv::Size(640, 480));
    EXPECT_DOUBLE_EQ(camera.fps(), fps);
  }
  cv::Size granted;
  {
    V4l2Capture odd(cap_, {.size = {1000, 600}, .fps = 0, .formats = {PixelFormat::yuyv}});
    granted = odd.size();
    EXPECT_NE(granted, cv::Size(1000, 600));
    const cv::Mat frame = odd.read()->image;
    EXPECT_EQ(frame.size(), granted);
    expect_colour_bars(frame, "frame of the granted size");
  }  // closed: `ifsfx cam` below needs the device

  std::string err;
  ASSERT_EQ(run({ifsfx_, "cam", "--device", cap_, "--size", "640x480", "--fps", "15", "--format",
                 "yuyv", "--output", loop_, "--max-frames", "3", "--exact"},
                "cam-rate", &err),
            0)
      << err;
  EXPECT_NE(err.find("cam: " + cap_ + " (vivid"), std::string::npos) << err;
  EXPECT_NE(err.find("): 640x480 YUYV at 15 fps"), std::string::npos) << err;
  ASSERT_EQ(run({ifsfx_, "cam", "--device", cap_, "--size", "1000x600", "--format", "yuyv",
                 "--output", loop_, "--max-frames", "3", "--exact"},
                "cam-size", &err),
            0)
      << err;
  EXPECT_NE(err.find(fmt::format("): {}x{} YUYV at", granted.width, granted.height)),
            std::string::npos)
      << err;
}

TEST_F(VividTest, nv12_and_yuv420_capture_show_the_same_colour_bars) {
  for (const PixelFormat format : {PixelFormat::nv12, PixelFormat::yuv420}) {
    const cv::Mat frame = grab(cap_, {640, 360}, format);
    expect_colour_bars(frame, fourcc_name(fourcc(format)));
  }
}

TEST_F(VividTest, cam_output_sends_the_filtered_frames_to_the_loopback) {
  const cv::Size size(320, 180);
  const cv::Mat camera_frame = grab(cap_, size, PixelFormat::yuyv);
  Child cam({ifsfx_, "cam", "--device", cap_, "--size", "320x180", "--fps", "30", "--output", loop_,
             "--max-frames", "100", "--preset", "sierpinski-triangle", "--exact"},
            "cam-output");
  const std::vector<cv::Mat> got = read_loopback(cam, size, 5);
  ASSERT_TRUE(cam.wait(120s)) << "ifsfx cam did not stop after --max-frames";
  EXPECT_EQ(cam.rc(), 0) << cam.err();
  ASSERT_EQ(got.size(), 5u);

  StealMapOptions o;
  o.exact = true;
  const cv::Mat expected = through_yuyv(expected_filter(camera_frame, "sierpinski-triangle", o));
  save("loopback-filtered.png", got.back());
  save("expected-filtered.png", expected);
  for (const cv::Mat& frame : got) {
    ASSERT_EQ(frame.size(), size);
    EXPECT_LE(cv::norm(frame, expected, cv::NORM_INF), 2) << "PSNR " << psnr(frame, expected);
  }
  // Not a trivially equal pair: the filter changed the camera's frame.
  EXPECT_LT(psnr(expected, through_yuyv(camera_frame)), 20);
}

TEST_F(VividTest, identity_preset_through_the_live_path_returns_the_camera_frames) {
  // F = G = the four quadrant maps of the unit square, shown on the whole frame: T(x) = x
  // (docs/design.md §3, identity oracle).
  const cv::Size size(320, 180);
  const cv::Mat camera_frame = grab(cap_, size, PixelFormat::yuyv);
  Child cam({ifsfx_, "cam", "--device", cap_, "--size", "320x180", "--output", loop_,
             "--max-frames", "100", "--preset", "square-tiling-4", "--colouring", "square-tiling-4",
             "--view", "0,0,1,1", "--exact"},
            "cam-identity");
  const std::vector<cv::Mat> got = read_loopback(cam, size, 5);
  ASSERT_TRUE(cam.wait(120s));
  EXPECT_EQ(cam.rc(), 0) << cam.err();
  ASSERT_EQ(got.size(), 5u);
  save("loopback-identity.png", got.back());
  for (const cv::Mat& frame : got) {
    EXPECT_GE(psnr(frame, camera_frame), 40);
    expect_colour_bars(frame, "identity through the loopback");
  }
}

TEST_F(VividTest, missing_device_fails_with_one_line) {
  std::string err;
  EXPECT_EQ(run({ifsfx_, "cam", "--device", "/dev/video99", "--output", loop_, "--max-frames", "5"},
                "missing", &err),
            1);
  EXPECT_EQ(err, "ifsfx: /dev/video99: no such device: No such file or directory (ENOENT)\n");
}

TEST_F(VividTest, unsupported_format_is_an_unsupported_error_naming_the_device) {
  try {
    V4l2Capture camera(cap_, {.size = {320, 180}, .formats = {PixelFormat::mjpeg}});
    FAIL() << "vivid does not offer MJPEG";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_EQ(std::string(e.what()).rfind(cap_ + ": pixel format not supported: asked for MJPG "
                                                 "(device offers YUYV, UYVY",
                                          0),
              0u)
        << e.what();
  }
}

TEST_F(VividTest, busy_device_is_a_device_error_naming_the_device) {
  V4l2Capture holder(cap_, {.size = {320, 180}, .fps = 0, .formats = {PixelFormat::yuyv}});
  ASSERT_TRUE(holder.read().has_value());  // streaming: the device is now taken
  try {
    V4l2Capture second(cap_, {.size = {320, 180}, .fps = 0, .formats = {PixelFormat::yuyv}});
    second.read();
    FAIL() << "a second streamer was let in";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::device);
    EXPECT_EQ(std::string(e.what()).rfind(cap_ + ": device busy", 0), 0u) << e.what();
  }
}

TEST_F(VividTest, a_capture_node_is_not_an_output) {
  try {
    V4l2Output out(cap_, {320, 180});
    FAIL() << "vivid's capture node taken as an output";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_EQ(std::string(e.what()).rfind(cap_ + ": not a video output device", 0), 0u) << e.what();
  }
}

TEST_F(VividTest, loopback_round_trip_and_producer_gone_ends_the_read_without_a_hang) {
  const cv::Size size(320, 180);
  const cv::Mat pattern = grab(cap_, size, PixelFormat::yuyv);
  auto producer = std::make_unique<V4l2Output>(loop_, size);
  Frame f;
  f.image = pattern;
  producer->write(f);
  V4l2Capture reader(loop_,
                     {.size = size, .fps = 0, .formats = {PixelFormat::yuyv}, .timeout_ms = 2000});
  std::atomic<bool> stop{false};
  std::thread feed([&] {
    while (!stop) {
      producer->write(f);
      std::this_thread::sleep_for(20ms);
    }
  });
  cv::Mat got;
  for (int i = 0; i < 3; ++i) got = reader.read()->image;
  stop = true;
  feed.join();
  // What went out as YUYV comes back as the same YUYV.
  EXPECT_EQ(cv::norm(got, through_yuyv(pattern), cv::NORM_INF), 0);
  producer.reset();
  const auto t0 = Clock::now();
  try {
    // A frame or two may still be queued; then the reader must give up, not wait forever.
    for (int i = 0; i < 10; ++i) reader.read();
    FAIL() << "frames kept coming after the producer closed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::device);
    EXPECT_EQ(std::string(e.what()).rfind(loop_ + ": no frame for 2000 ms", 0), 0u) << e.what();
  }
  EXPECT_LT(Clock::now() - t0, 60s);
}

// Waits until a file of `dir` named after `stem` (the recording's temporary file,
// .STEM.XXXXXXXX.ifsfx-tmp) holds some frames (a codec that writes each frame).
bool wait_for_recording(Child& cam, const std::filesystem::path& dir, const std::string& stem) {
  const auto deadline = Clock::now() + 90s;
  while (Clock::now() < deadline && cam.running()) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().filename().string().find(stem) != std::string::npos && e.file_size() > 40'000) {
        return true;
      }
    }
    std::this_thread::sleep_for(100ms);
  }
  return false;
}

// Frames in a movie file, decoded to the end (-1 if it does not open).
int decodable_frames(const std::filesystem::path& path) {
  cv::VideoCapture in(path.string(), cv::CAP_FFMPEG);
  if (!in.isOpened()) return -1;
  int n = 0;
  cv::Mat f;
  while (in.read(f)) ++n;
  return n;
}

// An X server of the test's own (Xvfb) for the window of `ifsfx cam`, set as DISPLAY for the
// children started while it lives.
class VirtualDisplay {
 public:
  VirtualDisplay()
      : server_({"Xvfb", ":77", "-screen", "0", "1024x768x24", "-nolisten", "tcp"}, "xvfb") {
    const auto deadline = Clock::now() + 60s;
    while (Clock::now() < deadline && server_.running() &&
           !std::filesystem::exists("/tmp/.X11-unix/X77")) {
      std::this_thread::sleep_for(100ms);
    }
    ready_ = server_.running() && std::filesystem::exists("/tmp/.X11-unix/X77");
    setenv("DISPLAY", ":77", 1);
  }
  ~VirtualDisplay() {
    unsetenv("DISPLAY");
    if (server_.running()) kill(server_.pid(), SIGTERM);
    server_.wait(10s);
  }
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;
  bool ready() const { return ready_; }
  std::string log() const { return server_.err(); }

 private:
  Child server_;
  bool ready_ = false;
};

// Waits until a line of `child`'s stderr starts with `prefix`; returns the rest of that line, or
// nothing on timeout or when the child ended first. (No std::regex: GCC 12 warns inside it at -O1.)
std::optional<std::string> wait_for_line(Child& child, const std::string& prefix,
                                         std::chrono::seconds timeout = 90s) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    std::istringstream lines(child.err());
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
    }
    if (Clock::now() > deadline || !child.running()) return std::nullopt;
    std::this_thread::sleep_for(100ms);
  }
}

// The number just before `suffix` in `text` ("..., 12 drift maps"), -1 when there is none.
int number_before(const std::string& text, const std::string& suffix) {
  const auto end = text.find(suffix);
  if (end == std::string::npos) return -1;
  auto begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(text[begin - 1]))) --begin;
  return begin == end ? -1 : std::stoi(text.substr(begin, end - begin));
}

// The window's picture, read back from the X server (xwd, then netpbm's xwdtopnm).
cv::Mat window_image(const std::string& window_id, const std::filesystem::path& dir) {
  const std::filesystem::path xwd = dir / "window.xwd", ppm = dir / "window.ppm";
  if (run({"sh", "-c",
           "xwd -silent -id " + window_id + " > " + xwd.string() + " && xwdtopnm " + xwd.string() +
               " > " + ppm.string() + " 2>/dev/null"},
          "xwd") != 0) {
    return {};
  }
  return cv::imread(ppm.string(), cv::IMREAD_COLOR);
}

// The window of `ifsfx cam` under a real X server, its keys pressed as a user would (xdotool
// types into the focused window): s snapshot, n/p next/previous preset, a animation, r recording,
// q quit; and the readout drawn over the picture.
TEST_F(VividTest, window_keys_snapshot_switch_presets_animate_record_and_quit) {
  VirtualDisplay display;
  ASSERT_TRUE(display.ready()) << "Xvfb did not start: " << display.log();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "window";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const cv::Size size(320, 180);
  const cv::Mat camera_frame = grab(cap_, size, PixelFormat::yuyv);
  Child cam({ifsfx_, "cam", "--device", cap_, "--size", "320x180", "--format", "yuyv", "--window",
             "--preset", "sierpinski-triangle", "--exact", "--snapshot", "snap-%02d.png"},
            "cam-window", dir);
  std::string window;
  ASSERT_EQ(run({"xdotool", "search", "--sync", "--onlyvisible", "--name", "^ifsfx cam$"},
                "xdotool-search", nullptr, &window),
            0)
      << cam.err();
  window = window.substr(0, window.find('\n'));
  ASSERT_FALSE(window.empty()) << cam.err();
  // Keys go to the focused window; it takes focus once mapped, which may lag its creation.
  std::string focus_err;
  const auto focus_deadline = Clock::now() + 30s;
  while (run({"xdotool", "windowfocus", "--sync", window}, "xdotool-focus", &focus_err) != 0) {
    ASSERT_LT(Clock::now(), focus_deadline) << "xdotool windowfocus: " << focus_err;
    std::this_thread::sleep_for(500ms);
  }
  const auto press = [&](const char* key) {
    ASSERT_EQ(run({"xdotool", "key", key}, "xdotool-key"), 0) << key;
  };

  // s: the filtered frame, without the readout, as the filter makes it.
  press("s");
  ASSERT_EQ(wait_for_line(cam, "cam: snapshot "), "snap-01.png") << cam.err();
  const cv::Mat snap1 = cv::imread((dir / "snap-01.png").string(), cv::IMREAD_COLOR);
  StealMapOptions exact;
  exact.exact = true;
  const cv::Mat expected = expected_filter(camera_frame, "sierpinski-triangle", exact);
  ASSERT_EQ(snap1.size(), size);
  EXPECT_LE(cv::norm(snap1, expected, cv::NORM_INF), 2);

  // The window shows that frame, with the readout (fps, preset, the last action) over its
  // top-left corner and nothing else changed.
  const cv::Mat shown = window_image(window, dir);
  ASSERT_EQ(shown.size(), size) << "the window is the picture alone";
  save("window.png", shown);
  const int readout_rows = size.height / 3;
  const cv::Rect below(0, readout_rows, size.width, size.height - readout_rows);
  EXPECT_EQ(cv::norm(shown(below), snap1(below), cv::NORM_INF), 0);
  const cv::Rect corner(0, 0, size.width, readout_rows);
  cv::Mat diff;
  cv::absdiff(shown(corner), snap1(corner), diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), 200) << "no readout drawn";

  // n: the next shipped preset, a different picture; p: back to the first, the same picture.
  press("n");
  const std::string switched = wait_for_line(cam, "cam: preset ").value_or("");
  const std::string next = switched.substr(0, switched.find(' '));
  EXPECT_NE(switched.find(" ("), std::string::npos) << switched;
  EXPECT_FALSE(next.empty()) << cam.err();
  EXPECT_NE(next, "sierpinski-triangle");
  press("s");
  ASSERT_TRUE(wait_for_line(cam, "cam: snapshot snap-02.png")) << cam.err();
  const cv::Mat snap2 = cv::imread((dir / "snap-02.png").string(), cv::IMREAD_COLOR);
  EXPECT_GT(cv::norm(snap2, snap1, cv::NORM_L1) / snap1.total(), 10) << next << " looks the same";
  press("p");
  ASSERT_TRUE(wait_for_line(cam, "cam: preset sierpinski-triangle (")) << cam.err();
  press("s");
  ASSERT_TRUE(wait_for_line(cam, "cam: snapshot snap-03.png")) << cam.err();
  const cv::Mat snap3 = cv::imread((dir / "snap-03.png").string(), cv::IMREAD_COLOR);
  EXPECT_EQ(cv::norm(snap3, snap1, cv::NORM_INF), 0);

  // a: the drift animation on, then off again; the summary counts the maps it built.
  press("a");
  ASSERT_TRUE(wait_for_line(cam, "cam: animation on")) << cam.err();
  std::this_thread::sleep_for(4s);
  press("a");
  ASSERT_TRUE(wait_for_line(cam, "cam: animation off")) << cam.err();

  // r: a recording starts, r again finalises it, playable with the frames it reports.
  press("r");
  ASSERT_TRUE(wait_for_line(cam, "cam: recording cam-recording.mkv")) << cam.err();
  std::this_thread::sleep_for(3s);
  press("r");
  const std::optional<std::string> stopped =
      wait_for_line(cam, "cam: recording stopped: cam-recording.mkv (");
  ASSERT_TRUE(stopped) << cam.err();
  const int recorded = number_before(*stopped, " frames)");
  EXPECT_GT(recorded, 0) << *stopped;
  EXPECT_EQ(decodable_frames(dir / "cam-recording.mkv"), recorded);

  // q: the end, exit 0, with the summary.
  press("q");
  ASSERT_TRUE(cam.wait(60s)) << "q did not end ifsfx cam";
  EXPECT_EQ(cam.rc(), 0) << cam.err();
  const std::string err = cam.err();
  const std::string last = err.substr(err.rfind("cam: "));
  EXPECT_NE(last.find(" frames in "), std::string::npos) << err;
  EXPECT_GT(number_before(last, " drift maps"), 0) << err;
}

TEST_F(VividTest, window_without_a_display_fails_with_one_line_before_opening_the_camera) {
  unsetenv("DISPLAY");
  std::string err;
  EXPECT_EQ(run({ifsfx_, "cam", "--device", cap_}, "no-display", &err), 1);
  EXPECT_EQ(err,
            "ifsfx: --window: no display (neither DISPLAY nor WAYLAND_DISPLAY is set); run "
            "headless with --output or --record\n");
}

// vivid offers no MJPEG, so a producer of our own sends JPEG frames through the loopback device
// (as a USB webcam sends them): our capture decodes them to what the producer encoded, and
// `ifsfx cam --format mjpeg` runs on them.
TEST_F(VividTest, mjpeg_frames_from_the_loopback_decode_to_what_was_sent) {
  const cv::Size size(320, 180);
  const cv::Mat pattern = grab(cap_, size, PixelFormat::yuyv);
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", pattern, jpeg, {cv::IMWRITE_JPEG_QUALITY, 90}));
  const cv::Mat sent = cv::imdecode(jpeg, cv::IMREAD_COLOR);

  const int fd = ::open(loop_.c_str(), O_RDWR);
  ASSERT_GE(fd, 0) << loop_;
  const std::unique_ptr<const int, void (*)(const int*)> close_fd(
      &fd, [](const int* f) { ::close(*f); });
  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  f.fmt.pix.width = size.width;
  f.fmt.pix.height = size.height;
  f.fmt.pix.pixelformat = V4L2_PIX_FMT_MJPEG;
  f.fmt.pix.field = V4L2_FIELD_NONE;
  f.fmt.pix.sizeimage = size.area() * 2;
  ASSERT_EQ(ioctl(fd, VIDIOC_S_FMT, &f), 0) << "the loopback refuses MJPEG: " << strerror(errno);
  ASSERT_EQ(f.fmt.pix.pixelformat, static_cast<std::uint32_t>(V4L2_PIX_FMT_MJPEG));
  // The loopback offers its format to readers once the producer has sent a frame.
  ASSERT_EQ(::write(fd, jpeg.data(), jpeg.size()), static_cast<ssize_t>(jpeg.size()))
      << strerror(errno);
  // Feeds the JPEG frame until the end of the test, however it ends.
  struct Feeder {
    std::atomic<bool> stop{false};
    std::thread thread;
    ~Feeder() {
      stop = true;
      if (thread.joinable()) thread.join();
    }
  } feeder;
  feeder.thread = std::thread([&] {
    while (!feeder.stop) {
      if (::write(fd, jpeg.data(), jpeg.size()) < 0) {
        ADD_FAILURE() << "write to " << loop_ << ": " << strerror(errno);
        break;
      }
      std::this_thread::sleep_for(30ms);
    }
  });
  try {
    V4l2Capture reader(
        loop_, {.size = size, .fps = 0, .formats = {PixelFormat::mjpeg}, .timeout_ms = 5000});
    EXPECT_EQ(reader.format(), PixelFormat::mjpeg);
    EXPECT_EQ(reader.size(), size);
    for (int i = 0; i < 3; ++i) {
      const cv::Mat got = reader.read()->image;
      ASSERT_EQ(got.size(), size);
      EXPECT_EQ(cv::norm(got, sent, cv::NORM_INF), 0) << "frame " << i;
    }
  } catch (const Error& e) {
    FAIL() << e.what();
  }
  std::string err;
  const int rc = run({ifsfx_, "cam", "--device", loop_, "--format", "mjpeg", "--size", "320x180",
                      "--record", (std::filesystem::temp_directory_path() / "mjpeg.avi").string(),
                      "--max-frames", "10", "--preset", "square-tiling-4", "--colouring",
                      "square-tiling-4", "--view", "0,0,1,1", "--exact"},
                     "cam-mjpeg", &err);
  EXPECT_EQ(rc, 0) << err;
  EXPECT_NE(err.find(": 320x180 MJPG at"), std::string::npos) << err;
  EXPECT_NE(err.find("cam: 10 frames in"), std::string::npos) << err;
}

// Last: vivid stays disconnected until every handle on it is closed.
// Also runs the live drift animation, whose worker must not keep the program from ending.
// The recording is kept as a playable partial movie beside its target (the output policy: a run
// that fails never takes the output's name).
TEST_F(VividTest, camera_vanishing_mid_stream_ends_cleanly_with_the_recording_playable) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vanish";
  std::filesystem::create_directories(dir);
  // AVI with MPEG-4 part 2 (its default codec): packets reach the file as they are made, so
  // its growth shows that frames are being recorded.
  const std::filesystem::path rec = dir / "vanish.avi";
  Child cam({ifsfx_, "cam", "--device", cap_, "--size", "320x180", "--record", rec.string(),
             "--preset", "square-tiling-4", "--colouring", "square-tiling-4", "--view", "0,0,1,1",
             "--exact", "--animate", "drift"},
            "cam-vanish");
  ASSERT_TRUE(wait_for_recording(cam, dir, "vanish.avi")) << cam.err();
  // vivid's "disconnect" button acts as a USB camera unplugged mid-stream.
  ASSERT_EQ(run({"v4l2-ctl", "-d", cap_, "-c", "disconnect=1"}, "disconnect"), 0);
  ASSERT_TRUE(cam.wait(60s)) << "ifsfx cam hung after the camera vanished";
  EXPECT_EQ(cam.rc(), 1) << cam.err();
  const std::string err = cam.err();
  EXPECT_NE(err.find("ifsfx: " + cap_ + ": device vanished"), std::string::npos) << err;
  const std::filesystem::path partial = dir / "vanish.partial.avi";
  EXPECT_NE(err.find("recording kept: " + partial.string()), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(rec)) << "a failed recording took the output's name";
  EXPECT_GT(frames_reported(err), 0) << err;
  EXPECT_EQ(decodable_frames(partial), frames_reported(err)) << "recording not playable to the end";
}

}  // namespace
}  // namespace ifsfx::video
