// SPDX-License-Identifier: Apache-2.0
// The subcommands of `ifsfx`. Each lives in its own file, cli/<name>_command.cpp, and registers
// itself on the top-level CLI11 app; main() turns any error into one line and an exit code.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace ifsfx::app {

void add_presets_command(CLI::App& app);  // list shipped presets
void add_render_command(CLI::App& app);   // render an IFS to a still
void add_apply_command(CLI::App& app);    // colour an image through a saved steal map
void add_fit_command(CLI::App& app);      // fit an IFS to a shape (collage theorem)
void add_texture_command(CLI::App& app);  // render a superIFS texture or texture sequence
void add_cam_command(CLI::App& app);      // live camera kaleidoscope over V4L2
void add_filter_command(CLI::App& app);   // fractal video filter on movie files
void add_info_command(CLI::App& app);     // version, build and kernel level
void add_farm_command(CLI::App& app);     // shard filter/texture over a Slurm cluster
void add_studio_command(CLI::App& app);   // local web editor (docs/studio.md)
void add_dataset_command(CLI::App& app);  // FractalDB datasets (docs/dataset.md)

// "ifsfx VERSION (BUILD TYPE build, ...)" and the kernel level line, for --version and `info`.
std::string version_text();

}  // namespace ifsfx::app
