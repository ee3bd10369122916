// SPDX-License-Identifier: Apache-2.0
// Collage fitting on real shapes (issues 15 and 32): every shape × every N of --maps is fitted
// once per method of --methods in one run: `collage` (the fit before issue 32: the collage W(L)
// and its iterates), `attractor` (issue 32: the attractor itself, from the best few starts),
// `noscan` (the attractor method without the self-similarity scan's starts, as it was before),
// `noreseed` (the attractor method without the re-seed of maps where the error is, as before it),
// `grow` (the attractor method growing from fewer maps on --grow-share of its stages, default
// 0.1) and `nogrow` (the attractor method without growing).
// The shapes: the silhouettes of bench/collage-shapes/ (holes, thin parts, letters, a logo with
// rings and text) and two fractals' own pictures drawn here: the attractor of the shipped
// barnsley-fern preset and that of the first FractalDB category of seed 1 (ifsfx dataset's
// search), each rendered 512² and taken as a shape.
// Per shape, N and method it prints IoU(L, A) on the working raster and on a raster 4 times
// finer (512² for the default 128², rendered in the target's own frame), whether the collage
// bound h(L, A) ≤ h(L, W(L)) / (1 − s) held, the wall seconds, the CPU seconds (all threads:
// 2 × wall on an idle 2-core machine, less on a shared one) and the thousands of evaluations
// the fit counted (FitOptions::max_evaluations: what a clocked fit's seconds bought); then the
// medians, and for shapes
// with holes IoU(L, L with its holes filled), the most a fit without holes can reach.
//   build/release/bench/collage_bench [--only fish,logo,fern] [--maps 4,6,8]
//       [--methods collage,attractor,noscan,noreseed,grow,nogrow] [--grow-share 0.1] [--seed 1]
//       [--max-seconds 30] [--max-evaluations N]
//       [--previews DIR]
//       [--truth 1]
// --truth 1: for the drawn fractals fitted with their own number of maps, a diagnosis line for
// the fit and for the fractal's own maps (conjugated into the working raster's frame): the
// attractor loss at each level, as the fit cuts it and as it was cut before, and the IoUs; with
// --previews also both attractors on the fine raster. A bench-only path: the true maps never
// reach the fit.
// Targets of issue 32 (at 512²): animal-like silhouettes ≥ 0.85 with 6 maps, the logo ≥ 0.75
// with 8, the fern ≥ 0.9 with 4, each in ≤ 30 s on 2 cores. It exits non-zero when a bound fails.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <sys/resource.h>
#include <opencv2/imgproc.hpp>

#include "collage/attractor_loss.h"
#include "collage/fit.h"
#include "collage/preview.h"
#include "collage/target.h"
#include "fractaldb/search.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "ifs/rng.h"
#include "ifs/sampling.h"

namespace {

using namespace ifsfx;

struct Shape {
  std::string name;
  cv::Mat mask;              // CV_8UC1, 255 on the shape, the picture's own size
  std::optional<Ifs> truth;  // a fractal's own picture: the IFS that drew it
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ',');) out.push_back(item);
  return out;
}

// The files of the manifest shapes.txt: "FILE N description", '#' starts a comment line.
std::vector<std::filesystem::path> manifest(const std::filesystem::path& folder) {
  const auto path = folder / "shapes.txt";
  std::ifstream in(path);
  if (!in) throw Error(ErrorKind::not_found, fmt::format("{}: cannot open", path.string()));
  std::vector<std::filesystem::path> files;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string file;
    if (!(fields >> file))
      throw Error(ErrorKind::parse,
                  fmt::format("{}:{}: expected 'FILE N description'", path.string(), number));
    files.push_back(folder / file);
  }
  return files;
}

// A fractal's own picture: its attractor rendered 512² (auto-framed), as a shape.
cv::Mat picture(const Ifs& ifs) {
  return render_attractor(ifs, {512, 512});
}

