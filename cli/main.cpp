// SPDX-License-Identifier: Apache-2.0
// ifsfx-full: every command of ifsfx. The installed `ifsfx` is the light binary
// (cli/light_main.cpp), which runs `render` to PNG itself and hands every other command line to
// this one unchanged (exec: the same process). main() builds the command line, runs one
// subcommand, and turns every error into a single line "ifsfx: ..." and an exit code (run_cli).
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/run_cli.h"

int main(int argc, char** argv) {
  CLI::App app{ifsfx::app::kDescription};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show the help of every command");
  app.set_version_flag("--version", ifsfx::app::version_text,
                       "Show the version, the build and the kernel level used here, and exit");
  ifsfx::app::add_presets_command(app);
  ifsfx::app::add_render_command(app);
  ifsfx::app::add_apply_command(app);
  ifsfx::app::add_fit_command(app);
  ifsfx::app::add_texture_command(app);
  ifsfx::app::add_cam_command(app);
  ifsfx::app::add_filter_command(app);
  ifsfx::app::add_info_command(app);
  ifsfx::app::add_farm_command(app);
  ifsfx::app::add_studio_command(app);
  ifsfx::app::add_dataset_command(app);
  return ifsfx::app::run_cli(app, argc, argv);
}
