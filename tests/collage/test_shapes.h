// SPDX-License-Identifier: Apache-2.0
// Working rasters and maps with known answers, and a quick fit's options, shared by the collage
// tests.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "collage/fit.h"
#include "ifs/affine_map.h"
#include "ifs/ifs.h"

namespace ifsfx::testing {

// A small, fast fit: the evaluation budget (not the clock) ends it, so it is reproducible.
inline collage::FitOptions quick(int maps) {
  collage::FitOptions o;
  o.maps = maps;
  o.restarts = 2;
  o.max_evaluations = 12000;
  o.max_seconds = 0;
  o.quality = 128;
  return o;
}

// The square [1/8, 7/8]² as a 64×64 working raster.
inline cv::Mat framed_square() {
  cv::Mat square(64, 64, CV_8UC1, cv::Scalar(0));
  square(cv::Rect(8, 8, 48, 48)).setTo(255);
  return square;
}

// The maps of [1/8, 7/8]² onto its four quadrants (bottom-left, bottom-right, top-left,
// top-right): their collage is the square itself.
inline std::vector<AffineMap> quadrant_maps() {
  std::vector<AffineMap> maps;
  for (double y : {0.125, 0.5})
    for (double x : {0.125, 0.5})
      maps.push_back(rectangle_map(0.125, 0.125, 0.875, 0.875, x, y, x + 0.375, y + 0.375));
  return maps;
}

// Five maps that are not a tiling: each shrinks the plane by 0.55 about (1/2, 1/2), turns it by
// ±25° (alternately) and moves it 0.22 towards a corner of a regular pentagon. Their pieces
// overlap (Σ|det| = 1.51), and the attractor is a solid five-petalled flower with a fractal rim.
inline Ifs five_petals() {
  Ifs ifs;
  ifs.name = "five-petals";
  for (int k = 0; k < 5; ++k) {
    const double corner = 2 * std::numbers::pi * k / 5 + std::numbers::pi / 2;
    const double turn = (k % 2 ? -25.0 : 25.0) * std::numbers::pi / 180;
    const double c = 0.55 * std::cos(turn), s = 0.55 * std::sin(turn);
    const double x = 0.5 + 0.22 * std::cos(corner), y = 0.5 + 0.22 * std::sin(corner);
    ifs.maps.push_back({c, -s, s, c, x - 0.5 * (c - s), y - 0.5 * (s + c)});
  }
  ifs.probabilities = default_probabilities(ifs.maps);
  return ifs;
}

// A disc on the left and a square on the right, apart: a shape of two components.
inline cv::Mat disc_and_square(int size = 96) {
  cv::Mat m(size, size, CV_8UC1, cv::Scalar(0));
  cv::circle(m, {size / 4, size / 2}, size / 5, cv::Scalar(255), cv::FILLED);
  m(cv::Rect(size * 3 / 5, size / 3, size / 3, size / 3)).setTo(255);
  return m;
}

// five_petals() shrunk into the disc of disc_and_square(96) (centre (24.5, 48.5) px, radius 19):
// each map conjugated by x -> c + 0.38 (x - (1/2, 1/2)), the same linear parts, moved. A is the
// flower inside the disc and misses the square.
inline std::vector<AffineMap> flower_in_disc() {
  const Point c{24.5 / 96, 1 - 48.5 / 96};
  const double rho = 0.38;
  std::vector<AffineMap> maps;
  for (AffineMap f : five_petals().maps) {
    const Point t = f({0.5, 0.5});
    f.e = c.x - (f.a * c.x + f.b * c.y) + rho * (t.x - 0.5);
    f.f = c.y - (f.c * c.x + f.d * c.y) + rho * (t.y - 0.5);
    maps.push_back(f);
  }
  return maps;
}

}  // namespace ifsfx::testing
