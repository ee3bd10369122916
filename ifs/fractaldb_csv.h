// SPDX-License-Identifier: Apache-2.0
// FractalDB's files (formula-driven supervised learning, Kataoka et al.; the reference generator
// is fractal_renderer/ and param_search/ of hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch,
// docs/dataset.md):
//
//   category CSV   one row per map, "a,b,c,d,e,f,p": f(x, y) = (a x + b y + e, c x + d y + f),
//                  ifsfx's own order (docs/design.md §1), and p the map's probability. The
//                  reference's search writes p = |det| / Σ|det| (np.savetxt, "%.18e"); its
//                  chaos game walks the cumulative sums of p as written.
//   weight CSV     one row per variant, "wa,wb,wc,wd,we,wf": the factors each coefficient a..f of
//                  every map is multiplied by (p is kept). Its weights_K.csv tables are
//                  weights_table(K).
//
// The category's name is its file's stem ("00042"): the folder and file names of its images.
//   const fractaldb::Category c = fractaldb::read_category("csv/00042.csv");
//   const auto weights = fractaldb::read_weights("weights_0.4.csv");
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ifs/affine_map.h"
#include "ifs/ifs.h"

namespace ifsfx::fractaldb {

struct Category {
  std::string name;  // the file's stem
  std::vector<AffineMap> maps;
  // Column p as written: the chaos game picks the first map whose running sum reaches a uniform
  // draw (the reference's rule), so they sum to 1 (checked to 1e-6).
  std::vector<double> probabilities;

  // The IFS for the rest of ifsfx (probabilities normalised).
  Ifs ifs() const;
};

// Factors of a, b, c, d, e, f.
using Weight = std::array<double, 6>;

// Reads a category CSV: rows of 7 numbers separated by commas (spaces around them, blank lines
// and '#' comments allowed, as numpy.genfromtxt reads them), finite, p ≥ 0 summing to 1.
// Refuses a row set that does not contract on average (contraction_rate ≥ 0): its chaos game
// flies off to infinity, and FractalDB's search drops such an IFS, whose points then collapse
// into a few pixels, far below any filling rate. Throws Error{parse} "FILE:LINE: ..." for a
// malformed row, Error{invalid_ifs} "FILE:LINE: ..." for a bad number, "FILE: ..." for the
// sum of p and the contraction.
Category parse_category(std::string_view text, const std::string& filename);
// The same from a file (the name from its stem). Throws Error{not_found} / Error{io} naming it.
Category read_category(const std::filesystem::path& path);

// Reads a weight CSV: rows of 6 finite numbers. Throws as parse_category does.
std::vector<Weight> parse_weights(std::string_view text, const std::string& filename);
std::vector<Weight> read_weights(const std::filesystem::path& path);

// The reference's weights_K.csv: the factors 1 − 2K, 1 − K, 1, 1 + K, 1 + 2K of a (25 rows: all
// ones once, then for each of a..f in turn the four others; 1 − 2K below 0.01 is 0.01, as its
// weights_0.5.csv has), each the double nearest to its decimal value, as a file holds it.
// Throws Error{invalid_argument} for K outside (0, 10].
std::vector<Weight> weights_table(double step);

// The category CSVs under `folder` (every *.csv file, also in subfolders, as the reference's
// parallel layout csv0/, csv1/, ... has them), sorted by file name: the order of the labels (a
// category's label is its index here, the class index torchvision's ImageFolder gives its
// folder). Throws Error{not_found} for a missing folder and Error{invalid_argument} for two files
// of the same name (their images would share a folder).
std::vector<std::filesystem::path> category_files(const std::filesystem::path& folder);

// A category as the reference's search writes it: np.savetxt's "%.18e" numbers, ',' between.
std::string category_text(const Category& category);

// The rate at which the chaos game's linear parts contract, per step (natural log): negative
// when the IFS contracts on average. The mean log contraction of words of up to 3 maps
// (mean_log_contraction, an upper bound of the top Lyapunov exponent) where it is negative, else
// the top Lyapunov exponent estimated along the reference's own draws (2^16 steps).
double contraction_rate(const std::vector<AffineMap>& maps,
                        const std::vector<double>& probabilities);

}  // namespace ifsfx::fractaldb
