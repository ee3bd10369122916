// SPDX-License-Identifier: Apache-2.0
// `ifsfx fit TARGET -n N -o OUT.toml`: collage-theorem fitting (paper §2, eq. 3;
// docs/design.md §6). Finds N affine maps whose attractor looks like the target's shape, writes
// them as a preset any other subcommand reads, and reports the collage theorem's numbers.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/stop_signals.h"
#include "collage/fit.h"
#include "collage/preview.h"
#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/utf8.h"
#include "ifs/view.h"
#include "run/fit_run.h"

namespace ifsfx::app {
namespace {

enum class PresetFormat { toml, fractint };

PresetFormat preset_format(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".toml") return PresetFormat::toml;
  if (ext == ".ifs") return PresetFormat::fractint;
  throw Error(ErrorKind::unsupported,
              fmt::format("{}: -o must end in .toml (native preset) or .ifs (Fractint) (got '{}')",
                          path.string(), ext));
}

// One Fractint entry: NAME { a b c d e f p } with a name of letters, digits, '-' and '_'.
std::string to_fractint(const Ifs& ifs, const std::string& comment) {
  std::string name;
  for (char c : ifs.name)
    name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  if (name.empty()) name = "fitted";
  std::string out = fmt::format("{} {{ ; {}\n", name, valid_utf8(comment));
  const auto p = effective_probabilities(ifs);
  for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
    const auto& m = ifs.maps[i];
    out += fmt::format("  {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g}\n", m.a, m.b, m.c, m.d,
                       m.e, m.f, p[i]);
  }
  return out + "}\n";
}

double finite_or_nan(double x) {
  return std::isfinite(x) ? x : std::numeric_limits<double>::quiet_NaN();
}

// The outputs under the policy, checked before any work; the number of maps.
void check_fit_outputs(const FitArgs& args, const std::filesystem::path& output,
                       const OutputOptions& policy) {
  check_output(output, policy);
  if (!args.preview.empty()) {
    check_writable_image(args.preview, policy);
    if (same_output(args.preview, output))
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("--preview {}: must differ from -o (got the same file)", args.preview));
  }
  check_fit_maps(args.maps);
}

// --progress: one line on stderr, redrawn in place. Every change of phase is shown; within a
// phase, five lines a second at most.
class FitProgressLine {
 public:
  void operator()(const collage::FitProgress& p) {
    const auto now = std::chrono::steady_clock::now();
    if (p.phase == last_phase_ && now - last_print_ < std::chrono::milliseconds(200)) return;
    last_print_ = now;
    last_phase_ = p.phase;
    const auto number = [](double x, int digits) {
      return std::isfinite(x) && x > 0 ? fmt::format("{:.{}f}", x, digits) : std::string("-");
    };
    fmt::print(stderr,
               "\r{:<9}  run {:>3}  evaluations {:>8}  objective {:>7}  best IoU {:>5}  {:.1f} s ",
               to_string(p.phase), p.run + 1, p.evaluations, number(p.best, 5),
               number(p.best_iou, 3), p.seconds);
  }

 private:
  std::chrono::steady_clock::time_point last_print_ =
      std::chrono::steady_clock::now() - std::chrono::seconds(1);
  std::optional<collage::FitPhase> last_phase_;
};

// The fit, with the progress line (if any) ended before the result or the error is printed.
collage::FitResult fit_with_progress(const cv::Mat& raster, collage::FitOptions options,
                                     bool progress) {
  FitProgressLine line;
  if (progress) options.progress = [&line](const collage::FitProgress& p) { line(p); };
  try {
    collage::FitResult result = collage::fit(raster, options);
    if (progress) std::fputs("\n", stderr);
    return result;
  } catch (...) {
    if (progress) std::fputs("\n", stderr);  // the error goes on a line of its own
    throw;
  }
}

// The preset and its preview appear together or not at all (a stop during the preview).
void write_fit_outputs(const FitArgs& args, const std::filesystem::path& output,
                       PresetFormat format, const OutputOptions& policy, const cv::Mat& raster,
                       const collage::FitResult& result) {
  const std::string summary = fit_summary(args, result);
  std::vector<OutputFile> staged;
  staged.emplace_back(output, policy);
  write_file(staged.back(), format == PresetFormat::toml ? to_toml(result.ifs, summary)
                                                         : to_fractint(result.ifs, summary));
  if (!args.preview.empty()) {
    staged.emplace_back(args.preview, policy);
    write_image(staged.back(),
                collage::fit_preview(raster, result.ifs,
                                     {.quality = 256, .seed = args.seed, .threads = args.threads}));
  }
  commit_together(staged);
}

