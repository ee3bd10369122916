// SPDX-License-Identifier: Apache-2.0
#include "ifs/fractaldb_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "ifs/detail/fractaldb_chaos.h"
#include "ifs/detail/numpy_random.h"
#include "ifs/error.h"

namespace ifsfx::fractaldb {
namespace fs = std::filesystem;
namespace {

constexpr const char* kColumns[] = {"a", "b", "c", "d", "e", "f", "p"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// One field as Python's float() reads it (a leading '+' too); from_chars rounds correctly, as
// float() does, so a file's numbers become the reference's doubles.
bool parse_number(std::string_view token, double& x) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
  return ec == std::errc() && end == token.data() + token.size();
}

struct Row {
  int line = 0;
  std::vector<double> values;
};

// The rows of a CSV of `columns` finite numbers each. `kind` says what a row is, for messages.
std::vector<Row> parse_rows(std::string_view text, const std::string& filename, std::size_t columns,
                            const char* kind) {
  std::vector<Row> rows;
  int line = 0;
  while (!text.empty()) {
    ++line;
    const std::size_t eol = text.find('\n');
    std::string_view content = text.substr(0, eol);
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    if (const std::size_t hash = content.find('#'); hash != std::string_view::npos)
      content = content.substr(0, hash);
    content = trim(content);
    if (content.empty()) continue;
    std::vector<std::string_view> fields;
    for (;;) {
      const std::size_t comma = content.find(',');
      fields.push_back(trim(content.substr(0, comma)));
      if (comma == std::string_view::npos) break;
      content.remove_prefix(comma + 1);
    }
    if (fields.size() != columns)
      throw Error(ErrorKind::parse,
                  fmt::format("{}:{}: {} is {} numbers separated by commas (got {})", filename,
                              line, kind, columns, fields.size()));
    Row row{line, {}};
    for (std::size_t i = 0; i < columns; ++i) {
      const std::string column = columns == 7 ? fmt::format("column {} ({})", i + 1, kColumns[i])
                                              : fmt::format("column {}", i + 1);
      double x = 0;
      if (!parse_number(fields[i], x))
        throw Error(ErrorKind::parse, fmt::format("{}:{}: {}: expected a number (got '{}')",
                                                  filename, line, column, fields[i]));
      if (!std::isfinite(x))
        throw Error(ErrorKind::invalid_ifs,
                    fmt::format("{}:{}: {}: must be a finite number (got {})", filename, line,
                                column, fields[i]));
      row.values.push_back(x);
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty())
    throw Error(ErrorKind::parse, fmt::format("{}: no rows ({} is {} numbers separated by commas)",
                                              filename, kind, columns));
  return rows;
}

std::string read_text(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file", path.string()));
  if (fs::is_directory(path, ec))
    throw Error(ErrorKind::io, fmt::format("{}: cannot read (got a folder)", path.string()));
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad())
    throw Error(ErrorKind::io, fmt::format("{}: cannot read ({})", path.string(),
                                           std::generic_category().message(errno)));
  return text.str();
}

// A decimal's nearest double: the value a file listing `x` rounded to 12 digits holds.
double as_written(double x) {
  const std::string text = fmt::format("{:.12g}", x);
  double value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

}  // namespace

Ifs Category::ifs() const {
  Ifs out;
  out.name = name;
  out.maps = maps;
  double sum = 0;
  for (const double p : probabilities) sum += p;
  for (const double p : probabilities) out.probabilities.push_back(p / sum);
  return out;
}

Category parse_category(std::string_view text, const std::string& filename) {
  const std::vector<Row> rows = parse_rows(text, filename, 7, "a category row a,b,c,d,e,f,p");
  Category category;
  category.name = fs::path(filename).stem().string();
  double sum = 0;
  for (const Row& row : rows) {
    const auto& v = row.values;
    if (v[6] < 0)
      throw Error(ErrorKind::invalid_ifs,
                  fmt::format("{}:{}: column 7 (p): a probability must be ≥ 0 (got {})", filename,
                              row.line, v[6]));
    category.maps.push_back(AffineMap::from_coefficients({v[0], v[1], v[2], v[3], v[4], v[5]}));
    category.probabilities.push_back(v[6]);
    sum += v[6];
  }
  if (!(std::abs(sum - 1) <= 1e-6))
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}:{}: the probabilities of column 7 (p) must sum to 1 over the {} "
                            "rows (got {:.9g})",
                            filename, rows.back().line, rows.size(), sum));
  const double rate = contraction_rate(category.maps, category.probabilities);
  if (!(rate < 0))
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}: the maps do not contract on average (contraction rate {:.4g} per "
                            "step, must be < 0): the chaos game flies off to infinity, and "
                            "FractalDB's search drops such an IFS (its points collapse into a few "
                            "pixels, below any filling rate)",
                            filename, rate));
  return category;
}

