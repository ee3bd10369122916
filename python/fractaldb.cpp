// SPDX-License-Identifier: Apache-2.0
#include "python/fractaldb.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "fractaldb/render.h"
#include "fractaldb/search.h"
#include "ifs/error.h"
#include "ifs/fractaldb_csv.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/options.h"

namespace ifsfx::python {
namespace {
namespace fs = std::filesystem;
namespace db = fractaldb;

bool is_path(const py::handle& object) {
  return py::isinstance<py::str>(object) || py::hasattr(object, "__fspath__");
}
std::string path_of(const py::handle& object) {
  return py::isinstance<py::str>(object) ? object.cast<std::string>()
                                         : py::str(object.attr("__fspath__")()).cast<std::string>();
}

// A category from arrays, checked by the reader's own rules (its messages name `name` and the
// row): written as the search writes a file, read back exactly ("%.18e" keeps every double).
db::Category category_from_arrays(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& maps,
    const std::optional<std::vector<double>>& probabilities, const std::string& name) {
  if (maps.ndim() != 2 || maps.shape(1) != 6 || maps.shape(0) < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("maps: an (N, 6) array of a, b, c, d, e, f (got shape {})",
                            std::string(py::str(py::cast(std::vector<py::ssize_t>(
                                maps.shape(), maps.shape() + maps.ndim()))))));
  db::Category c;
  const auto k = maps.unchecked<2>();
  for (py::ssize_t n = 0; n < maps.shape(0); ++n)
    c.maps.push_back(
        AffineMap::from_coefficients({k(n, 0), k(n, 1), k(n, 2), k(n, 3), k(n, 4), k(n, 5)}));
  if (probabilities) {
    if (probabilities->size() != c.maps.size())
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("probabilities: one per map ({}) (got {})", c.maps.size(),
                              probabilities->size()));
    c.probabilities = *probabilities;
  } else {
    // As the search makes them: |det| / Σ|det|.
    double sum = 0;
    for (const AffineMap& f : c.maps) sum += std::abs(f.a * f.d - f.b * f.c);
    for (const AffineMap& f : c.maps)
      c.probabilities.push_back(std::abs(f.a * f.d - f.b * f.c) / sum);
  }
  db::Category checked = db::parse_category(db::category_text(c), name.empty() ? "category" : name);
  checked.name = name;
  return checked;
}

py::array_t<double> maps_array(const db::Category& c) {
  py::array_t<double> out({static_cast<py::ssize_t>(c.maps.size()), py::ssize_t{6}});
  auto k = out.mutable_unchecked<2>();
  for (std::size_t n = 0; n < c.maps.size(); ++n) {
    const auto v = c.maps[n].coefficients();
    for (py::ssize_t i = 0; i < 6; ++i) k(static_cast<py::ssize_t>(n), i) = v[i];
  }
  return out;
}

py::array_t<double> weights_array(const std::vector<db::Weight>& weights) {
  py::array_t<double> out({static_cast<py::ssize_t>(weights.size()), py::ssize_t{6}});
  auto k = out.mutable_unchecked<2>();
  for (std::size_t n = 0; n < weights.size(); ++n)
    for (py::ssize_t i = 0; i < 6; ++i)
      k(static_cast<py::ssize_t>(n), i) = weights[n][static_cast<std::size_t>(i)];
  return out;
}

// Files and folders (every *.csv below) as categories, sorted by name, as `ifsfx dataset`.
std::vector<db::Category> read_paths(const std::vector<std::string>& paths) {
  std::vector<db::Category> out;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      const auto files = db::category_files(path);
      if (files.empty())
        throw Error(ErrorKind::not_found, fmt::format("{}: no category CSV files in it", path));
      for (const fs::path& file : files) out.push_back(db::read_category(file));
    } else {
      out.push_back(db::read_category(path));
    }
  }
  return out;
}