void print_json_report(const FitArgs& args, const cv::Mat& raster,
                       const collage::FitResult& result) {
  const collage::CollageReport& r = result.report;
  nlohmann::json maps = nlohmann::json::array();
  for (const auto& m : result.ifs.maps) maps.push_back(m.coefficients());
  nlohmann::json parts = nlohmann::json::array();
  for (const auto& part : r.parts)
    parts.push_back({{"area", part.area},
                     {"centre", {part.centre.x, part.centre.y}},
                     {"covered", part.covered}});
  const nlohmann::json report = {
      {"target", valid_utf8(args.target)},
      {"output", valid_utf8(args.output)},
      {"maps", args.maps},
      {"size", raster.cols},
      {"seed", args.seed},
      {"runs", result.runs},
      {"evaluations", result.evaluations},
      {"seconds", result.seconds},
      {"time_capped", result.time_capped},
      {"collage_distance", r.collage_distance},
      {"contraction", r.contraction},
      {"lower_bound", r.lower_bound},
      {"upper_bound", finite_or_nan(r.upper_bound)},
      {"hausdorff", finite_or_nan(r.hausdorff)},
      {"raster_error", r.raster_error},
      {"bound_holds", r.bound_holds()},
      {"iou", r.iou},
      {"collage_iou", r.collage_iou},
      {"fine_iou", r.fine_iou},
      {"fine_size", r.fine_size},
      {"interrupted", result.interrupted},
      {"pixel", r.pixel},
      {"clipped", r.clipped},
      {"init", args.init == collage::Initialisation::moments ? "moments" : "search"},
      {"method", args.method == collage::FitMethod::collage ? "collage" : "attractor"},
      {"parts", parts},
      {"ifs",
       {{"name", result.ifs.name}, {"maps", maps}, {"probabilities", result.ifs.probabilities}}},
  };
  std::printf("%s\n", report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

void print_text_report(const FitArgs& args, const cv::Mat& raster,
                       const collage::FitResult& result) {
  const collage::CollageReport& r = result.report;
  const double px = 1 / r.pixel;
  fmt::print(
      "{} -> {}: {} maps on a {}x{} working raster; {} runs, {} evaluations, {:.1f} s{}\n"
      "  distances in units of the working square's side (1 pixel = {:.4f})\n"
      "  collage distance h(L, W(L))   {:.4f}  ({:.1f} px)\n"
      "  contraction s                 {:.4f}\n"
      "  collage theorem               {:.4f} <= h(L, A) <= {:.4f}\n"
      "  measured h(L, A)              {:.4f}  ({:.1f} px, +-{:.1f} px raster){}\n"
      "  IoU(L, A)                     {:.3f} at {}x{}{}  (collage IoU(L, W(L)) {:.3f})\n",
      args.target, args.output, args.maps, raster.cols, raster.rows, result.runs,
      result.evaluations, result.seconds,
      result.interrupted   ? " (interrupted)"
      : result.time_capped ? " (stopped by --max-seconds)"
                           : "",
      r.pixel, r.collage_distance, r.collage_distance * px, r.contraction, r.lower_bound,
      r.upper_bound, r.hausdorff, r.hausdorff * px, r.raster_error * px,
      r.bound_holds() ? "" : "  ABOVE THE BOUND: please report this as a bug", r.iou, raster.cols,
      raster.rows,
      r.fine_size > 0 ? fmt::format(", {:.3f} at {}x{}", r.fine_iou, r.fine_size, r.fine_size) : "",
      r.collage_iou);
  // Components of L the attractor leaves (mostly) out: too small for a map of their own, and
  // not reached by a neighbour's.
  for (const auto& part : r.parts)
    if (part.covered < 0.5)
      fmt::print("  part not covered: {} px around ({:.3f}, {:.3f}), {:.0f}% of it in A\n",
                 part.area, part.centre.x, part.centre.y, 100 * part.covered);
  if (r.clipped)
    std::printf(
        "  note: the attractor reaches beyond the measuring canvas; h(L, A) is a lower "
        "estimate\n");
}

void run_fit(const FitArgs& args) {
  const std::filesystem::path output = args.output;
  const PresetFormat format = preset_format(output);
  // The output policy: neither output replaces the target image, and they differ.
  StopSignals signals;
  OutputOptions policy{.cancel = StopSignals::token()};
  policy.inputs.add(args.target);
  check_fit_outputs(args, output, policy);

  const cv::Mat raster = fit_raster(args);

  collage::FitOptions options = fit_options(args, policy.cancel);
  options.fine_target = fit_fine_raster(args);
  const collage::FitResult result = fit_with_progress(raster, options, args.progress);
  // Stopped with a fit in hand: the best so far is written all the same, then the stop reported.
  OutputOptions write_policy = policy;
  if (result.interrupted) write_policy.cancel = {};
  write_fit_outputs(args, output, format, write_policy, raster, result);
  if (args.json)
    print_json_report(args, raster, result);
  else
    print_text_report(args, raster, result);
  if (result.interrupted)
    throw Error(ErrorKind::interrupted,
                fmt::format("fit: interrupted; the best IFS so far is in {}", output.string()));
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  auto* cmd = app.add_subcommand(
      "fit", "Fit an IFS to a shape by the collage theorem: its attractor looks like the target");
  cmd->add_option("target", args->target,
                  "Target image; the shape is its alpha channel, else its dark pixels (Otsu)")
      ->required();
  cmd->add_option("-o,--output", args->output, "Preset to write: .toml (native) or .ifs (Fractint)")
      ->required();
  cmd->add_option("-n,--maps", args->maps, "Number of affine maps N (1..32)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed: the same seed gives the same maps")
      ->capture_default_str()
      ->check(not_negative());
  const std::map<std::string, collage::Initialisation> inits{
      {"moments", collage::Initialisation::moments}, {"search", collage::Initialisation::search}};
  cmd->add_option("--init", args->init,
                  "Starting maps. search: fractal-compression range/domain search over several "
                  "partitions of the shape (one part per component at least), combined and "
                  "refined; moments: split the shape and match each part's moments (faster, "
                  "for convex, nearly self-similar shapes)")
      ->transform(choice(inits))
      ->default_str("search")
      ->option_text(choices_text(inits, "search"));
  const std::map<std::string, collage::FitMethod> methods{
      {"attractor", collage::FitMethod::attractor}, {"collage", collage::FitMethod::collage}};
  cmd->add_option("--method", args->method,
                  "What is optimised after the start. attractor: the rendered attractor itself, "
                  "coarse to fine, from the best few starts, with random escapes; collage: the "
                  "collage W(L) and its iterates (the fit before issue 32)")
      ->transform(choice(methods))
      ->default_str("attractor")
      ->option_text(choices_text(methods, "attractor"));
  cmd->add_option("--threshold", args->threshold,
                  "Grey (or alpha) level in [0, 1] between shape and background; default: Otsu "
                  "(alpha: 0.5)")
      ->check(number_in(0, 1));
  cmd->add_flag("--invert", args->invert, "Swap shape and background (light shape, clear alpha)");
  cmd->add_option("--size", args->size, "Working raster S or SxS (pixels, square)")
      ->capture_default_str();
  cmd->add_option("--max-seconds", args->max_seconds,
                  "Stop the search after this many seconds (0: no cap; then the same seed gives "
                  "the same maps on any machine)")
      ->capture_default_str()
      ->check(number_in(0, kMaxFitSeconds));
  cmd->add_option("--max-evaluations", args->max_evaluations, "Objective evaluations over all runs")
      ->capture_default_str()
      ->check(CLI::Range(2L, kMaxFitEvaluations));
  cmd->add_option("--reseed-share", args->reseed_share,
                  "Attractor method: the share of its stages spent re-seeding the maps that pay "
                  "least onto the parts of the shape the attractor misses (0: none)")
      ->capture_default_str()
      ->check(number_in(0, kMaxFitShare));
  cmd->add_option("--grow-share", args->grow_share,
                  "Attractor method: the share of its stages spent growing from fewer maps: the "
                  "two that pay least dropped, then maps added one at a time where the attractor "
                  "misses most, each followed by a re-optimisation (0: none)")
      ->capture_default_str()
      ->check(number_in(0, kMaxFitShare));
  cmd->add_option("--preview", args->preview,
                  "Write target, collage and attractor side by side to this image, each of the "
                  "N pieces in its own colour (missed pixels dark grey, spill dimmed)");
  cmd->add_flag("--json", args->json, "Print the report as a JSON object on stdout");
  cmd->add_flag("--progress", args->progress,
                "Show the phase (partition, search, refine), the objective and the best IoU so "
                "far (stderr)");
  add_threads_option(*cmd, args->threads);
  cmd->callback([args] { run_fit(*args); });
}

}  // namespace ifsfx::app
