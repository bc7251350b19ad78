// `stepwise scene ...`: the commands on one ray-tracer scene file (docs/tracer/scene-format.md).
// `check` validates it and prints a summary; `plan` prints the effect plan; `render` renders it;
// `export-pov` writes it as POV-Ray SDL (docs/tracer/povray.md); `raster` draws it with the
// pipeline family's rasterizer (docs/pipeline/semantics.md#scene-raster).
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include "budget.hpp"

namespace sw::cli {

// main keeps this alive while parsing: the subcommands write their options into it.
struct SceneCommands {
  CLI::App* group = nullptr;
  CLI::App *check = nullptr, *plan = nullptr, *render = nullptr, *export_pov = nullptr, *raster = nullptr;
  std::string file;
  bool json = false;
  std::string out, offset = "robust";
  std::optional<std::string> size;  // given or not: an empty --size is refused, not ignored
  std::optional<std::int64_t> spp;
  bool adaptive = false, all_effects = false, quiet = false;
  unsigned threads = 0;
  std::uint64_t max_rays = tracer::kDefaultMaxRays;  // render: the work budget
  std::string mode = "image";  // export-pov
  std::int64_t light = 0;
  std::string numeric = "double", shading = "phong", depth_out;  // raster
  int stacks = 12;
  bool identity = false;
  std::uint64_t max_work = pipespec::kDefaultMaxWork;
  std::string shadows = "none";  // raster
  std::int64_t map_size = 512, map_pcf = 1;
  int map_bits = 24;
  std::string map_bias = "1/65536", map_slope = "2";
  std::optional<std::string> volume;  // raster --shadows volume: zfail (default) or zpass
  std::optional<std::int64_t> receiver;  // raster --shadows projective: the receiving object
};

void add_scene_commands(CLI::App& app, SceneCommands& c);
// Runs the subcommand given; returns its exit code. Throws InputError on bad input (nothing printed).
int run_scene_commands(const SceneCommands& c);

}  // namespace sw::cli
