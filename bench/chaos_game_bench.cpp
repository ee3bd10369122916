// SPDX-License-Identifier: Apache-2.0
// The chaos-game core: points per second for the fern and the Sierpinski triangle at 1920×1080,
// 64 points per pixel, attractor and measure modes, on 1 and 2 threads. Each run also checks its
// result (coverage), so a broken kernel cannot look fast. Run: build/release/bench/chaos_game_bench
#include <benchmark/benchmark.h>

#include "ifs/preset.h"
#include "ifs/render.h"

namespace {

// One renderer on one preset at 1920×1080, 64 points per pixel, state.range(0) threads. The rates
// are of the chaos game (RenderStats::seconds: the walk and the accumulation, not the tone map).
template <auto render>
void run(benchmark::State& state, const char* preset, double min_coverage) {
  const ifsfx::Ifs ifs = ifsfx::load_ifs(preset).ifs;
  const ifsfx::RenderOptions options{
      .sampling = {.quality = 64, .threads = static_cast<int>(state.range(0))}};
  ifsfx::RenderStats stats;
  double compute_seconds = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(render(ifs, {1920, 1080}, options, &stats));
    compute_seconds += stats.seconds;
  }
  if (stats.coverage < min_coverage) state.SkipWithError("covers too little of the frame");
  const double points = static_cast<double>(stats.points) * state.iterations();
  state.counters["Mpts/s"] = points / compute_seconds / 1e6;
  state.counters["Mpts/s/thread"] = points / compute_seconds / 1e6 / state.range(0);
  state.counters["coverage"] = stats.coverage;
}

void fern_measure(benchmark::State& state) {
  run<ifsfx::render_measure>(state, "barnsley-fern", 0.05);
}
void fern_attractor(benchmark::State& state) {
  run<ifsfx::render_attractor>(state, "barnsley-fern", 0.05);
}
void sierpinski_measure(benchmark::State& state) {
  run<ifsfx::render_measure>(state, "sierpinski-triangle", 0.02);
}
void sierpinski_attractor(benchmark::State& state) {
  run<ifsfx::render_attractor>(state, "sierpinski-triangle", 0.02);
}
BENCHMARK(fern_measure)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(fern_attractor)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(sierpinski_measure)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(sierpinski_attractor)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
