// SPDX-License-Identifier: Apache-2.0
// The two steal maps side by side over every shipped IFS preset (issue 14 item 5): the exact
// per-pixel descent and the chaos game (quality 64, the paper's method), at 1280×720 and
// 1920×1080, coloured through the default colouring, on 2 threads. Each exact run reports its
// time; each chaos run its time and its agreement with the exact map: the share of pixels whose
// coverage agrees ("cover_agree"), and of the pixels both cover, the share whose source point lies
// within one output pixel of the exact one ("uv_agree").
//   build/release/bench/steal_modes_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"

namespace {

using namespace ifsfx;

struct Agreement {
  double coverage = 0, uv = 0;
};

Agreement agreement(const StealMap& exact, const StealMap& chaos) {
  const cv::Size size = exact.size();
  std::size_t same_cover = 0, both = 0, near = 0;
  for (int r = 0; r < size.height; ++r) {
    const auto* ce = exact.coverage.ptr<std::uint8_t>(r);
    const auto* cc = chaos.coverage.ptr<std::uint8_t>(r);
    const auto* ue = exact.source_uv.ptr<cv::Vec2f>(r);
    const auto* uc = chaos.source_uv.ptr<cv::Vec2f>(r);
    for (int c = 0; c < size.width; ++c) {
      same_cover += (ce[c] != 0) == (cc[c] != 0);
      if (ce[c] == 0 || cc[c] == 0) continue;
      ++both;
      near += std::abs(ue[c][0] - uc[c][0]) * size.width <= 1 &&
              std::abs(ue[c][1] - uc[c][1]) * size.height <= 1;
    }
  }
  return {static_cast<double>(same_cover) / static_cast<double>(size.area()),
          both ? static_cast<double>(near) / static_cast<double>(both) : 1.0};
}

// The exact map of each (preset, size), computed once and kept for the chaos runs' agreement.
const StealMap& exact_map(const std::string& name, const Ifs& F, cv::Size size) {
  static std::map<std::pair<std::string, int>, StealMap> maps;
  auto [it, added] = maps.try_emplace({name, size.width});
  if (added)
    it->second = compute_steal_map(F, default_colouring(F.size()), size,
                                   {.sampling = {.threads = 2}, .exact = true});
  return it->second;
}

void steal_mode(benchmark::State& state, const std::string& name, cv::Size size, bool exact) {
  const Ifs F = load_ifs(name).ifs;
  const Ifs G = default_colouring(F.size());
  const StealMap& reference = exact_map(name, F, size);
  StealMap map;
  for (auto _ : state) {
    map = compute_steal_map(F, G, size, {.sampling = {.threads = 2}, .exact = exact});
    benchmark::DoNotOptimize(map.source_uv.data);
  }
  if (map.empty()) throw std::runtime_error(name + ": empty map");
  const Agreement a = agreement(reference, map);  // 1 and 1 for the exact map itself
  state.counters["cover_agree"] = a.coverage;
  state.counters["uv_agree"] = a.uv;
  state.counters["cover"] = cv::countNonZero(map.coverage) / static_cast<double>(size.area());
}

}  // namespace

int main(int argc, char** argv) {
  for (const PresetSummary& preset : list_shipped_presets()) {
    // The square tilings are colourings, not drawings: their maps do not contract everywhere.
    try {
      load_ifs(preset.name);
    } catch (const Error& e) {
      fmt::print(stderr, "skipped {}: {}\n", preset.name, e.what());
      continue;
    }
    for (const cv::Size size : {cv::Size(1280, 720), cv::Size(1920, 1080)})
      for (const bool exact : {true, false})
        benchmark::RegisterBenchmark(
            fmt::format("{}/{}p/{}", preset.name, size.height, exact ? "exact" : "chaos").c_str(),
            [name = preset.name, size, exact](benchmark::State& state) {
              steal_mode(state, name, size, exact);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->MeasureProcessCPUTime()
            ->Iterations(2);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
