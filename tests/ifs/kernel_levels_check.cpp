// SPDX-License-Identifier: Apache-2.0
// kernel_levels_check: runs the chaos-game kernels of every level this CPU supports (ifs/cpu.h)
// on IFSs of 2 to 17 maps, compares every mode's output with the scalar level byte for byte, and
// prints a hash of each level's outputs and each level's speed on one core. The scalar level's
// hash is the same on every x86-64 machine, so two machines' runs compare too. Exit status 0 when
// every level matched, 1 on any mismatch, 2 on a bad argument. It links the kernel objects alone
// (no OpenCV, no OpenImageIO) and is linked statically where it can be, so it can be copied to
// another machine and run there:
//   cmake --build build/release --target kernel_levels_check
//   scp build/release/tests/ifs/kernel_levels_check elsewhere: && ssh elsewhere
//   ./kernel_levels_check
// Options: --points N (points per timed run, default 4194304), --repeat R (timed runs per level,
// mode and IFS, the best is kept; default 3).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "ifs/cpu.h"
#include "ifs/detail/walk_kernels.h"
#include "ifs/rng.h"

namespace {

using namespace ifsfx;
using namespace ifsfx::detail;

// An IFS as the kernels see it, with its tables.
struct TestIfs {
  std::string name;
  std::vector<double> a, b, c, d, e, f, p;
  std::vector<std::uint32_t> palette;
  MapPicker pick;

