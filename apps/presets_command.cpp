// `ifsfx presets`: one aligned line per shipped IFS preset (name, maps, contraction factor,
// description). The names are what `ifsfx render NAME` accepts.
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "apps/commands.h"
#include "ifs/preset.h"
#include "superifs/superifs_file.h"

namespace ifsfx::app {

void add_presets_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "presets",
      "List the shipped IFS presets: name, number of maps, contraction factor, description.\n"
      "Name one on the command line, or give a path to a .toml or .ifs file (FILE.ifs:NAME for\n"
      "one entry of a Fractint file). --super lists the superIFS presets of `ifsfx texture`.");
  auto super = std::make_shared<bool>(false);
  cmd->add_flag("--super", *super,
                "List the shipped superIFS presets (for `ifsfx texture` and "
                "`ifsfx filter --animate superifs`) instead");
  cmd->callback([super] {
    if (*super) {
      const auto presets = list_shipped_superifs();
      std::size_t width = 0;
      for (const auto& p : presets) width = std::max(width, p.name.size());
      std::string out;
      for (const auto& p : presets)
        out += fmt::format("{:<{}}  {}\n", p.name, width, p.description);
      std::fputs(out.c_str(), stdout);
      return;
    }
    const auto presets = list_shipped_presets();
    std::size_t width = 0;
    for (const auto& p : presets) width = std::max(width, p.name.size());
    std::string out;
    for (const auto& p : presets)
      out += fmt::format("{:<{}}  {:>2} maps  factor {:<6.4g}  {}\n", p.name, width, p.maps,
                         p.contraction, p.description);
    std::fputs(out.c_str(), stdout);
  });
}

}  // namespace ifsfx::app
