// SPDX-License-Identifier: Apache-2.0
#include "studio/superifs.h"

#include <vector>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "run/arguments.h"
#include "studio/fields.h"

namespace ifsfx::app {

using nlohmann::json;

namespace {

std::vector<double> numbers(const json& value, const std::string& field) {
  if (!value.is_array()) bad_field(field, "must be a list of numbers", value);
  std::vector<double> out;
  for (const json& v : value) {
    if (!v.is_number()) bad_field(field, "must be a list of numbers", value);
    out.push_back(v.get<double>());
  }
  return out;
}

Ifs ifs_from_json(const json& table, const std::string& field) {
  if (!table.is_object()) bad_field(field, "must be an object {\"maps\": [...]}", table);
  Ifs f;
  f.name = text_field(table, "name", "");
  const auto maps = table.find("maps");
  if (maps == table.end() || !maps->is_array() || maps->empty())
    bad_field(field + " maps", "must be a non-empty list of [a, b, c, d, e, f]",
              maps == table.end() ? json("nothing") : *maps);
  if (maps->size() > 64) bad_field(field + " maps", "at most 64", json(maps->size()));
  for (std::size_t i = 0; i < maps->size(); ++i) {
    const auto k = numbers((*maps)[i], fmt::format("{} map {}", field, i + 1));
    if (k.size() != 6)
      bad_field(fmt::format("{} map {}", field, i + 1), "must be [a, b, c, d, e, f]", (*maps)[i]);
    f.maps.push_back({k[0], k[1], k[2], k[3], k[4], k[5]});
  }
  if (const auto p = table.find("probabilities"); p != table.end() && !p->is_null())
    f.probabilities = numbers(*p, field + " probabilities");
  return f;
}

json ifs_to_json(const Ifs& f) {
  json maps = json::array();
  for (const auto& m : f.maps) maps.push_back(m.coefficients());
  return {{"name", f.name}, {"maps", maps}, {"probabilities", f.probabilities}};
}

std::vector<Ifs> ifs_list(const json& body, const char* key, const char* what, bool required) {
  const auto it = body.find(key);
  if (it == body.end() || it->is_null()) {
    if (required) bad_field(key, "must be a non-empty list of IFSs", json("nothing"));
    return {};
  }
  if (!it->is_array() || (required && it->empty()))
    bad_field(key, "must be a non-empty list of IFSs", *it);
  if (it->size() > 16) bad_field(key, "at most 16 IFSs", json(it->size()));
  std::vector<Ifs> out;
  for (std::size_t n = 0; n < it->size(); ++n)
    out.push_back(ifs_from_json((*it)[n], fmt::format("{} {}", what, n + 1)));
  return out;
}

}  // namespace

SuperIfsPreset superifs_from_json(const json& body) {
  if (!body.is_object()) bad_field("superifs", "must be a JSON object", body);
  SuperIfs super;
  super.name = text_field(body, "name", "studio");
  if (super.name.empty()) super.name = "studio";
  const std::string description = text_field(body, "description", "");
  super.ifs = ifs_list(body, "ifs", "IFS", true);
  super.colouring = ifs_list(body, "colouring", "colouring", false);
  if (const auto p = body.find("probabilities"); p != body.end() && !p->is_null())
    super.probabilities = numbers(*p, "probabilities");
  if (const auto v = body.find("view"); v != body.end() && !v->is_null()) {
    const auto box = numbers(*v, "view");
    if (box.size() != 4) bad_field("view", "must be [x0, y0, x1, y1]", *v);
    super.view = Box{box[0], box[1], box[2], box[3]};
  }
  validate(super, super.name);
  // Through the TOML text, as `ifsfx texture` reads a saved superIFS: the same SuperIfs.
  return parse_superifs_toml(to_toml(super, description), super.name + ".super.toml");
}

json superifs_to_json(const SuperIfsPreset& preset) {
  const SuperIfs& s = preset.super;
  json ifs = json::array(), colouring = json::array();
  for (const Ifs& f : s.ifs) ifs.push_back(ifs_to_json(f));
  for (const Ifs& g : s.colouring) colouring.push_back(ifs_to_json(g));
  json view = nullptr;
  if (s.view) view = {s.view->x0, s.view->y0, s.view->x1, s.view->y1};
  return {{"name", s.name},
          {"description", preset.description},
          {"probabilities", s.probabilities},
          {"view", view},
          {"ifs", ifs},
          {"colouring", colouring}};
}

std::string TexturePreviews::frame_png(const json& body, const std::string& client,
                                       StudioContext& context) {
  if (!body.is_object()) bad_field("request", "must be a JSON object", body);
  if (!body.contains("superifs")) bad_field("superifs", "must be given", json("nothing"));
  const SuperIfsPreset preset = superifs_from_json(body["superifs"]);
  const std::string size_text = text_field(body, "size", "384x384");
  const cv::Size size = size_option(size_text, "size");
  if (size.width > 1024 || size.height > 1024)
    bad_field("size", "at most 1024x1024 for a preview (a texture job makes larger ones)",
              json(size_text));
  const int V = static_cast<int>(integer_field(body, "V", 3, 1, 64));
  const int buffer = static_cast<int>(integer_field(body, "buffer", 1, 1, V));
  const std::string mode_text =
      choice_field(body, "mode", "attractor", {"attractor", "tops", "steal", "measure"});
  const std::int64_t step = integer_field(body, "step", 0, 0, 10000);
  const auto seed = static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  const std::string source = mode_text == "steal" ? text_field(body, "source", "sample") : "";
  const std::filesystem::path source_path = source.empty() ? "" : context.source_path(source);
  const std::string key =
      json{preset.text, V, buffer, mode_text, size_text, seed, source_path.string()}.dump();

  std::shared_ptr<Entry> entry;
  {
    std::lock_guard lock(mutex_);
    if (stopping_) throw Error(ErrorKind::interrupted, "texture: the server is stopping");
    auto& slot = entries_[client];
    if (!slot || slot->key != key) {
      if (slot) slot->stop = true;  // a burn-in of the old settings stops (409)
      slot = std::make_shared<Entry>();
      slot->key = key;
    }
    slot->used = ++clock_;
    entry = slot;
    while (entries_.size() > kMaxTabs) {  // forget the tab used longest ago
      auto oldest = entries_.begin();
      for (auto it = entries_.begin(); it != entries_.end(); ++it)
        if (it->second->used < oldest->second->used) oldest = it;
      oldest->second->stop = true;
      entries_.erase(oldest);
    }
  }
  cv::Mat image;
  {
    std::lock_guard build(entry->build);
    if (!entry->sequence) {
      TextureOptions options;
      options.count = V;
      options.buffer = buffer - 1;
      options.mode = parse_texture_mode(mode_text, "mode");
      options.sampling.seed = seed;
      options.sampling.cancel = CancelToken(&entry->stop);
      if (!source_path.empty()) options.source = read_image(source_path).pixels;
      entry->sequence = std::make_unique<TextureSequence>(preset.super, size, options);
    }
    image = entry->sequence->frame_at(step);
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", image, png))
    throw Error(ErrorKind::io, "texture: cannot encode the picture as PNG");
  return {png.begin(), png.end()};
}

void TexturePreviews::stop_all() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  for (auto& [client, entry] : entries_) entry->stop = true;
}

}  // namespace ifsfx::app
