// SPDX-License-Identifier: Apache-2.0
// `ifsfx presets [FILE...]`: one aligned line per shipped IFS preset (name, maps, contraction
// factor, description), or per entry of the files given. The names are what `ifsfx render NAME`
// (or FILE.ifs:NAME) accepts.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.h"
#include "flame/flame_file.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "superifs/superifs_file.h"

namespace ifsfx::app {
namespace {

// What ends the line of a preset offered as a seamless tile (`--seamless`, docs/seamless.md).
std::string seamless_mark(bool seamless) {
  return seamless ? " [seamless tile]" : "";
}

// One aligned line per preset: name, maps, contraction factor, description (or why it cannot be
// used), and whether it is offered as a seamless tile.
std::string preset_lines(const std::vector<PresetSummary>& presets) {
  std::size_t width = 0;
  for (const auto& p : presets) width = std::max(width, p.name.size());
  std::string out;
  for (const auto& p : presets)
    out += p.problem.empty()
               ? fmt::format("{:<{}}  {:>2} maps  factor {:<6.4g}  {}{}\n", p.name, width, p.maps,
                             p.contraction, p.description, seamless_mark(p.seamless))
               : fmt::format("{:<{}}  not usable: {}\n", p.name, width, p.problem);
  return out;
}

// One line per flame of a flame file: how to pick it (FILE:NAME, or FILE:INDEX for a flame
// without a name), its xforms, or why it cannot be rendered.
std::string flame_lines(const std::string& file) {
  const std::vector<flame::FlameEntry> flames = flame::list_flames(file);
  const auto pick = [&](const flame::FlameEntry& f) {
    return fmt::format("{}:{}", file, f.name.empty() ? std::to_string(f.index) : f.name);
  };
  std::size_t width = 0;
  for (const auto& f : flames) width = std::max(width, pick(f).size());
  std::string out;
  for (const auto& f : flames)
    out += f.problem.empty()
               ? fmt::format("{:<{}}  {:>2} xforms{}\n", pick(f), width, f.xforms,
                             f.name.empty() ? "" : fmt::format("  (or {}:{})", file, f.index))
               : fmt::format("{:<{}}  not usable: {}\n", pick(f), width, f.problem);
  return out;
}

}  // namespace

void add_presets_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "presets",
      "List the shipped IFS presets: name, number of maps, contraction factor, description.\n"
      "Name one on the command line, or give a path to a .toml, .ifs or .flame file to list its\n"
      "entries (FILE.ifs:NAME, FILE.flame:NAME or FILE.flame:INDEX for one of them).\n"
      "--super lists the superIFS presets of `ifsfx texture`.");
  auto super = std::make_shared<bool>(false);
  auto files = std::make_shared<std::vector<std::string>>();
  cmd->add_flag("--super", *super,
                "List the shipped superIFS presets (for `ifsfx texture` and "
                "`ifsfx filter --animate superifs`) instead");
  cmd->add_option("file", *files,
                  "List the presets of these files instead: every entry of a Fractint .ifs file "
                  "(render one as FILE.ifs:NAME), every flame of a .flame file (FILE.flame:NAME "
                  "or FILE.flame:INDEX), with why an entry cannot be used, or the preset of a "
                  ".toml file");
  cmd->callback([super, files] {
    if (!files->empty()) {
      if (*super) throw Error(ErrorKind::invalid_argument, "--super: lists shipped presets only");
      std::string out;
      for (const auto& file : *files)
        out += flame::is_flame_spec(file) ? flame_lines(file) : preset_lines(list_presets_in(file));
      std::fputs(out.c_str(), stdout);
      return;
    }
    if (*super) {
      const auto presets = list_shipped_superifs();
      std::size_t width = 0;
      for (const auto& p : presets) width = std::max(width, p.name.size());
      std::string out;
      for (const auto& p : presets)
        out +=
            fmt::format("{:<{}}  {}{}\n", p.name, width, p.description, seamless_mark(p.seamless));
      std::fputs(out.c_str(), stdout);
      return;
    }
    std::fputs(preset_lines(list_shipped_presets()).c_str(), stdout);
  });
}

}  // namespace ifsfx::app
