// SPDX-License-Identifier: Apache-2.0
// The kernel table of one level, included by ifs/walk_kernels_<level>.cpp inside its namespace
// after walk_kernels_common.inl and its own walk<Sink>() (see there), with kLevel defined.

void hits(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, std::uint8_t* out) {
  HitSink sink{out};
  walk(w, seeds, points, sink);
}

void counts(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, std::uint32_t* out) {
  CountSink sink{out};
  walk(w, seeds, points, sink);
}

void measure(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, MeasureCells& cells) {
  MeasureSink sink{cells};
  walk(w, seeds, points, sink);
  sink.finish();
  cells.spilled = sink.m.spilled;
}

void tops32(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, std::uint32_t* cells) {
  TopsSink<std::uint32_t> sink{cells};
  walk(w, seeds, points, sink);
}

void tops64(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, std::uint64_t* cells) {
  TopsSink<std::uint64_t> sink{cells};
  walk(w, seeds, points, sink);
}

std::size_t trace(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points,
                  TracedPoint* out) {
  TraceSink sink{out, 0};
  walk(w, seeds, points, sink);
  return sink.count;
}

constexpr WalkKernels kernels{kLevel, &hits, &counts, &measure, &tops32, &tops64, &trace};
