// SPDX-License-Identifier: Apache-2.0
// The fractal filter as one object (docs/design.md §10, "One engine, many doors"): every door —
// `ifsfx filter`, `ifsfx cam`, the frei0r plugins, a farm's shards — fills in one FractalSettings
// and asks one FractalEngine for its frames, so a picture made through any door is the picture
// made through every other one.
//
// A frame is a pure function of (settings, frame size, frame index or time): the fixed map is
// computed once; an animation's keyframes are pure functions of their number (engine/drift.h,
// superifs/texture.h), built ahead on worker threads (engine/map_schedule.h) and rebuilt when asked
// for again, so frames may be asked for in any order — backwards, from the middle, by several
// engines — and still agree.
//
//   FractalEngine engine({.drawing = load_ifs("maple-leaf").ifs, .animate = Animate::drift},
//                        {1920, 1080});
//   for (const Frame& f : frames) sink.write(engine.filter(f.image, f.index));
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "engine/drawing.h"
#include "engine/drift.h"
#include "engine/fractal_filter.h"
#include "ifs/cancel.h"
#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/steal_map.h"
#include "ifs/timeline.h"
#include "ifs/view.h"
#include "superifs/superifs.h"

namespace ifsfx {
class TextureSequence;
}

namespace ifsfx::engine {

class MapSchedule;

enum class Animate {
  none,      // one fixed map
  drift,     // the map coefficients wander by fBm noise (engine/drift.h)
  superifs,  // one V-variable step of a superIFS per keyframe (superifs/texture.h)
};

// The animation's defaults, which every door reads from here (the command's flags, the studio's
// fields, Python's keywords, the plugins' parameters).
inline constexpr double kDefaultDriftAmount = 0.05;  // largest excursion of a coefficient
inline constexpr double kDefaultDriftSpeed = 0.2;    // cycles per second of the slowest octave
inline constexpr int kDefaultKeyframeInterval = 12;  // frames between rebuilt maps
inline constexpr int kMaxKeyframeInterval = 100000;

// The shipped preset FractalSettings draw with when a door sets none, and its IFS.
inline constexpr const char* kDefaultPreset = "barnsley-fern";
Ifs default_drawing();

struct FractalSettings {
  // The fractal (docs/design.md §3) as data, the doors load presets (load_ifs, load_colouring,
  // flame::read_flame): the drawing F, an IFS — by default the shipped barnsley-fern — or a
  // fractal flame (its xforms through the chaos game, framed by its camera: engine/drawing.h),
  // and the colouring IFS G on the unit square (load_colouring fits a preset to it), one map per
  // map or xform of F, by default a tiling (default_colouring).
  Drawing drawing = default_drawing();
  std::optional<Ifs> colouring;
  bool exact = true;  // per-pixel descent (faster); false: the chaos game. A flame takes the
                      // chaos game either way (its xforms have no inverse).
  // The plane rectangle of F shown (none: auto-framed; a superIFS brings its own), the margin,
  // the chaos game's points per pixel, the seed of the chaos game, the drift and the superIFS
  // steps, the threads (0 = all cores), and the stop flag, polled while maps are built (the steal
  // map, the framing, the superIFS burn-in and descent): a stop request ends prepare() or a
  // keyframe's build with Error{interrupted} within a fraction of a second. The command line
  // passes its Ctrl-C flag; a plugin's host has none to pass.
  Sampling sampling;

  // How the frame shows through it.
  double mix = 0;  // weight of the original frame blended over the fractal, 0..1
  Background background;
  Interpolation interpolation = Interpolation::bilinear;

  // Animation: keyframe k shows the maps of time k · keyframe_interval / frame rate (the
  // stream's, see prepare()); the frames between two keyframes cross-fade from one to the next.
  Animate animate = Animate::none;
  double drift_amount = kDefaultDriftAmount;  // drift: largest excursion of a coefficient
  double drift_speed = kDefaultDriftSpeed;    // drift: cycles per second of the slowest octave
  int keyframe_interval = kDefaultKeyframeInterval;  // frames between rebuilt maps
  std::string superifs = "paper-fig4";  // superifs: the superIFS (its view and colouring
                                        // replace preset, colouring and view)
  int buffers = 3;                      // superifs: V
  // Frames after which the animation is back at frame 0, bit for bit (docs/design.md §12); 0 =
  // never. The loop holds ⌈loop / keyframe_interval⌉ keyframes spread evenly over it; the drift
  // is periodic with period loop / frame rate, the superIFS steps close into a loop of textures.
  std::int64_t loop = 0;

