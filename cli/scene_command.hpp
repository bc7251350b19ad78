// `stepwise scene ...`: the commands on one ray-tracer scene file (docs/tracer/scene-format.md).
// `check` validates it and prints a summary; `render` and `plan` go beside it: each adds its
// options and CLI::App* here, one block in add_scene_commands and one line in run_scene_commands.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace sw::cli {

// main keeps this alive while parsing: the subcommands write their options into it.
struct SceneCommands {
  CLI::App* group = nullptr;
  CLI::App* check = nullptr;
  std::string check_file;
  bool check_json = false;
};

void add_scene_commands(CLI::App& app, SceneCommands& c);
// Runs the subcommand given; returns its exit code. Throws InputError on bad input (nothing printed).
int run_scene_commands(const SceneCommands& c);

}  // namespace sw::cli