  WalkSpec spec(double x0, double y0, double x1, double y1, int width, int height) const {
    WalkSpec w{};
    w.maps = static_cast<std::uint32_t>(a.size());
    w.a = a.data(), w.b = b.data(), w.c = c.data(), w.d = d.data(), w.e = e.data(), w.f = f.data();
    const MapPicker::View v = pick.view();
    w.pick_n = v.n, w.threshold = v.threshold, w.alias = v.alias;
    w.sx = width / (x1 - x0), w.ox = -x0 * w.sx;
    w.sy = -height / (y1 - y0), w.oy = y1 * height / (y1 - y0);
    w.width = width, w.height = height, w.stride = width;
    w.burn_in = 40;
    w.key_bits = 1;
    while ((1u << w.key_bits) < w.maps) ++w.key_bits;
    w.palette = palette.data();
    return w;
  }
};

// N maps of factor 0.45, each turned a little more, towards N points spread over the unit circle;
// unequal probabilities so that the alias table has aliases. Its attractor lies in [-1, 1]².
TestIfs polygon(int n) {
  TestIfs t;
  t.name = std::to_string(n) + "-gon";
  // Points of the unit circle as ((1 − u²), 2u) / (1 + u²): rational, so the coefficients are the
  // same bits on every machine (libm's cos and sin may round differently on CPUs with FMA), and
  // so is the hash of the scalar level's outputs.
  const auto on_circle = [](double u) {
    return std::pair{(1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)};
  };
  for (int k = 0; k < n; ++k) {
    const auto [cs, sn] = on_circle(0.05 * k);  // turned a little more
    const auto [cx, cy] = on_circle(n > 1 ? 2.5 * (2.0 * k / (n - 1) - 1) : 0);  // a corner
    const double s = 0.45;
    t.a.push_back(s * cs), t.b.push_back(-s * sn), t.c.push_back(s * sn), t.d.push_back(s * cs);
    t.e.push_back(0.5 * cx), t.f.push_back(0.5 * cy);
    t.p.push_back(1.0 + k % 3);
    t.palette.push_back(n > 1 ? static_cast<std::uint32_t>(std::lround(65535.0 * k / (n - 1))) : 0);
  }
  t.pick = MapPicker(t.p);
  return t;
}

// The outputs of every mode of one level on one IFS, as bytes: the traced points of three point
// counts, then the rasters of hits, counts, 32- and 64-bit tops and measure.
struct Output {
  std::string mode;
  std::vector<unsigned char> bytes;
};

template <class T>
std::vector<unsigned char> bytes_of(const std::vector<T>& v, std::size_t n) {
  const auto* p = reinterpret_cast<const unsigned char*>(v.data());
  return {p, p + n * sizeof(T)};
}

// Every mode of `k` with the walk `w`: a trace of `traced` points (and of 8 and 3), rasters of
// `points`; `where` ends each mode's name.
std::vector<Output> outputs_of(const WalkSpec& w, const WalkKernels& k, const std::string& where,
                               std::uint64_t traced, std::uint64_t points) {
  std::vector<Output> out;
  const auto area = static_cast<std::size_t>(w.width) * static_cast<std::size_t>(w.height);
  for (std::uint64_t count : {traced, std::uint64_t{8}, std::uint64_t{3}}) {
    std::vector<TracedPoint> t(count);
    const std::size_t n = k.trace(w, lane_seeds(42, count), count, t.data());
    out.push_back({"trace of " + std::to_string(count) + " points" + where, bytes_of(t, n)});
  }
  const LaneSeeds seeds = lane_seeds(7, 11);
  // One raster-writing kernel on a zeroed raster of Cell.
  const auto raster = [&](auto kernel, auto cell, const char* mode) {
    std::vector<decltype(cell)> r(area);
    (k.*kernel)(w, seeds, points, r.data());
    out.push_back({mode + where, bytes_of(r, area)});
  };
  raster(&WalkKernels::hits, std::uint8_t{}, "hits");
  raster(&WalkKernels::counts, std::uint32_t{}, "counts");
  raster(&WalkKernels::tops32, std::uint32_t{}, "tops32");
  raster(&WalkKernels::tops64, std::uint64_t{}, "tops64");
  // The measure as count | Σc6 << 32 per cell: the bytes (and the hash) of every version since
  // the first, whatever the kernels' own cells are.
  std::vector<std::uint32_t> cells(area);
  std::vector<std::uint64_t> spills(points / MeasureCells::kFull), count(area), colour(area);
  MeasureCells m{cells.data(), spills.data(), 0};
  k.measure(w, seeds, points, m);
  fold_measure_cells(m, area, count.data(), colour.data());
  for (std::size_t i = 0; i < area; ++i) count[i] |= colour[i] << 32;
  out.push_back({"measure" + where, bytes_of(count, area)});
  return out;
}

// Every mode of `k` on a raster that cuts the attractor, and on the torus of the unit tile, which
// the attractor overlaps (WalkSpec::wrap: every step wraps into [0,1)², docs/design.md §11).
std::vector<Output> outputs(const TestIfs& ifs, const WalkKernels& k) {
  std::vector<Output> out;
  const int width = 301, height = 203;
  for (const bool wrap : {false, true}) {
    WalkSpec w = ifs.spec(-0.7, -1.05, 1.05, 0.6, width, height);
    if (wrap) {
      w.wrap = 1;
      w.sx = width, w.ox = 0, w.sy = height, w.oy = 0;
    }
    // The torus (the same code, and a wrap per step) on a quarter of the points.
    const std::vector<Output> more = wrap ? outputs_of(w, k, " on the torus", 50'001, 125'001)
                                          : outputs_of(w, k, "", 200'003, 500'001);
    out.insert(out.end(), more.begin(), more.end());
  }
  return out;
}

// FNV-1a, 64 bits: a fingerprint of a level's outputs, to compare across machines (the scalar
// level's is the same on every x86-64 CPU).
std::uint64_t fnv1a(std::uint64_t h, const std::vector<unsigned char>& bytes) {
  for (unsigned char byte : bytes) h = (h ^ byte) * 0x100000001b3ULL;
  return h;
}
constexpr std::uint64_t kFnvBasis = 0xcbf29ce484222325ULL;

enum class Mode { hits, tops, measure };
const char* const kModeNames[] = {"hits", "tops", "measure"};

// Points per second of one kernel (hits, 64-bit tops or measure) on a 1920×1080 raster holding
// the attractor, best of `repeat` runs of `points` points in chunks of 2^22.
double rate(const TestIfs& ifs, const WalkKernels& k, Mode mode, std::uint64_t points, int repeat) {
  const int width = 1920, height = 1080;
  WalkSpec w = ifs.spec(-1.8, -1.0, 1.8, 1.0, width, height);
  const auto area = static_cast<std::size_t>(width) * height;
  std::vector<std::uint64_t> cells(area), count(area), colour(area);
  std::vector<std::uint8_t> hits(area);
  std::vector<std::uint32_t> measure_cells(area);
  std::vector<std::uint64_t> spills(points / MeasureCells::kFull);
  MeasureCells m{measure_cells.data(), spills.data(), 0};
  double best = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t done = 0, chunk = 0; done < points;
         done += std::uint64_t{1} << 22, ++chunk) {
      const std::uint64_t n = std::min<std::uint64_t>(points - done, std::uint64_t{1} << 22);
      switch (mode) {
        case Mode::hits:
          k.hits(w, lane_seeds(1, chunk), n, hits.data());
          break;
        case Mode::tops:
          k.tops64(w, lane_seeds(1, chunk), n, cells.data());
          break;
        case Mode::measure:
          k.measure(w, lane_seeds(1, chunk), n, m);
          break;
      }
    }
    if (mode == Mode::measure) fold_measure_cells(m, area, count.data(), colour.data());
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, static_cast<double>(points) / s);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t points = std::uint64_t{1} << 22;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--points" || arg == "--repeat") && i + 1 < argc) {
      const long long v = std::atoll(argv[++i]);
      if (v <= 0) {
        std::fprintf(stderr, "kernel_levels_check: %s must be positive\n", arg.c_str());
        return 2;
      }
      if (arg == "--points")
        points = static_cast<std::uint64_t>(v);
      else
        repeat = static_cast<int>(v);
    } else {
      std::fprintf(stderr, "usage: kernel_levels_check [--points N] [--repeat R]\n");
      return 2;
    }
  }
  const std::vector<CpuLevel> levels = supported_cpu_levels();
  std::printf("kernel levels this CPU runs:");
  for (CpuLevel level : levels) std::printf(" %s", to_string(level));
  std::printf("\n");
  std::vector<TestIfs> cases;
  for (int n : {2, 3, 4, 5, 6, 7, 8, 9, 12, 16, 17}) cases.push_back(polygon(n));

  // Every level's outputs against the scalar level's, byte for byte, and a hash of each level's.
  std::vector<std::vector<Output>> reference;
  for (const TestIfs& ifs : cases)
    reference.push_back(outputs(ifs, walk_kernels(CpuLevel::scalar)));
  int mismatches = 0;
  for (CpuLevel level : levels) {
    std::uint64_t hash = kFnvBasis;
    int wrong = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const std::vector<Output> mine =
          level == CpuLevel::scalar ? reference[i] : outputs(cases[i], walk_kernels(level));
      for (std::size_t j = 0; j < mine.size(); ++j) {
        hash = fnv1a(hash, mine[j].bytes);
        if (mine[j].bytes != reference[i][j].bytes) {
          std::printf("MISMATCH: %s, %s kernels, %s\n", cases[i].name.c_str(), to_string(level),
                      mine[j].mode.c_str());
          ++wrong;
        }
      }
    }
    std::printf("%-8s hash %016llx  %s\n", to_string(level), static_cast<unsigned long long>(hash),
                level == CpuLevel::scalar ? "(the reference)"
                : wrong == 0              ? "= scalar, byte for byte"
                                          : "DIFFERS from scalar");
    mismatches += wrong;
  }
  std::printf("Mpts/s on 1 core, 1920x1080 raster, %llu points, best of %d\n",
              static_cast<unsigned long long>(points), repeat);
  for (Mode mode : {Mode::hits, Mode::tops, Mode::measure}) {
    std::printf("%-8s", kModeNames[static_cast<int>(mode)]);
    for (CpuLevel level : levels) std::printf(" %8s", to_string(level));
    std::printf("\n");
    for (const TestIfs& ifs : cases) {
      std::printf("%-8s", ifs.name.c_str());
      for (CpuLevel level : levels)
        std::printf(" %8.1f", rate(ifs, walk_kernels(level), mode, points, repeat) / 1e6);
      std::printf("\n");
    }
  }
  if (mismatches > 0) {
    std::printf("FAIL: %d mode(s) differ from the scalar level\n", mismatches);
    return 1;
  }
  std::printf("PASS: every level gives the scalar bytes in every mode\n");
  return 0;
}
