// The chaos-game core: points per second for the fern at 1920×1080, attractor and measure modes,
// on 1 and 2 threads. Each run also checks its result (coverage), so a broken kernel cannot look
// fast. Run: build/release/bench/chaos_game_bench
#include <benchmark/benchmark.h>

#include "ifs/preset.h"
#include "ifs/render.h"

namespace {

void fern_measure(benchmark::State& state) {
  const ifsfx::Ifs fern = ifsfx::load_ifs("barnsley-fern").ifs;
  const ifsfx::RenderOptions options{.quality = 64, .threads = static_cast<int>(state.range(0))};
  ifsfx::RenderStats stats;
  double compute_seconds = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ifsfx::render_measure(fern, {1920, 1080}, options, &stats));
    compute_seconds += stats.seconds;
  }
  if (stats.coverage < 0.05) state.SkipWithError("fern covers too little of the frame");
  const double points = static_cast<double>(stats.points) * state.iterations();
  state.counters["Mpts/s"] = points / compute_seconds / 1e6;
  state.counters["Mpts/s/thread"] = points / compute_seconds / 1e6 / state.range(0);
  state.counters["coverage"] = stats.coverage;
}
BENCHMARK(fern_measure)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void fern_attractor(benchmark::State& state) {
  const ifsfx::Ifs fern = ifsfx::load_ifs("barnsley-fern").ifs;
  const ifsfx::RenderOptions options{.quality = 64, .threads = static_cast<int>(state.range(0))};
  ifsfx::RenderStats stats;
  double compute_seconds = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ifsfx::render_attractor(fern, {1920, 1080}, options, &stats));
    compute_seconds += stats.seconds;
  }
  const double points = static_cast<double>(stats.points) * state.iterations();
  state.counters["Mpts/s"] = points / compute_seconds / 1e6;
  state.counters["Mpts/s/thread"] = points / compute_seconds / 1e6 / state.range(0);
}
BENCHMARK(fern_attractor)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