std::vector<db::Category> categories_arg(const py::handle& categories) {
  std::vector<db::Category> out;
  std::vector<std::string> paths;
  const auto add = [&](const py::handle& item) {
    if (py::isinstance<db::Category>(item))
      out.push_back(item.cast<db::Category>());
    else if (is_path(item))
      paths.push_back(path_of(item));
    else
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("categories: a path (a CSV file or a folder of them), a Category, "
                              "or a list of them (got {})",
                              std::string(py::str(py::type::of(item).attr("__name__")))));
  };
  if (is_path(categories) || py::isinstance<db::Category>(categories) ||
      !py::isinstance<py::iterable>(categories))
    add(categories);
  else
    for (const py::handle item : py::iter(categories)) add(item);
  const auto read = run_released([&](const CancelToken&) { return read_paths(paths); });
  out.insert(out.end(), read.begin(), read.end());
  std::stable_sort(out.begin(), out.end(),
                   [](const db::Category& a, const db::Category& b) { return a.name < b.name; });
  return out;
}

std::vector<db::Weight> weights_arg(const py::handle& weights) {
  if (py::isinstance<py::float_>(weights) || py::isinstance<py::int_>(weights))
    return db::weights_table(weights.cast<double>());
  if (is_path(weights)) return db::read_weights(path_of(weights));
  const auto array =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(weights);
  if (!array || array.ndim() != 2 || array.shape(1) != 6 || array.shape(0) < 1)
    throw Error(ErrorKind::invalid_argument,
                "weights: a step K (the reference's weights_K.csv), a weight CSV path, or a (W, "
                "6) array of factors of a..f");
  std::vector<db::Weight> out;
  const auto k = array.unchecked<2>();
  for (py::ssize_t n = 0; n < array.shape(0); ++n) {
    db::Weight w{};
    for (py::ssize_t i = 0; i < 6; ++i) {
      w[static_cast<std::size_t>(i)] = k(n, i);
      if (!std::isfinite(k(n, i)))
        throw Error(ErrorKind::invalid_argument,
                    fmt::format("weights: row {}, column {}: must be a finite number (got {})",
                                n + 1, i + 1, k(n, i)));
    }
    out.push_back(w);
  }
  return out;
}

cv::Size padding_arg(const py::handle& padding) {
  if (py::isinstance<py::int_>(padding)) {
    const int p = padding.cast<int>();
    return {p, p};
  }
  if (py::isinstance<py::str>(padding)) {
    const std::string text = padding.cast<std::string>();
    const std::size_t x = text.find('x');
    try {
      if (x != std::string::npos)
        return {std::stoi(text.substr(0, x)), std::stoi(text.substr(x + 1))};
      return {std::stoi(text), std::stoi(text)};
    } catch (const std::exception&) {
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("padding: N, (x, y) or \"XxY\" (got '{}')", text));
    }
  }
  const auto pair = padding.cast<std::pair<int, int>>();
  return {pair.first, pair.second};
}

struct DatasetState {
  db::DatasetSpec spec;
  bool rgb = false;
  std::vector<double> draws;  // numpy.random.seed(100)'s, shared by every walk
};

// The last walk and canvas made, so that consecutive images of one category and weight share
// them. Shared pointers: a reader copies them out under the Dataset's lock and renders unlocked;
// one held by nobody else is reused in place.
struct RenderCache {
  std::size_t group = static_cast<std::size_t>(-1);
  std::shared_ptr<db::Points> points;
  int instance = -1;
  std::shared_ptr<cv::Mat> canvas;
};

// Image `key`, reusing and updating `cache`. Runs without the GIL.
cv::Mat render(const DatasetState& state, const db::ImageKey& key, RenderCache& cache,
               db::WalkBuffers& buffers) {
  const db::DatasetSpec& spec = state.spec;
  const std::size_t group = key.category * spec.weights.size() + key.weight;
  if (cache.group != group || !cache.points) {
    if (!cache.points || cache.points.use_count() > 1)
      cache.points = std::make_shared<db::Points>();
    db::walk(spec.categories[key.category], spec.weights[key.weight], spec.settings, state.draws,
             *cache.points, buffers);
    cache.group = group;
    cache.instance = -1;
  }
  if (cache.instance != key.instance || !cache.canvas) {
    if (!cache.canvas || cache.canvas.use_count() > 1) cache.canvas = std::make_shared<cv::Mat>();
    db::draw(*cache.points, spec.settings, db::mask_seed(spec, key), *cache.canvas);
    cache.instance = key.instance;
  }
  cv::Mat image;
  db::to_image(*cache.canvas, key.flip, spec.settings.draw, state.rgb, image);
  return image;
}

