// SPDX-License-Identifier: Apache-2.0
#include "fractaldb/dataset.h"

#include <chrono>
#include <memory>
#include <mutex>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::fractaldb {
namespace fs = std::filesystem;
namespace {

void make_folder(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder, ec))
    throw Error(ErrorKind::io,
                fmt::format("{}: cannot make the folder ({})", folder.string(),
                            ec ? ec.message() : std::string("a file is in the way")));
}

// Counts and reports from the workers, one report at a time, at most one per interval.
class Reporter {
 public:
  Reporter(const DatasetOptions& options, std::int64_t total)
      : options_(options), start_(std::chrono::steady_clock::now()) {
    progress_.total = total;
  }

  void add(std::int64_t written, std::int64_t skipped) {
    const std::lock_guard lock(mutex_);
    progress_.done += written + skipped;
    progress_.skipped += skipped;
    const auto now = std::chrono::steady_clock::now();
    if (options_.progress &&
        std::chrono::duration<double>(now - last_).count() >= options_.progress_interval) {
      last_ = now;
      progress_.seconds = std::chrono::duration<double>(now - start_).count();
      options_.progress(progress_);
    }
  }

  DatasetStats finish() {
    const std::lock_guard lock(mutex_);
    progress_.finished = true;
    progress_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (options_.progress) options_.progress(progress_);
    return {progress_.done - progress_.skipped, progress_.skipped};
  }

 private:
  const DatasetOptions& options_;
  std::mutex mutex_;
  DatasetProgress progress_;
  std::chrono::steady_clock::time_point start_, last_{};
};

}  // namespace

DatasetStats write_dataset(const DatasetSpec& spec, const fs::path& folder,
                           const DatasetOptions& options) {
  check(spec);
  resolve_threads(options.threads);
  make_folder(folder);
  for (const Category& category : spec.categories) make_folder(folder / category.name);
  const std::vector<double> draws = reference_draws(spec.settings.iterations);
  const int instances = instances_drawn(spec);
  const std::size_t weights = spec.weights.size();
  const std::size_t groups = spec.categories.size() * weights;
  // Per worker: its PNG encoder, walk buffers and canvas, kept from one group to the next.
  struct Workspace {
    PngEncoder encoder;
    Points points;
    WalkBuffers buffers;
    cv::Mat canvas;
  };
  std::vector<std::unique_ptr<Workspace>> workspaces(
      static_cast<std::size_t>(worker_count(groups, options.threads)));
  Reporter reporter(options, image_count(spec));
  const CancelToken& cancel = options.output.cancel;

  // A worker takes one category and weight: its walk is shared by its instances and flips.
  parallel_for(groups, options.threads, [&](std::size_t group, int worker) {
    cancel.check("dataset");
    auto& space = workspaces[static_cast<std::size_t>(worker)];
    if (!space) space = std::make_unique<Workspace>();
    struct Missing {
      ImageKey key;
      fs::path path;
    };
    std::vector<Missing> missing;
    std::int64_t present = 0;
    for (int instance = 0; instance < instances; ++instance)
      for (int flip = 0; flip < kFlips; ++flip) {
        const ImageKey key{group / weights, group % weights, instance, flip};
        fs::path path = folder / image_path(spec, key);
        std::error_code ec;
        if (fs::exists(path, ec))
          ++present;
        else
          missing.push_back({key, std::move(path)});
      }
    reporter.add(0, present);
    if (missing.empty()) return;
    walk(spec.categories[group / weights], spec.weights[group % weights], spec.settings, draws,
         space->points, space->buffers);
    int drawn = -1;
    for (const Missing& m : missing) {
      cancel.check("dataset");
      if (m.key.instance != drawn) {
        draw(space->points, spec.settings, mask_seed(spec, m.key), space->canvas);
        drawn = m.key.instance;
      }
      OutputFile out(m.path, options.output);
      write_file(out, space->encoder.encode(space->canvas, m.key.flip, spec.settings.draw,
                                            options.rgb_png));
      out.commit();
      reporter.add(1, 0);
    }
  });
  return reporter.finish();
}

}  // namespace ifsfx::fractaldb