  // A live source (a camera through the OBS filter), timed by its clock: an animation's frames
  // never wait for a late keyframe but show the nearest earlier ready maps, and its keyframes are
  // built one at a time on one thread at a lower priority (engine/map_schedule.h, "Live"). Off
  // (files, frame-keyed): a frame's picture depends only on its index.
  bool live = false;

  friend bool operator==(const FractalSettings&, const FractalSettings&) = default;
};

// Whether two settings give the same maps, so that an engine made for `a` serves `b` after
// set_look(b.mix, b.background).
bool same_maps(const FractalSettings& a, const FractalSettings& b);

class FractalEngine {
 public:
  // Loads the fractal and checks every setting that does not depend on the frame size (throws
  // ifsfx::Error naming the setting): the cheap part, done before any input is opened.
  explicit FractalEngine(const FractalSettings& settings);
  // The same, then prepare(frame_size, output_size, frame_rate).
  FractalEngine(const FractalSettings& settings, cv::Size frame_size, cv::Size output_size = {},
                double frame_rate = 25);
  ~FractalEngine();
  FractalEngine(const FractalEngine&) = delete;
  FractalEngine& operator=(const FractalEngine&) = delete;

  // Computes the map (or starts the animation's keyframes) for frames of `frame_size` coloured
  // onto `output_size` (default: the frame size), `frame_rate` frames per second (it turns frame
  // numbers into the animation's time and back). Once.
  void prepare(cv::Size frame_size, cv::Size output_size = {}, double frame_rate = 25);

  // Frame `index` of the source (CV_8UC3 BGR, or CV_8UC4 whose fourth channel passes through, of
  // the prepared frame size), filtered: of the output size and the frame's type. One thread at a
  // time per engine; the work inside is spread over settings.threads.
  cv::Mat filter(const cv::Mat& frame, std::int64_t index);
  // Into `out`, reallocated only when its size or type differ.
  void filter(const cv::Mat& frame, std::int64_t index, cv::Mat& out);
  // The frame at `seconds` from the start: frame seconds · frame rate, between two frames where it
  // falls between them.
  void filter_at(const cv::Mat& frame, double seconds, cv::Mat& out);

  // New mix and background from the next frame on; no map is rebuilt.
  void set_look(double mix, const Background& background);

  const FractalSettings& settings() const { return settings_; }
  // F's name, or the superIFS's when animate is superifs.
  const std::string& name() const { return name_; }
  const Drawing& drawing() const { return F_; }
  const Ifs& colouring() const { return G_; }
  // The steal-map options of the settings (view, margin, exact, quality, seed, threads).
  StealMapOptions map_options() const;
  // How frames show through the maps (interpolation, mix, background, threads).
  const FilterOptions& filter_options() const { return options_; }
  // The drift of the settings (amount, speed, seed; with a loop, its length in seconds at the
  // prepared frame rate).
  DriftOptions drift_options() const;
  // Frames that waited for a keyframe (see MapSchedule::stalls); 0 for a fixed map.
  std::int64_t stalls() const;

 private:
  void filter_at(const cv::Mat& frame, StepPosition position, cv::Mat& out);
  // Keyframes in one loop (0 without a loop).
  std::int64_t loop_keyframes() const;

  FractalSettings settings_;
  double frame_rate_ = 25;
  FilterOptions options_;
  std::string name_;
  Drawing F_;
  Ifs G_;
  SuperIfs super_;                                 // animate superifs
  std::shared_ptr<TextureSequence> sequence_;      // animate superifs
  std::shared_ptr<const PreparedStealMap> table_;  // animate none
  std::unique_ptr<MapSchedule> schedule_;          // animate drift or superifs
};

}  // namespace ifsfx::engine