py::tuple pair(cv::Mat image, std::size_t label) {
  return py::make_tuple(to_array(std::move(image)), label);
}

// A worker's share of a dataset, in order: the categories and weights g = first, first + step,
// ... (category-major), each with its instances and flips.
class Images {
 public:
  Images(std::shared_ptr<const DatasetState> state, std::size_t first, std::size_t step)
      : state_(std::move(state)), group_(first), step_(step) {
    const db::DatasetSpec& spec = state_->spec;
    groups_ = spec.categories.size() * spec.weights.size();
    per_group_ = db::instances_drawn(spec) * db::kFlips;
  }

  std::int64_t remaining() const {
    if (group_ >= groups_) return 0;
    const auto later = static_cast<std::int64_t>((groups_ - 1 - group_) / step_);
    return (later + 1) * per_group_ - in_group_;
  }

  py::tuple next() {
    if (group_ >= groups_) throw py::stop_iteration();
    const db::DatasetSpec& spec = state_->spec;
    const std::size_t weights = spec.weights.size();
    const db::ImageKey key{group_ / weights, group_ % weights, in_group_ / db::kFlips,
                           in_group_ % db::kFlips};
    cv::Mat image;
    {
      const py::gil_scoped_release release;
      image = render(*state_, key, cache_, buffers_);
    }
    if (++in_group_ == per_group_) {
      in_group_ = 0;
      group_ += step_;
    }
    return pair(std::move(image), key.category);
  }

 private:
  std::shared_ptr<const DatasetState> state_;
  std::size_t group_, step_, groups_ = 0;
  int per_group_ = 0, in_group_ = 0;
  RenderCache cache_;
  db::WalkBuffers buffers_;
};

class Dataset {
 public:
  explicit Dataset(std::shared_ptr<const DatasetState> state) : state_(std::move(state)) {}

  const DatasetState& state() const { return *state_; }
  std::int64_t size() const { return db::image_count(state_->spec); }

  std::int64_t index_arg(std::int64_t index) const {
    const std::int64_t n = size();
    if (index < -n || index >= n)
      throw py::index_error(fmt::format("index: the dataset has {} images (got {})", n, index));
    return index < 0 ? index + n : index;
  }

  py::tuple get(std::int64_t index) {
    const db::ImageKey key = db::image_key(state_->spec, index_arg(index));
    cv::Mat image;
    {
      const py::gil_scoped_release release;
      RenderCache cache;
      {
        const std::lock_guard lock(mutex_);
        cache = cache_;
      }
      db::WalkBuffers buffers;
      image = render(*state_, key, cache, buffers);
      const std::lock_guard lock(mutex_);
      cache_ = std::move(cache);
    }
    return pair(std::move(image), key.category);
  }

  Images shard(std::int64_t index, std::int64_t count) const {
    if (count < 1 || index < 0 || index >= count)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("shard: worker index in 0..count-1 and count ≥ 1 (got {} of {})",
                              index, count));
    return Images(state_, static_cast<std::size_t>(index), static_cast<std::size_t>(count));
  }

 private:
  std::shared_ptr<const DatasetState> state_;
  std::mutex mutex_;
  RenderCache cache_;
};

std::unique_ptr<Dataset> make_dataset(const py::object& categories, const py::object& weights,
                                      const std::string& draw, const py::object& size,
                                      const py::object& padding, int iterations, int instances,
                                      std::uint64_t seed, bool rgb) {
  auto state = std::make_shared<DatasetState>();
  db::DatasetSpec& spec = state->spec;
  spec.settings.draw = db::parse_draw_type(draw);
  spec.settings.size = size_arg(size);
  spec.settings.padding = padding_arg(padding);
  spec.settings.iterations = iterations;
  spec.instances = instances;
  spec.seed = seed;
  db::check(spec.settings);
  spec.weights = weights_arg(weights);
  spec.categories = categories_arg(categories);
  db::check(spec);
  state->rgb = rgb;
  state->draws = db::reference_draws(iterations);
  return std::make_unique<Dataset>(std::move(state));
}

