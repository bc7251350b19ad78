// `stepwise scene check SCENE [--json]` (scene_command.hpp). The scene is read and validated in
// full before anything is printed, so a bad scene prints only the error line.
#include "scene_command.hpp"
#include <iostream>
#include "tracer/scene.hpp"

namespace sw::cli {

void add_scene_commands(CLI::App& app, SceneCommands& c) {
  c.group = app.add_subcommand("scene", "Ray-tracer scenes: check (render and plan come later)");
  c.group->require_subcommand(1);
  c.check = c.group->add_subcommand("check", "Validate a scene file and print a summary (docs/tracer/scene-format.md)");
  c.check->add_option("scene", c.check_file, "Scene file (JSON)")->required();
  c.check->add_flag("--json", c.check_json, "Print the summary as one JSON object");
}

int run_scene_commands(const SceneCommands& c) {
  if (*c.check) {
    const tracer::Scene s = tracer::read_scene_file(c.check_file);
    if (c.check_json) std::cout << tracer::scene_summary(s).dump() << '\n';
    else std::cout << tracer::scene_summary_text(s);
    return 0;
  }
  return 2;
}

}  // namespace sw::cli
