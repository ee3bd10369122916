// SPDX-License-Identifier: Apache-2.0
// `ifsfx dataset render CATEGORIES -o FOLDER`: a FractalDB dataset (formula-driven supervised
// learning) as the reference generator's make_fractaldb.py writes it, and `ifsfx dataset search
// -o FOLDER`: its category search (ifs_search.py). docs/dataset.md.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/progress_bar.h"
#include "cli/stop_signals.h"
#include "fractaldb/dataset.h"
#include "fractaldb/search.h"
#include "ifs/error.h"
#include "ifs/output_file.h"

namespace ifsfx::app {
namespace {
namespace fs = std::filesystem;
namespace db = fractaldb;

struct RenderArgs {
  std::vector<std::string> categories;
  std::string output;
  std::string weights;
  double weight_step = 0;
  std::string draw = "patch_gray";
  std::string size = "512x512";
  std::string padding = "6x6";
  int iterations = db::DrawSettings{}.iterations;
  int instances = db::DatasetSpec{}.instances;
  std::uint64_t seed = db::DatasetSpec{}.seed;
  int threads = 0;
  bool rgb_png = false;
  bool quiet = false;
};

struct SearchArgs {
  std::string output;
  db::SearchOptions options;
  bool quiet = false;
};

// "N" (N×N) or "WxH"; `zero` allows 0 (a padding).
cv::Size side_pair(const std::string& text, const std::string& what, bool zero) {
  if (text.find('x') == std::string::npos) {
    int side = -1;
    try {
      std::size_t used = 0;
      side = std::stoi(text, &used);
      if (used != text.size()) side = -1;
    } catch (const std::exception&) {
      side = -1;
    }
    if (side < (zero ? 0 : 1))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: expected N or WxH (got '{}')", what, text));
    return {side, side};
  }
  if (!zero) return size_option(text, what);
  const std::size_t x = text.find('x');
  return {side_pair(text.substr(0, x), what, true).width,
          side_pair(text.substr(x + 1), what, true).width};
}

// The categories named: CSV files, and folders of them (every *.csv below), sorted by name.
std::vector<db::Category> read_categories(const std::vector<std::string>& specs,
                                          InputFiles& inputs) {
  std::vector<fs::path> files;
  for (const std::string& spec : specs) {
    std::error_code ec;
    if (fs::is_directory(spec, ec)) {
      const auto found = db::category_files(spec);
      if (found.empty())
        throw Error(ErrorKind::not_found, fmt::format("{}: no category CSV files in it", spec));
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.emplace_back(spec);
    }
  }
  std::vector<db::Category> categories;
  for (const fs::path& file : files) {
    inputs.add(file);
    categories.push_back(db::read_category(file));
  }
  std::stable_sort(categories.begin(), categories.end(),
                   [](const db::Category& a, const db::Category& b) { return a.name < b.name; });
  return categories;
}

void run_render(const RenderArgs& args) {
  if (!args.weights.empty() && args.weight_step > 0)
    throw Error(ErrorKind::invalid_argument,
                "--weights: give a weight file or --weight-step, not both");
  StopSignals signals;
  db::DatasetOptions options{.threads = args.threads, .rgb_png = args.rgb_png};
  options.output.cancel = StopSignals::token();
  db::DatasetSpec spec;
  spec.settings.draw = db::parse_draw_type(args.draw, "--draw");
  spec.settings.size = side_pair(args.size, "--size", false);
  spec.settings.padding = side_pair(args.padding, "--padding", true);
  spec.settings.iterations = args.iterations;
  spec.instances = args.instances;
  spec.seed = args.seed;
  db::check(spec.settings);
  spec.categories = read_categories(args.categories, options.output.inputs);
  if (!args.weights.empty()) {
    options.output.inputs.add(args.weights);
    spec.weights = db::read_weights(args.weights);
  } else {
    spec.weights =
        db::weights_table(args.weight_step > 0 ? args.weight_step : db::kDefaultWeightStep);
  }
  db::check(spec);

  const bool tty = isatty(fileno(stderr)) != 0;
  if (!args.quiet) {
    options.progress = [bar =
                            ProgressBar(tty, "images", "images/s")](const db::DatasetProgress& p) {
      bar(p.done, p.total, p.seconds, p.finished);
    };
    options.progress_interval = tty ? 0.25 : 2.0;
  }
  db::DatasetStats stats;
  try {
    stats = db::write_dataset(spec, args.output, options);
  } catch (const Error& e) {
    if (!args.quiet && tty) std::fputs("\n", stderr);
    if (e.kind() == ErrorKind::interrupted)
      throw Error(ErrorKind::interrupted,
                  fmt::format("interrupted: the images written are whole; run the same command "
                              "again to write the rest into {}",
                              args.output));
    throw;
  }
  if (!args.quiet)
    fmt::print(
        "{} categories x {} weights x {} x 4 flips ({}, {}x{}): {} images written, {} "
        "already there -> {}\n",
        spec.categories.size(), spec.weights.size(),
        db::instances_drawn(spec) == 1 ? std::string("1 picture")
                                       : fmt::format("{} instances", spec.instances),
        db::to_string(spec.settings.draw), spec.settings.size.width, spec.settings.size.height,
        stats.written, stats.skipped, args.output);
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void run_search(const SearchArgs& args) {
  StopSignals signals;
  OutputOptions output{.cancel = StopSignals::token()};
  std::error_code ec;
  fs::create_directories(args.output, ec);
  if (ec || !fs::is_directory(args.output))
    throw Error(ErrorKind::io, fmt::format("{}: cannot make the folder ({})", args.output,
                                           ec ? ec.message() : "a file is in the way"));
  db::SearchOptions options = args.options;
  options.cancel = output.cancel;
  const bool tty = isatty(fileno(stderr)) != 0;
  const ProgressBar bar(tty, "categories", "categories/s");
  int written = 0, kept = 0;
  std::int64_t tried = 0;
  double last = -1;
  try {
    db::search(
        options,
        [&](const db::Category& category, double) {
          // A category already there must be this one: a rerun resumes the same search.
          const fs::path path = fs::path(args.output) / (category.name + ".csv");
          const std::string text = db::category_text(category);
          if (fs::exists(path, ec)) {
            if (file_text(path) != text)
              throw Error(ErrorKind::invalid_argument,
                          fmt::format("{}: holds another category than this search finds (a "
                                      "search with other settings?); use another folder",
                                      path.string()));
            ++kept;
            return;
          }
          write_file(path, text, output);
          ++written;
        },
        [&](const db::SearchProgress& p) {
          tried = p.tried;
          if (args.quiet || (p.seconds - last < (tty ? 0.25 : 2.0) && p.found < p.wanted)) return;
          last = p.seconds;
          bar(p.found, p.wanted, p.seconds, p.found == p.wanted);
        });
  } catch (const Error& e) {
    if (!args.quiet && tty) std::fputs("\n", stderr);
    if (e.kind() == ErrorKind::interrupted)
      throw Error(ErrorKind::interrupted,
                  fmt::format("interrupted: {} categories written whole; run the same command "
                              "again to go on",
                              written + kept));
    throw;
  }
  if (!args.quiet)
    fmt::print(
        "{} categories of filling rate >= {} from {} candidates: {} written, {} already "
        "there -> {}\n",
        args.options.categories, args.options.rate, tried, written, kept, args.output);
}

}  // namespace

void add_dataset_command(CLI::App& app) {
  auto* dataset = app.add_subcommand(
      "dataset",
      "FractalDB datasets for formula-driven supervised learning, as the reference generator "
      "(hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch) makes them (docs/dataset.md)");
  dataset->require_subcommand(1);

  auto r = std::make_shared<RenderArgs>();
  auto* render = dataset->add_subcommand(
      "render",
      "Render categories x weights x instances x 4 flips into FOLDER/NAME/"
      "NAME_WW_count_I_flipT.png (make_fractaldb.py's layout, for torchvision's ImageFolder). "
      "Images already there are kept: run it again to resume a stopped run");
  render
      ->add_option("categories", r->categories,
                   "Category CSV files (rows a,b,c,d,e,f,p), or folders of them (every *.csv "
                   "below, as csv0/ csv1/ ...); labels follow their names' order")
      ->required();
  render->add_option("-o,--output", r->output, "Dataset folder (made if needed)")->required();
  render->add_option("--weights", r->weights,
                     "Weight CSV (rows wa,wb,wc,wd,we,wf multiplying a..f), e.g. the reference's "
                     "weights_0.4.csv; default: --weight-step 0.1");
  render
      ->add_option("--weight-step", r->weight_step,
                   "The reference's weights_K.csv table without the file: a..f each times "
                   "1-2K, 1-K, 1+K, 1+2K, and all ones (25 weights) [default: 0.1]")
      ->check(number_in(0, 10, true));
  render
      ->add_option("--draw", r->draw,
                   "{point_gray,point_color,patch_gray,patch_color}: points, or 3x3 patches "
                   "masked at random; grey or coloured by point")
      ->capture_default_str();
  render->add_option("--size", r->size, "Image size, WxH or N")->capture_default_str();
  render->add_option("--padding", r->padding, "Pixels left free at each side, WxH or N")
      ->capture_default_str();
  render->add_option("--iterations", r->iterations, "Chaos-game points per picture")
      ->capture_default_str()
      ->check(CLI::Range(1, 1'000'000'000));
  render
      ->add_option("--instances", r->instances,
                   "Pictures per category and weight (patch types; the point types draw one)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  render->add_option("--seed", r->seed, "Seed of the patch masks")
      ->capture_default_str()
      ->check(not_negative());
  add_threads_option(*render, r->threads);
  render->add_flag("--rgb-png", r->rgb_png,
                   "Write 24-bit RGB PNGs as the reference does, instead of indexed-colour PNGs "
                   "with the same pixels (smaller, and many times faster to write)");
  render->add_flag("-q,--quiet", r->quiet, "No progress bar or summary");
  render->callback([r] { run_render(*r); });

  auto s = std::make_shared<SearchArgs>();
  auto* search = dataset->add_subcommand(
      "search",
      "FractalDB's category search: random IFSs of 2 to 7 maps kept when their picture fills "
      "at least --rate of it, written as FOLDER/00000.csv ... (ifs_search.py, with NumPy's "
      "draws: the same categories for the same seed). A rerun resumes");
  search->add_option("-o,--output", s->output, "Folder of the category CSVs (made if needed)")
      ->required();
  search->add_option("-n,--categories", s->options.categories, "Categories to find")
      ->capture_default_str()
      ->check(CLI::Range(1, 1'000'000));
  search
      ->add_option("--rate", s->options.rate,
                   "Least filling rate: lit pixels over all pixels of the 512x512 point picture")
      ->capture_default_str()
      ->check(number_in(0, 1));
  search->add_option("--points", s->options.points, "Chaos-game points per candidate")
      ->capture_default_str()
      ->check(CLI::Range(2, 100'000'000));
  search->add_option("--seed", s->options.seed, "numpy.random.seed of the search")
      ->capture_default_str()
      ->check(not_negative());
  search->add_flag("-q,--quiet", s->quiet, "No progress bar or summary");
  search->callback([s] { run_search(*s); });
}

}  // namespace ifsfx::app
