// What the two window hosts share (gui_main.cpp, the GLFW desktop window; web/web_main.cpp, the
// browser page): their command line and how it opens the session.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include "budget.hpp"
#include "lessons/session.hpp"

namespace sw::vis {

struct HostOptions {
  std::string lesson, algorithm, input, numeric, compare, answers_dir, student;
  std::optional<std::size_t> step;
  double scale = 1;
  bool present = false, quiz = false;
  Budget budget;
};

// The options that open something, shared by both hosts: --lesson, --algorithm, --input,
// --numeric, --compare, --step, --max-steps, --scale, --present, --quiz, --answers-dir, --student.
void add_host_options(CLI::App& cli, HostOptions& o);

// Opens what the options ask for. --lesson takes a file, or a manifest entry by the number its
// file name starts with ("05" opens 05-triangle-crack.md). Failures show in the app (error()) and
// return false.
bool open_session(Session& session, const HostOptions& o);

}  // namespace sw::vis
