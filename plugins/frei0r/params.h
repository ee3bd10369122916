// SPDX-License-Identifier: Apache-2.0
// The parameters of a frei0r plugin: one table of names, types, explanations and defaults, and an
// instance's values, set and read through the frei0r API's untyped pointers. Hosts address a
// parameter by its position (FFmpeg's "a|b|c") or by its name (melt's name=value, GStreamer's
// properties): keep a table's order and names stable.
#pragma once

#include <mutex>
#include <span>
#include <string>
#include <vector>

// frei0r.h declares the API without extern "C": the plugins define it with C linkage.
extern "C" {
#include <frei0r.h>
}

// The plugins are compiled with hidden visibility; the frei0r API is what they export (and
// exports.map keeps everything else local).
#define IFSFX_F0R_EXPORT __attribute__((visibility("default")))

namespace ifsfx::frei0r {

enum class ParamType { flag = F0R_PARAM_BOOL, number = F0R_PARAM_DOUBLE, text = F0R_PARAM_STRING };

struct ParamInfo {
  const char* name;
  ParamType type;
  const char* explanation;
  double number = 0;      // default of a flag (0 or 1) or a number
  const char* text = "";  // default of a text
};

// f0r_get_param_info for parameter `index` of `table` (ignored out of range).
void describe(std::span<const ParamInfo> table, f0r_param_info_t* info, int index);

// One instance's values. Hosts may set a parameter from one thread while another renders
// (GStreamer's properties), so every access holds a lock; values() copies them out for a frame.
class ParamValues {
 public:
  explicit ParamValues(std::span<const ParamInfo> table);

  struct Values {
    std::vector<double> numbers;     // flags and numbers, by index (0 for a text)
    std::vector<std::string> texts;  // texts, by index ("" for a number)
    bool flag(int index) const { return numbers[static_cast<std::size_t>(index)] >= 0.5; }
    double number(int index) const { return numbers[static_cast<std::size_t>(index)]; }
    const std::string& text(int index) const { return texts[static_cast<std::size_t>(index)]; }
  };

  // f0r_set_param_value: copies the value (a double* or a char**); false when it did not change
  // or the index is out of range.
  bool set(const void* param, int index);
  // f0r_get_param_value: a double, or a char* to this instance's copy (valid until the next set).
  void get(void* param, int index);
  Values values() const;

 private:
  std::span<const ParamInfo> table_;
  mutable std::mutex mutex_;
  Values values_;
};

}  // namespace ifsfx::frei0r
