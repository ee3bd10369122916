// SPDX-License-Identifier: Apache-2.0
// Each variation of flam3's set drawn by flam3-render and by ifsfx's own chaos game (through
// flame/xform_eval.h) on the same grid: the Pearson correlation of flam3's luminance with
// log(1 + count) of ours, and of ours with x and y swapped (a formula that mixes up θ = atan2(x, y)
// with φ = atan2(y, x), or sin with cos, correlates better swapped). Prints one line per
// variation; exits 1 when one correlates below --min (default 0.8) or better swapped.
//   variations_vs_flam3 [--min 0.8] [--only NAME,NAME…] [--keep DIR] [--offset 0.37]
// (--offset: added to every parameter's default, so that parameters are not all 0 or 1)
// Needs flam3-render on PATH (exit 77, "skipped", without it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "flame/flame_write.h"
#include "flame/variations.h"
#include "flame/xform_eval.h"
#include "ifs/image_io.h"

namespace fs = std::filesystem;
using namespace ifsfx;
using namespace ifsfx::flame;

namespace {

constexpr int kSide = 128;
constexpr double kQuality = 60;

// flam3's parameters (an Ember-only one keeps its default, which flam3 does not read).
bool flam3_knows(std::string_view p) {
  return p != "log_base" && p != "waves2_scalez" && p != "waves2_freqz" && p != "auger_half_scale";
}

Flame test_flame(const Variation& v, double offset) {
  Flame f;
  f.name = std::string(v.name);
  VariationTerm t{.id = v.id, .weight = 1, .params = default_parameters(v)};
  for (std::size_t k = 0; k < t.params.size(); ++k)
    if (flam3_knows(v.parameters[k].name)) t.params[k] += offset;
  Xform a{.pre = from_flam3_coefs({0.6, 0.25, -0.2, 0.55, 0.15, -0.1}), .weight = 0.5, .colour = 0};
  (v.place == VariationPlace::pre_only ? a.pre_variations : a.variations).push_back(t);
  if (v.place == VariationPlace::pre_only)
    a.variations.push_back({.id = find_variation("linear")->id, .weight = 1});
  Xform b{.pre = from_flam3_coefs({0.5, 0, 0, 0.5, -0.4, 0.3}),
          .weight = 0.5,
          .colour = 1,
          .variations = {{.id = find_variation("linear")->id, .weight = 1}}};
  f.xforms = {a, b};
  for (auto& c : f.palette.colours) c = {1, 1, 1, 1};
  f.filtering.filter_radius = 0;
  f.filtering.estimator_radius = 0;
  f.quality = kQuality;
  f.camera.width = f.camera.height = kSide;
  return f;
}

// The orbit's points after a burn-in, non-finite points re-seeded.
std::vector<Point> orbit(const Flame& f, std::size_t n) {
  Rng rng(12345);
  std::vector<Point> out;
  Point p{rng.uniform() * 2 - 1, rng.uniform() * 2 - 1};
  const double w0 = f.xforms[0].weight / (f.xforms[0].weight + f.xforms[1].weight);
  for (std::size_t i = 0; out.size() < n && i < 4 * n; ++i) {
    p = apply_xform(f.xforms[rng.uniform() < w0 ? 0 : 1], p, rng);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e10 ||
        std::abs(p.y) > 1e10) {
      p = {rng.uniform() * 2 - 1, rng.uniform() * 2 - 1};
      continue;
    }
    if (i >= 20) out.push_back(p);
  }
  return out;
}

// The camera: the middle 96% of the points in x and in y.
void frame(Flame& f, const std::vector<Point>& pts) {
  std::vector<double> xs, ys;
  for (const Point& p : pts) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  auto q = [](std::vector<double>& v, double t) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(t * (v.size() - 1)), v.end());
    return v[static_cast<std::size_t>(t * (v.size() - 1))];
  };
  const double x0 = q(xs, 0.02), x1 = q(xs, 0.98), y0 = q(ys, 0.02), y1 = q(ys, 0.98);
  f.camera.center = {(x0 + x1) / 2, (y0 + y1) / 2};
  f.camera.scale = kSide / std::max({x1 - x0, y1 - y0, 1e-6}) * 0.9;
}