constexpr const char* kDatasetDoc =
    R"doc(A FractalDB dataset in memory: categories × weights × instances × 4 flips, each item an
(image, label) pair, as `ifsfx dataset render` writes them (docs/dataset.md): the image equals
the pixels of the file the command writes for the same settings, the label is the category's
index (categories sorted by name: torchvision ImageFolder's class index of its folder).

Map-style (len, [i]) and iterable (iter, shard): a PyTorch DataLoader takes it as it is, with
any number of workers and shuffle=True: item i is a pure function of (settings, seed, i), so no
worker needs seeding. Iterating is fastest (a walk serves all the instances and flips of a
category and weight); for an IterableDataset give each worker its share:

    def __iter__(self):                      # in a torch IterableDataset
        info = torch.utils.data.get_worker_info()
        return iter(self.db.shard(info.id, info.num_workers) if info else self.db)

The masks of the patches come from `seed`: another seed (say the epoch) gives other patches.
Rendering releases the GIL: several Python threads render at once.

categories: a category CSV path, a folder of them (every *.csv below), a Category, or a list
    of these.
weights: a step K (default 0.1: the reference's weights_0.1.csv table, 25 weights), a weight
    CSV path, or a (W, 6) array of factors of a, b, c, d, e, f.
draw: "point_gray", "point_color", "patch_gray" (default) or "patch_color".
size: (width, height) or "WxH", default (512, 512). padding: pixels left free at each side,
    N or (x, y), default (6, 6). iterations: chaos-game points per picture, default 100000.
instances: pictures per category and weight for the patch types, default 10 (the point types
    draw one). seed: default 1. rgb: False (default): H×W×3 uint8 in BGR order, like cv2;
    True: RGB, like PIL and torchvision.)doc";

// The Category class: maps and probabilities, as a category CSV holds them.
void bind_category(py::module_& f) {
  py::class_<db::Category>(f, "Category", R"doc(
One FractalDB category: affine maps f(x, y) = (a x + b y + e, c x + d y + f) and the
probability p of each, as a category CSV holds them (rows a,b,c,d,e,f,p).
)doc")
      .def(
          py::init(&category_from_arrays), py::arg("maps"), py::arg("probabilities") = py::none(),
          py::arg("name") = "",
          R"doc(maps: (N, 6) array of a, b, c, d, e, f per map. probabilities: N numbers summing to 1,
default None: |det| / Σ|det|, as the search makes them. name: the category's name (its folder
and file names), default "". Raises ValueError as read_category does for its file.)doc")
      .def_property_readonly("name", [](const db::Category& c) { return c.name; })
      .def_property_readonly("maps", &maps_array, "(N, 6) float64 array of a, b, c, d, e, f")
      .def_property_readonly(
          "probabilities", [](const db::Category& c) { return c.probabilities; },
          "p per map, as written (they sum to 1)")
      .def_property_readonly("text", &db::category_text,
                             "the category as a CSV file's text (np.savetxt's %.18e, as the "
                             "search writes it)")
      .def_property_readonly(
          "contraction_rate",
          [](const db::Category& c) { return db::contraction_rate(c.maps, c.probabilities); },
          "how fast the chaos game contracts per step (natural log): < 0 for every readable "
          "category")
      .def("__len__", [](const db::Category& c) { return c.maps.size(); })
      .def("__repr__",
           [](const db::Category& c) {
             return fmt::format("<ifsfx.fractaldb.Category '{}': {} maps>", c.name, c.maps.size());
           })
      .def(py::pickle(
          [](const db::Category& c) {
            return py::make_tuple(c.name, maps_array(c), c.probabilities);
          },
          [](const py::tuple& t) {
            db::Category c;
            c.name = t[0].cast<std::string>();
            const auto maps =
                t[1].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
            const auto k = maps.unchecked<2>();
            for (py::ssize_t n = 0; n < maps.shape(0); ++n)
              c.maps.push_back(AffineMap::from_coefficients(
                  {k(n, 0), k(n, 1), k(n, 2), k(n, 3), k(n, 4), k(n, 5)}));
            c.probabilities = t[2].cast<std::vector<double>>();
            return c;
          }));
}

