// SPDX-License-Identifier: Apache-2.0
// SuperIFS textures (issue targets on 2 cores): a converged 2048×2048 steal-mode texture of the
// paper's Fig. 4 superIFS with V = 3 (≤ 1 s), and each further step of a 1920×1080 texture
// sequence (≥ 10 steps/s). Every run also checks its result. `--threads N` (before Google
// Benchmark's own flags) gives every case N workers; the default, 0, is all cores.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ifs/parallel.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace {

using namespace ifsfx;

int threads_option = 0;  // --threads, set once in main() before any case runs

// A smooth colourful source, so that the stolen texture is a real image.
cv::Mat gradient_source(cv::Size size) {
  cv::Mat m(size, CV_8UC3);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      m.at<cv::Vec3b>(r, c) = {static_cast<uchar>(255 * c / size.width),
                               static_cast<uchar>(255 * r / size.height),
                               static_cast<uchar>((c + r) % 256)};
  return m;
}

void check(benchmark::State& state, bool ok, const char* what) {
  if (!ok) state.SkipWithError(what);
}

void texture_steal_2048_fig4_v3(benchmark::State& state) {
  const SuperIfs super = load_superifs("paper-fig4").super;
  const cv::Size size{2048, 2048};
  TextureOptions options{.sampling = {.seed = 1, .threads = threads_option},
                         .count = 3,
                         .mode = TextureMode::steal,
                         .source = gradient_source({1024, 1024})};
  for (auto _ : state) {
    const cv::Mat t = render_texture(super, size, options);
    benchmark::DoNotOptimize(t.data);
    check(state, t.size() == size && cv::countNonZero(t.reshape(1)) > 0, "empty texture");
  }
  state.counters["steps"] = default_steps(super, size);
}
BENCHMARK(texture_steal_2048_fig4_v3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void texture_attractor_2048_fig4_v3(benchmark::State& state) {
  const SuperIfs super = load_superifs("paper-fig4").super;
  for (auto _ : state) {
    const cv::Mat t =
        render_texture(super, {2048, 2048}, {.sampling = {.threads = threads_option}, .count = 3});
    benchmark::DoNotOptimize(t.data);
  }
}
BENCHMARK(texture_attractor_2048_fig4_v3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// One further step of a sequence alone (the V buffers), with its new steal map (what the video
// filter asks for each step: step + exact descent), and with the source coloured in (what
// `ifsfx texture --frames` writes: step + descent + apply). The differences say where a step goes.
enum class StepPart { buffers, map, frame };

void sequence_step_1920x1080(benchmark::State& state, const char* preset, StepPart part) {
  const SuperIfs super = load_superifs(preset).super;
  const cv::Mat source = gradient_source({1920, 1080});
  TextureSequence seq(super, {1920, 1080},
                      {.sampling = {.threads = threads_option},
                       .count = 3,
                       .mode = TextureMode::steal,
                       .source = source});
  int previous = seq.steps_done();
  for (auto _ : state) {
    if (part == StepPart::frame) {
      seq.step();
      const cv::Mat frame = seq.frame();
      benchmark::DoNotOptimize(frame.data);
    } else if (part == StepPart::map) {
      const StealMap map = seq.next_map();
      benchmark::DoNotOptimize(map.source_uv.data);
    } else {
      seq.step();
      benchmark::DoNotOptimize(seq.buffers().mask(0).data);
    }
  }
  check(state, seq.steps_done() == previous + static_cast<int>(state.iterations()), "no steps");
  state.SetItemsProcessed(state.iterations());  // items/s = steps/s
}
BENCHMARK_CAPTURE(sequence_step_1920x1080, fig4_map, "paper-fig4", StepPart::map)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, fig4_frame, "paper-fig4", StepPart::frame)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, quadrant_shuffle_buffers, "quadrant-shuffle",
                  StepPart::buffers)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, quadrant_shuffle_map, "quadrant-shuffle", StepPart::map)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, quadrant_shuffle_frame, "quadrant-shuffle",
                  StepPart::frame)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, carpet_lace_buffers, "carpet-lace", StepPart::buffers)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, carpet_lace_map, "carpet-lace", StepPart::map)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(sequence_step_1920x1080, carpet_lace_frame, "carpet-lace", StepPart::frame)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace

int main(int argc, char** argv) {
  // --threads N or --threads=N, taken out before Google Benchmark reads the rest.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string value;
    if (arg == "--threads" && i + 1 < argc)
      value = argv[++i];
    else if (arg.rfind("--threads=", 0) == 0)
      value = arg.substr(10);
    else {
      argv[kept++] = argv[i];
      continue;
    }
    char* end = nullptr;
    const long n = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || n < 0 || n > kMaxThreads) {
      std::fprintf(stderr, "superifs_bench: --threads: 0 (all cores) to %d (got '%s')\n",
                   kMaxThreads, value.c_str());
      return 2;
    }
    threads_option = static_cast<int>(n);
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
