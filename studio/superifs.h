// SPDX-License-Identifier: Apache-2.0
// SuperIFSs in `ifsfx studio` (docs/studio.md): a superIFS preset as the page edits it (JSON),
// and the textures of its V-variable sequence rendered for the page, step by step.
//
// The page's superIFS:
//   {"name": "paper-fig4", "description": "...", "probabilities": [0.5, 0.5],  // P_n, optional
//    "view": [x0, y0, x1, y1],                                                 // optional
//    "ifs": [{"name": "...", "maps": [[a, b, c, d, e, f], ...], "probabilities": [...]}, ...],
//    "colouring": [{"maps": [...]}, ...]}                                      // optional
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "studio/context.h"
#include "studio/lru.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace ifsfx::app {

// The superIFS of the page's JSON, checked as a .super.toml file is (validate(SuperIfs)); its
// text is what to_toml writes. Throws Error{parse} for a field of the wrong shape and
// Error{invalid_ifs} naming the IFS and map that break a rule.
SuperIfsPreset superifs_from_json(const nlohmann::json& body);
nlohmann::json superifs_to_json(const SuperIfsPreset& preset);

// Textures for the page: per tab, the TextureSequence of the settings asked for last is kept, so
// that stepping through it (step k, k + 1, ...) costs one V-variable step each; a request with
// other settings replaces it and stops a burn-in still running for the old ones (409).
class TexturePreviews {
 public:
  // The PNG of texture `step` (0: the burnt-in one) of a request of tab `client`:
  //   {"superifs": {...}, "V": 3, "mode": "attractor", "size": "384x384", "step": 0, "seed": 1,
  //    "buffer": 1, "source": "sample"}
  // Throws Error{parse} or Error{invalid_argument} for a bad field, Error{interrupted} when newer
  // settings of the same tab took over or the server stops.
  std::string frame_png(const nlohmann::json& body, const std::string& client,
                        StudioContext& context);
  // Stops every burn-in and step in flight.
  void stop_all();

 private:
  struct Entry {
    std::string key;
    std::atomic<bool> stop{false};
    std::mutex build;  // one burn-in per entry
    std::unique_ptr<TextureSequence> sequence;
  };
  static constexpr std::size_t kMaxTabs = 8;

  std::mutex mutex_;
  LruSlots<Entry> entries_{kMaxTabs};  // by tab
  bool stopping_ = false;
};

}  // namespace ifsfx::app