Category read_category(const fs::path& path) {
  return parse_category(read_text(path), path.string());
}

std::vector<Weight> parse_weights(std::string_view text, const std::string& filename) {
  std::vector<Weight> weights;
  for (const Row& row : parse_rows(text, filename, 6, "a weight row wa,wb,wc,wd,we,wf")) {
    Weight w{};
    std::copy(row.values.begin(), row.values.end(), w.begin());
    weights.push_back(w);
  }
  return weights;
}

std::vector<Weight> read_weights(const fs::path& path) {
  return parse_weights(read_text(path), path.string());
}

std::vector<Weight> weights_table(double step) {
  if (!(step > 0 && step <= 10))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("weight step: must be a number in (0, 10] (got {})", step));
  std::vector<Weight> table;
  Weight ones{1, 1, 1, 1, 1, 1};
  const double factors[] = {std::max(as_written(1 - 2 * step), 0.01), as_written(1 - step),
                            as_written(1 + step), as_written(1 + 2 * step)};
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 4; ++i) {
      if (k == 0 && i == 2) table.push_back(ones);  // a's factors run 1 − 2K .. 1 + 2K
      Weight w = ones;
      w[static_cast<std::size_t>(k)] = factors[i];
      table.push_back(w);
    }
  return table;
}

std::vector<fs::path> category_files(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw Error(
        fs::exists(folder, ec) ? ErrorKind::invalid_argument : ErrorKind::not_found,
        fmt::format("{}: {}", folder.string(),
                    fs::exists(folder, ec) ? "not a folder of category CSVs" : "no such folder"));
  std::map<std::string, fs::path> by_name;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec) || it->path().extension() != ".csv") continue;
    const std::string name = it->path().filename().string();
    if (const auto found = by_name.find(name); found != by_name.end())
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("{}: two categories named {} (also {}): their images would share a "
                      "folder",
                      it->path().string(), it->path().stem().string(), found->second.string()));
    by_name.emplace(name, it->path());
  }
  if (ec)
    throw Error(ErrorKind::io, fmt::format("{}: cannot list ({})", folder.string(), ec.message()));
  std::vector<fs::path> files;
  for (auto& [name, path] : by_name) files.push_back(path);
  return files;
}

std::string category_text(const Category& category) {
  std::string text;
  for (std::size_t n = 0; n < category.maps.size(); ++n) {
    const auto k = category.maps[n].coefficients();
    text += fmt::format("{:.18e},{:.18e},{:.18e},{:.18e},{:.18e},{:.18e},{:.18e}\n", k[0], k[1],
                        k[2], k[3], k[4], k[5], category.probabilities[n]);
  }
  return text;
}

double contraction_rate(const std::vector<AffineMap>& maps,
                        const std::vector<double>& probabilities) {
  Ifs ifs;
  ifs.maps = maps;
  ifs.probabilities = probabilities;
  const double bound = mean_log_contraction(ifs);
  if (bound < 0) return bound;
  // The top Lyapunov exponent of the product of the linear parts, along the draws the renderer
  // makes (numpy.random.seed(100)): a unit vector carried through the maps, its growth summed.
  const detail::ReferenceMaps reference(maps, probabilities);
  detail::NumpyRandom random(100);
  constexpr int kSteps = 1 << 16;
  double x = 0.6, y = 0.8, log_growth = 0;
  for (int i = 0; i < kSteps; ++i) {
    const int j = reference.pick(random.random());
    if (j < 0) continue;
    const AffineMap& f = maps[static_cast<std::size_t>(j)];
    const double nx = f.a * x + f.b * y, ny = f.c * x + f.d * y;
    const double norm = std::hypot(nx, ny);
    if (norm == 0) return -std::numeric_limits<double>::infinity();  // a product of rank 0
    log_growth += std::log(norm);
    x = nx / norm;
    y = ny / norm;
  }
  return log_growth / kSteps;
}

}  // namespace ifsfx::fractaldb
