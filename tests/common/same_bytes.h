// SPDX-License-Identifier: Apache-2.0
// Byte-for-byte comparison of two images, for the determinism tests: same size, same type and
// the same bytes in every row (a float image compared this way fails on any last-bit change).
#pragma once

#include <cstring>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace ifsfx::testing {

inline ::testing::AssertionResult same_bytes(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type())
    return ::testing::AssertionFailure()
           << "shapes differ: " << a.cols << "x" << a.rows << " type " << a.type() << " vs "
           << b.cols << "x" << b.rows << " type " << b.type();
  const std::size_t row_bytes = a.cols * a.elemSize();
  std::size_t rows_differing = 0;
  int first = -1;
  for (int r = 0; r < a.rows; ++r)
    if (std::memcmp(a.ptr(r), b.ptr(r), row_bytes) != 0) {
      if (first < 0) first = r;
      ++rows_differing;
    }
  if (rows_differing == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << rows_differing << " of " << a.rows << " rows differ, the first is row " << first;
}

}  // namespace ifsfx::testing