// The file readers and the category search.
void bind_readers(py::module_& f) {
  f.def(
      "read_category",
      [](const py::object& path) {
        const std::string p = path_of(path);
        return run_released([&](const CancelToken&) { return db::read_category(p); });
      },
      py::arg("path"),
      R"doc(A category CSV (rows a,b,c,d,e,f,p) as a Category named by the file's stem. Raises
ValueError "FILE:LINE: ..." for a malformed row or number, "FILE: ..." for probabilities that
do not sum to 1 or maps that do not contract on average (FractalDB's search drops those: their
points collapse into a few pixels); FileNotFoundError, OSError.)doc");
  f.def(
      "read_categories", [](const py::object& paths) { return categories_arg(paths); },
      py::arg("paths"),
      R"doc(Categories from a CSV path, a folder (every *.csv below it, as the reference's
csv0/ csv1/ ... layout) or a list of these, sorted by name: their labels' order.)doc");
  f.def(
      "read_weights",
      [](const py::object& path) { return weights_array(db::read_weights(path_of(path))); },
      py::arg("path"),
      R"doc(A weight CSV (rows wa,wb,wc,wd,we,wf: factors of a..f) as a (W, 6) float64 array.)doc");
  f.def(
      "weights_table", [](double step) { return weights_array(db::weights_table(step)); },
      py::arg("step") = db::kDefaultWeightStep,
      R"doc(The reference's weights_K.csv for K = step (default 0.1) as a (25, 6) array: all ones, and
each of a..f in turn times 1-2K, 1-K, 1+K, 1+2K.)doc");
  const db::SearchOptions d;
  f.def(
      "search",
      [](int categories, double rate, int points, std::uint32_t seed) {
        return run_released([&](const CancelToken& cancel) {
          return db::search({.categories = categories,
                             .rate = rate,
                             .points = points,
                             .seed = seed,
                             .cancel = cancel});
        });
      },
      py::arg("categories") = d.categories, py::kw_only(), py::arg("rate") = d.rate,
      py::arg("points") = d.points, py::arg("seed") = d.seed,
      R"doc(FractalDB's category search (param_search/ifs_search.py), with NumPy's draws: random IFSs
of 2 to 7 maps, kept when their 512×512 point picture of `points` points (default 100000)
lights at least `rate` (default 0.2) of its pixels; `categories` of them (default 1000),
named "00000", ...; seed: numpy.random.seed, default 1 (the reference's: its
csv_rate0.2_category1000 files). The GIL is released; Ctrl-C stops it.)doc");
}

// The settings a Dataset was made with, read-only, and its pickling.
void add_dataset_settings(py::class_<Dataset>& dataset) {
  dataset
      .def_property_readonly(
          "classes",
          [](const Dataset& self) {
            std::vector<std::string> names;
            for (const auto& c : self.state().spec.categories) names.push_back(c.name);
            return names;
          },
          "the categories' names, by label")
      .def_property_readonly("categories",
                             [](const Dataset& self) { return self.state().spec.categories; })
      .def_property_readonly(
          "weights", [](const Dataset& self) { return weights_array(self.state().spec.weights); })
      .def_property_readonly(
          "draw",
          [](const Dataset& self) { return db::to_string(self.state().spec.settings.draw); })
      .def_property_readonly("size",
                             [](const Dataset& self) {
                               const cv::Size s = self.state().spec.settings.size;
                               return py::make_tuple(s.width, s.height);
                             })
      .def_property_readonly("padding",
                             [](const Dataset& self) {
                               const cv::Size s = self.state().spec.settings.padding;
                               return py::make_tuple(s.width, s.height);
                             })
      .def_property_readonly(
          "iterations", [](const Dataset& self) { return self.state().spec.settings.iterations; })
      .def_property_readonly("instances",
                             [](const Dataset& self) { return self.state().spec.instances; })
      .def_property_readonly("seed", [](const Dataset& self) { return self.state().spec.seed; })
      .def_property_readonly("rgb", [](const Dataset& self) { return self.state().rgb; })
      // For DataLoader workers started by spawn (the default off Linux): the settings travel,
      // the dataset is made again on the other side.
      .def(py::pickle(
          [](const Dataset& self) {
            const db::DatasetSpec& spec = self.state().spec;
            const db::DrawSettings& s = spec.settings;
            return py::make_tuple(spec.categories, weights_array(spec.weights),
                                  db::to_string(s.draw),
                                  py::make_tuple(s.size.width, s.size.height),
                                  py::make_tuple(s.padding.width, s.padding.height), s.iterations,
                                  spec.instances, spec.seed, self.state().rgb);
          },
          [](const py::tuple& t) {
            return make_dataset(t[0], t[1], t[2].cast<std::string>(), t[3], t[4], t[5].cast<int>(),
                                t[6].cast<int>(), t[7].cast<std::uint64_t>(), t[8].cast<bool>());
          }));
}

