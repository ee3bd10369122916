// SPDX-License-Identifier: Apache-2.0
// Steal maps from Python: compute (steal_map), save and load, and apply to any image array.
#pragma once

#include <memory>
#include <mutex>

#include <pybind11/pybind11.h>
#include <opencv2/core.hpp>

#include "ifs/steal_map.h"

namespace ifsfx::python {

namespace py = pybind11;

// The remap table of a steal map for the last source size and options it was applied with
// (prepare_apply), so that the frames of a video, all of one size, are remapped without building
// the table again. Safe to share between threads: a call that finds another size builds its own
// table and keeps it for the next.
class PreparedStealMapCache {
 public:
  using Table = std::shared_ptr<const PreparedStealMap>;
  Table get(const StealMap& map, cv::Size source_size, const ApplyOptions& options);

 private:
  std::mutex mutex_;
  Table table_;
};

// What a Python StealMap holds: the map, and its table cache.
struct SharedStealMap {
  explicit SharedStealMap(StealMap m)
      : map(std::make_shared<const StealMap>(std::move(m))),
        cache(std::make_shared<PreparedStealMapCache>()) {}
  std::shared_ptr<const StealMap> map;
  std::shared_ptr<PreparedStealMapCache> cache;
};

void bind_steal(py::module_& m);

}  // namespace ifsfx::python
