// SPDX-License-Identifier: Apache-2.0
// A small frei0r host of our own: loads a plugin with dlopen, runs it over raw RGBA frames through
// the frei0r API alone, and writes the frames it returns — what FFmpeg, MLT and GStreamer do,
// without them, so that the plugins can run in the sanitizer build and in orders no host offers.
//
//   frei0r_host PLUGIN.so --size WxH --frames N [--input IN.rgba] [--fps F] [--order
//   forward|reverse]
//               [--instances K] [--times seconds|none] [--param I=VALUE]...
//               [--set FRAME:I=VALUE]... -o OUT.rgba
//
// Frame j is shown at time j / fps seconds (with --times none, at the time FFmpeg 5.1 passes for a
// frame without a timestamp: AV_NOPTS_VALUE · 1000 / 25), rendered by instance j mod K (each
// instance on its own thread, in the given order) and written at its place in OUT whatever the
// order. --param sets a parameter of every instance before the first frame; --set changes one
// before frame FRAME of the instance that renders it (mid-stream, as an editor's keyframes do). A
// flag takes y/n or a number.
#include <dlfcn.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern "C" {
#include <frei0r.h>  // declares the API without extern "C"
}

namespace {

struct Api {
  int (*init)();
  void (*deinit)();
  void (*get_plugin_info)(f0r_plugin_info_t*);
  void (*get_param_info)(f0r_param_info_t*, int);
  f0r_instance_t (*construct)(unsigned, unsigned);
  void (*destruct)(f0r_instance_t);
  void (*set_param_value)(f0r_instance_t, f0r_param_t, int);
  void (*update)(f0r_instance_t, double, const std::uint32_t*, std::uint32_t*);
};

template <class F>
void bind(void* handle, const char* name, F& f) {
  f = reinterpret_cast<F>(dlsym(handle, name));
  if (f == nullptr) throw std::runtime_error(std::string("plugin lacks ") + name);
}

struct Setting {
  int index;
  std::string value;
};

struct Args {
  std::string plugin, input, output;
  unsigned width = 0, height = 0;
  int frames = 0, instances = 1;
  double fps = 25;
  bool reverse = false;
  bool timeless = false;  // --times none
  std::vector<Setting> params;
  std::multimap<int, Setting> changes;  // by frame
};

Setting parse_setting(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw std::runtime_error("expected I=VALUE (got " + text + ")");
  return {std::stoi(text.substr(0, eq)), text.substr(eq + 1)};
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--size") {
      const std::string s = next();
      a.width = static_cast<unsigned>(std::stoul(s));
      a.height = static_cast<unsigned>(std::stoul(s.substr(s.find('x') + 1)));
    } else if (arg == "--frames") {
      a.frames = std::stoi(next());
    } else if (arg == "--input") {
      a.input = next();
    } else if (arg == "--fps") {
      a.fps = std::stod(next());
    } else if (arg == "--order") {
      a.reverse = next() == "reverse";
    } else if (arg == "--times") {
      const std::string t = next();
      if (t != "seconds" && t != "none") throw std::runtime_error("--times: seconds or none");
      a.timeless = t == "none";
    } else if (arg == "--instances") {
      a.instances = std::stoi(next());
    } else if (arg == "--param") {
      a.params.push_back(parse_setting(next()));
    } else if (arg == "--set") {
      const std::string s = next();
      a.changes.emplace(std::stoi(s.substr(0, s.find(':'))),
                        parse_setting(s.substr(s.find(':') + 1)));
    } else if (arg == "-o") {
      a.output = next();
    } else if (a.plugin.empty()) {
      a.plugin = arg;
    } else {
      throw std::runtime_error("unknown argument " + arg);
    }
  }
  if (a.plugin.empty() || a.output.empty() || a.width == 0 || a.height == 0 || a.frames < 1 ||
      a.instances < 1)
    throw std::runtime_error("usage: frei0r_host PLUGIN --size WxH --frames N -o OUT [...]");
  return a;
}

void set(const Api& api, f0r_instance_t instance, const Setting& s) {
  f0r_param_info_t info{};
  api.get_param_info(&info, s.index);
  if (info.type == F0R_PARAM_STRING) {
    const char* text = s.value.c_str();
    api.set_param_value(instance, &text, s.index);
  } else {
    double value = s.value == "y" ? 1.0 : s.value == "n" ? 0.0 : std::stod(s.value);
    api.set_param_value(instance, &value, s.index);
  }
}

int run(const Args& a) {
  void* handle = dlopen(a.plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) throw std::runtime_error(dlerror());
  Api api{};
  bind(handle, "f0r_init", api.init);
  bind(handle, "f0r_deinit", api.deinit);
  bind(handle, "f0r_get_plugin_info", api.get_plugin_info);
  bind(handle, "f0r_get_param_info", api.get_param_info);
  bind(handle, "f0r_construct", api.construct);
  bind(handle, "f0r_destruct", api.destruct);
  bind(handle, "f0r_set_param_value", api.set_param_value);
  bind(handle, "f0r_update", api.update);
  if (api.init() != 1) throw std::runtime_error("f0r_init failed");
  f0r_plugin_info_t info{};
  api.get_plugin_info(&info);
  const bool source = info.plugin_type == F0R_PLUGIN_TYPE_SOURCE;

  const std::size_t pixels = std::size_t{a.width} * a.height;
  std::vector<std::uint32_t> in(source ? 0 : pixels * static_cast<std::size_t>(a.frames));
  if (!source) {
    std::ifstream file(a.input, std::ios::binary);
    if (!file.read(reinterpret_cast<char*>(in.data()), static_cast<std::streamsize>(in.size() * 4)))
      throw std::runtime_error("cannot read " + std::to_string(a.frames) + " frames from " +
                               a.input);
  }
  std::vector<std::uint32_t> out(pixels * static_cast<std::size_t>(a.frames));

  std::vector<f0r_instance_t> instances;
  for (int k = 0; k < a.instances; ++k) {
    instances.push_back(api.construct(a.width, a.height));
    if (instances.back() == nullptr) throw std::runtime_error("f0r_construct failed");
    for (const Setting& s : a.params) set(api, instances.back(), s);
  }
  std::vector<std::thread> threads;
  for (int k = 0; k < a.instances; ++k) {
    threads.emplace_back([&, k] {
      for (int n = 0; n < a.frames; ++n) {
        const int j = a.reverse ? a.frames - 1 - n : n;
        if (j % a.instances != k) continue;
        const auto [first, last] = a.changes.equal_range(j);
        for (auto it = first; it != last; ++it)
          set(api, instances[static_cast<std::size_t>(k)], it->second);
        const std::size_t at = pixels * static_cast<std::size_t>(j);
        const double nopts = static_cast<double>(INT64_MIN) * 1000 / 25;
        api.update(instances[static_cast<std::size_t>(k)], a.timeless ? nopts : j / a.fps,
                   source ? nullptr : &in[at], &out[at]);
      }
    });
  }
  for (auto& t : threads) t.join();
  for (f0r_instance_t instance : instances) api.destruct(instance);
  api.deinit();
  dlclose(handle);

  std::ofstream file(a.output, std::ios::binary);
  file.write(reinterpret_cast<const char*>(out.data()),
             static_cast<std::streamsize>(out.size() * 4));
  if (!file) throw std::runtime_error("cannot write " + a.output);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << "frei0r_host: " << e.what() << "\n";
    return 1;
  }
}