// Dataset and the iterator over its shards.
void bind_dataset(py::module_& f) {
  py::class_<Images>(f, "Images", "An iterator of (image, label) over a Dataset or a shard of it.")
      .def("__iter__", [](Images& self) -> Images& { return self; })
      .def("__next__", &Images::next)
      .def("__len__", &Images::remaining, "the images still to come");

  const db::DatasetSpec spec_defaults;
  const db::DrawSettings& settings = spec_defaults.settings;
  py::class_<Dataset> dataset(f, "Dataset", kDatasetDoc);
  dataset
      .def(py::init(&make_dataset), py::arg("categories"),
           py::arg("weights") = db::kDefaultWeightStep, py::kw_only(),
           py::arg("draw") = db::to_string(settings.draw),
           py::arg("size") = py::make_tuple(settings.size.width, settings.size.height),
           py::arg("padding") = py::make_tuple(settings.padding.width, settings.padding.height),
           py::arg("iterations") = settings.iterations,
           py::arg("instances") = spec_defaults.instances, py::arg("seed") = spec_defaults.seed,
           py::arg("rgb") = false)
      .def("__len__", &Dataset::size)
      .def("__getitem__", &Dataset::get, py::arg("index"),
           "(image, label) of image `index`, in the order the command writes them: category, "
           "weight, instance, flip (the last fastest)")
      .def(
          "__iter__", [](const Dataset& self) { return self.shard(0, 1); },
          "every (image, label) in order")
      .def("shard", &Dataset::shard, py::arg("index"), py::arg("count"),
           "An iterator over worker `index`'s share of `count` (whole categories and weights "
           "taken in turn): the shards of 0..count-1 together hold every image once.")
      .def(
          "path",
          [](const Dataset& self, std::int64_t index) {
            const auto& spec = self.state().spec;
            return db::image_path(spec, db::image_key(spec, self.index_arg(index)));
          },
          py::arg("index"),
          "image `index`'s file in the folder `ifsfx dataset render` writes: "
          "NAME/NAME_WW_count_I_flipT.png")
      .def(
          "key",
          [](const Dataset& self, std::int64_t index) {
            const auto k = db::image_key(self.state().spec, self.index_arg(index));
            return py::make_tuple(k.category, k.weight, k.instance, k.flip);
          },
          py::arg("index"), "(category, weight, instance, flip) of image `index`");
  add_dataset_settings(dataset);
}

}  // namespace

void bind_fractaldb(py::module_& m) {
  py::module_ f = m.def_submodule(
      "fractaldb",
      R"doc(FractalDB (formula-driven supervised learning, Kataoka et al.): category and weight files,
the category search, and datasets in memory, as the reference generator
(hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch) makes them; `ifsfx dataset` writes
the same pictures to files (docs/dataset.md).

    from ifsfx import fractaldb
    data = fractaldb.Dataset("csv_rate0.2_category1000", weights=0.4, size=(362, 362))
    image, label = data[0]
)doc");
  py::module_::import("sys").attr("modules")["ifsfx.fractaldb"] = f;

  bind_category(f);
  bind_readers(f);
  bind_dataset(f);
}

}  // namespace ifsfx::python