std::vector<Shape> shapes(const std::filesystem::path& folder,
                          const std::vector<std::string>& only) {
  const auto wanted = [&](const std::string& name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  std::vector<Shape> out;
  for (const auto& file : manifest(folder))
    if (wanted(file.stem().string()))
      out.push_back({file.stem().string(), collage::load_target(file)});
  const auto drawn = [&](const std::string& name, const Ifs& ifs) {
    if (wanted(name)) out.push_back({name, picture(ifs), ifs});
  };
  drawn("fern", load_ifs("barnsley-fern").ifs);
  drawn("fractaldb", fractaldb::search({.categories = 1}).front().ifs());
  return out;
}

struct Args {
  std::filesystem::path shapes = IFSFX_SOURCE_DIR "/bench/collage-shapes";
  std::vector<std::string> only;
  std::vector<int> maps = {4, 6, 8};
  std::vector<std::string> methods = {"collage", "attractor"};
  double max_seconds = 30;  // the fit's default
  long max_evaluations = 250000;
  int threads = 0;
  int size = 128;  // `ifsfx fit`'s default working raster
  std::filesystem::path previews;
  bool truth = false;       // --truth 1: the drawn fractals' own maps scored beside each fit
  double grow_share = 0.1;  // FitOptions::grow_share of the `grow` method
  std::uint64_t seed = 1;   // FitOptions::seed
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw Error(ErrorKind::parse, flag + ": expected a value");
    const std::string value = argv[++i];
    if (flag == "--shapes") {
      a.shapes = value;
    } else if (flag == "--only") {
      a.only = split(value);
    } else if (flag == "--maps") {
      a.maps.clear();
      for (const auto& n : split(value)) a.maps.push_back(std::stoi(n));
    } else if (flag == "--methods") {
      a.methods = split(value);
      for (const auto& m : a.methods)
        if (m != "collage" && m != "attractor" && m != "noscan" && m != "noreseed" && m != "grow" &&
            m != "nogrow")
          throw Error(
              ErrorKind::parse,
              "--methods: collage, attractor, noscan, noreseed, grow, nogrow (got " + m + ")");
    } else if (flag == "--seed") {
      a.seed = std::stoull(value);
    } else if (flag == "--grow-share") {
      a.grow_share = std::stod(value);
    } else if (flag == "--max-seconds") {
      a.max_seconds = std::stod(value);
    } else if (flag == "--max-evaluations") {
      a.max_evaluations = std::stol(value);
    } else if (flag == "--threads") {
      a.threads = std::stoi(value);
    } else if (flag == "--size") {
      a.size = std::stoi(value);
    } else if (flag == "--previews") {
      a.previews = value;
    } else if (flag == "--truth") {
      a.truth = value != "0";
    } else {
      throw Error(ErrorKind::parse,
                  "unknown option " + flag +
                      " (--shapes, --only, --maps, --methods, --grow-share, --seed, --max-seconds, "
                      "--max-evaluations, --threads, --size, --previews, --truth)");
    }
  }
  return a;
}

// CPU seconds (user + system, all threads) this process has used so far.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The maps of `truth` in the working raster's frame of its own picture `mask` (picture(), then
// working_raster with its default margin): T ∘ f ∘ T⁻¹, T the plane → unit square of that
// framing (render_attractor's auto-framed view, then working_raster's square frame).
std::vector<AffineMap> in_raster_frame(const Ifs& truth, const cv::Mat& mask) {
  const Viewport viewport = framed_viewport(truth, mask.size(), Sampling{});
  const cv::Rect box = cv::boundingRect(mask);
  const double margin = collage::FrameOptions{}.margin;
  const int side = static_cast<int>(std::ceil(std::max(box.width, box.height) / (1 - 2 * margin)));
  const double x0 = box.x + box.width / 2 - side / 2, y0 = box.y + box.height / 2 - side / 2;
  // Pixel (px, py) of the picture → (u, v) = ((px − x0) / side, 1 − (py − y0) / side).
  const AffineMap to_unit{1.0 / side, 0, 0, -1.0 / side, -x0 / side, 1 + y0 / side};
  const AffineMap t = to_unit.compose(viewport.plane_to_pixel());
  const AffineMap back = *t.inverse();
  std::vector<AffineMap> maps;
  for (const AffineMap& f : truth.maps) maps.push_back(t.compose(f).compose(back));
  return maps;
}

// One line of the diagnosis (--truth): the attractor loss of `maps` at the fit's levels, its
// terms, and IoU(L, A) on the working raster and 4× finer, as the fit's report measures them.
void print_diagnosis(const char* what, const cv::Mat& raster, const cv::Mat& fine,
                     const std::vector<AffineMap>& maps) {
  std::printf("  %-8s", what);
  // The levels as the fit cuts them (from the fine raster, any cover) and, in brackets, as they
  // were cut before (from the working raster, half cover).
  for (int level : {32, 64, raster.cols}) {
    const auto seed = stream_seed(1, static_cast<std::uint64_t>(level));
    const auto t =
        collage::AttractorLoss(fine, {.size = level, .seed = seed, .keep = 0}).terms(maps);
    const auto h = collage::AttractorLoss(raster, {.size = level, .seed = seed}).terms(maps);
    std::printf(" | L%d %.3f iou %.3f [%.3f %.3f]", level, t.value, t.iou, h.value, h.iou);
  }
  Ifs ifs;
  ifs.maps = maps;
  ifs.probabilities = default_probabilities(maps);
  std::printf(" | IoU %.3f IoU4x %.3f s %.3f\n", collage::attractor_iou(raster, ifs, {256, 1, 0}),
              collage::attractor_iou(fine, ifs, {64, 1, 0}), ifs.contraction());
}

struct Row {
  double iou = 0, fine_iou = 0, seconds = 0, cpu = 0;
  long evaluations = 0;  // what the fit counted (thousands printed: what its seconds bought)
  bool holds = true;
};