// log(1 + count) of the points on flam3's grid (row = (y − cy)·scale + H/2: y down).
cv::Mat density(const Flame& f, const std::vector<Point>& pts, bool swapped) {
  cv::Mat d(kSide, kSide, CV_64F, 0.0);
  const Camera& c = f.camera;
  for (const Point& p0 : pts) {
    const Point p =
        swapped ? Point{c.center.x + (p0.y - c.center.y), c.center.y + (p0.x - c.center.x)} : p0;
    const double col = (p.x - c.center.x) * c.scale + kSide / 2.0;
    const double row = (p.y - c.center.y) * c.scale + kSide / 2.0;
    if (col >= 0 && row >= 0 && col < kSide && row < kSide)
      d.at<double>(static_cast<int>(row), static_cast<int>(col)) += 1;
  }
  cv::Mat out;
  cv::log(d + 1, out);
  return out;
}

double correlation(const cv::Mat& a, const cv::Mat& b) {
  cv::Scalar ma, sa, mb, sb;
  cv::meanStdDev(a, ma, sa);
  cv::meanStdDev(b, mb, sb);
  if (sa[0] == 0 || sb[0] == 0) return 0;
  return cv::mean((a - ma[0]).mul(b - mb[0]))[0] / (sa[0] * sb[0]);
}

}  // namespace

int main(int argc, char** argv) {
  double min_corr = 0.8, offset = 0.37;
  std::string only;
  fs::path dir = fs::temp_directory_path() / "ifsfx_variations_vs_flam3";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--min") min_corr = std::atof(argv[i + 1]);
    if (a == "--only") only = argv[i + 1];
    if (a == "--keep") dir = argv[i + 1];
    if (a == "--offset") offset = std::atof(argv[i + 1]);
  }
  if (std::system("command -v flam3-render > /dev/null 2>&1") != 0) {
    std::puts("skipped: flam3-render (flam3-utils) is not installed");
    return 77;
  }
  fs::create_directories(dir);
  // flam3's own variations: those of the paper, flam3's later ones and the complex functions.
  const std::size_t flam3_count = find_variation("coth")->id + 1;
  int bad = 0;
  for (std::size_t id = 0; id < flam3_count; ++id) {
    const Variation& v = variations()[id];
    if (!only.empty() &&
        ("," + only + ",").find("," + std::string(v.name) + ",") == std::string::npos)
      continue;
    Flame f = test_flame(v, offset);
    const std::vector<Point> pts = orbit(f, static_cast<std::size_t>(kQuality * kSide * kSide));
    frame(f, pts);
    const fs::path in = dir / (f.name + ".flame"), out = dir / (f.name + ".png");
    std::ofstream(in) << flame_xml(f);
    const std::string cmd =
        "env out=" + out.string() + " seed=7 flam3-render < " + in.string() + " > /dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) {
      std::printf("%-14s flam3-render failed\n", f.name.c_str());
      ++bad;
      continue;
    }
    cv::Mat grey, theirs;
    const cv::Mat img = read_image(out).pixels;
    cv::cvtColor(img, grey, img.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
    grey.convertTo(theirs, CV_64F);
    const cv::Mat ours = density(f, pts, false);
    double mx = 0;
    cv::minMaxLoc(ours, nullptr, &mx);
    cv::Mat side;
    cv::hconcat(theirs, ours * (255 / std::max(mx, 1e-9)), side);
    side.convertTo(side, CV_8U);
    write_image(dir / (f.name + "_flam3_ours.png"), side);
    const double c = correlation(theirs, ours);
    const double s = correlation(theirs, density(f, pts, true));
    const bool ok = c >= min_corr && c >= s;
    bad += !ok;
    std::printf("%-14s %6.3f  swapped %6.3f  %s\n", f.name.c_str(), c, s, ok ? "" : "<-- differs");
  }
  return bad ? 1 : 0;
}