Row fit_one(const Args& args, const Shape& shape, int maps, const std::string& method) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const double cpu_start = cpu_seconds();
  const cv::Mat raster = collage::working_raster(shape.mask, {.size = args.size});
  collage::FitOptions options;
  options.maps = maps;
  options.method =
      method == "collage" ? collage::FitMethod::collage : collage::FitMethod::attractor;
  // noscan: the attractor method without the self-similarity scan's starts (before it).
  if (method == "noscan") options.similarity_starts = 0;
  // noreseed: the attractor method without the re-seed of maps where the error is (before it).
  if (method == "noreseed") options.reseed_share = 0;
  // grow / nogrow: the attractor method with and without growing from fewer maps.
  if (method == "grow") options.grow_share = args.grow_share;
  if (method == "nogrow") options.grow_share = 0;
  options.seed = args.seed;
  options.max_seconds = args.max_seconds;
  options.max_evaluations = args.max_evaluations;
  options.threads = args.threads;
  options.fine_target = collage::working_raster(shape.mask, {.size = 4 * args.size});
  const collage::FitResult result = collage::fit(raster, options);
  Row row;
  row.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  row.cpu = cpu_seconds() - cpu_start;
  row.iou = result.report.iou;
  row.fine_iou = result.report.fine_iou;
  row.holds = result.report.bound_holds();
  row.evaluations = result.evaluations;
  if (!args.previews.empty())
    write_image(args.previews / fmt::format("{}-{}-{}.png", shape.name, maps, method),
                collage::fit_preview(raster, result.ifs, {.threads = args.threads}));
  if (!args.previews.empty() && args.truth)
    write_image(args.previews / fmt::format("{}-{}-{}-fine.png", shape.name, maps, method),
                collage::fit_preview(options.fine_target, result.ifs, {.threads = args.threads}));
  if (args.truth && shape.truth && static_cast<int>(shape.truth->maps.size()) == maps) {
    std::printf("\n");
    print_diagnosis(method.c_str(), raster, options.fine_target, result.ifs.maps);
    const auto truth = in_raster_frame(*shape.truth, shape.mask);
    print_diagnosis("truth", raster, options.fine_target, truth);
    if (!args.previews.empty()) {
      Ifs ifs;
      ifs.maps = truth;
      ifs.probabilities = default_probabilities(truth);
      write_image(args.previews / fmt::format("{}-{}-truth.png", shape.name, maps),
                  collage::fit_preview(raster, ifs, {.threads = args.threads}));
      write_image(args.previews / fmt::format("{}-{}-truth-fine.png", shape.name, maps),
                  collage::fit_preview(options.fine_target, ifs, {.threads = args.threads}));
    }
  }
  return row;
}

// IoU(L, L with its holes filled), at the picture's own resolution: the most a fit whose
// attractor has no holes can reach (the butterfly's wing spots, the key's bow, the logo's "O").
double holeless_bound(const cv::Mat& mask) {
  cv::Mat framed(mask.rows + 2, mask.cols + 2, CV_8UC1, cv::Scalar(0));  // a frame of ground
  mask.copyTo(framed(cv::Rect(1, 1, mask.cols, mask.rows)));
  cv::floodFill(framed, cv::Point(0, 0), cv::Scalar(128));
  return static_cast<double>(cv::countNonZero(mask)) / cv::countNonZero(framed != 128);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

}  // namespace

int main(int argc, char** argv) try {
  const Args args = parse(argc, argv);
  const std::vector<Shape> all = shapes(args.shapes, args.only);
  std::printf(
      "collage_bench: %zu shapes; working raster %d, fine %d; --max-seconds %g, "
      "--max-evaluations %ld, threads %d\n",
      all.size(), args.size, 4 * args.size, args.max_seconds, args.max_evaluations, args.threads);
  std::printf("%-12s %2s", "shape", "N");
  for (const auto& method : args.methods)
    std::printf(" | %-9s %6s %6s %5s %5s %5s", method.c_str(), "IoU", "IoU4x", "sec", "cpu",
                "kevals");
  std::printf("\n");
  std::map<std::string, std::vector<double>> ious, fine, seconds;
  bool all_hold = true;
  for (const auto& shape : all)
    for (int maps : args.maps) {
      std::printf("%-12s %2d", shape.name.c_str(), maps);
      std::fflush(stdout);
      for (const auto& method : args.methods) {
        const Row row = fit_one(args, shape, maps, method);
        ious[method].push_back(row.iou);
        fine[method].push_back(row.fine_iou);
        seconds[method].push_back(row.seconds);
        all_hold = all_hold && row.holds;
        std::printf(" | %-9s %6.3f %6.3f %5.1f %5.1f %5ld", row.holds ? "" : "FAILS", row.iou,
                    row.fine_iou, row.seconds, row.cpu, row.evaluations / 1000);
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  std::printf("%-15s", "median");
  for (const auto& method : args.methods)
    std::printf(" | %-9s %6.3f %6.3f %5.1f %5s %5s", "", median(ious[method]), median(fine[method]),
                median(seconds[method]), "", "");
  std::printf("\n");
  std::string bounds;
  for (const auto& shape : all)
    if (const double b = holeless_bound(shape.mask); b < 0.995)
      bounds += fmt::format(" {} {:.3f}", shape.name, b);
  if (!bounds.empty())
    std::printf("holes: a fit without holes reaches at most IoU%s\n", bounds.c_str());
  if (!all_hold) std::printf("collage_bench: a collage bound FAILED\n");
  return all_hold ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "collage_bench: %s\n", e.what());
  return 2;
}
