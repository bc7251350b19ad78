// The `stepwise` command: list, trace, run, check, bench. Other tools drive these forms, so keep
// them stable (docs/cli.md). Bad input: one line on stderr, exit 2, no partial output file.
#include <CLI/CLI.hpp>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <fstream>
#include <iostream>
#include <sstream>
#include "bench_text.hpp"
#include "catalog.hpp"
#include "contract.hpp"
#include "data_root.hpp"
#include "scene_command.hpp"  // `stepwise scene check`
#include "output.hpp"
#include "trace_io.hpp"
#ifdef SW_HAVE_RENDER
#include "headless/bench_plot.hpp"      // visualizer/: `stepwise bench --plot`
#include "headless/lesson_command.hpp"  // visualizer/: `stepwise lesson export|lint`
#include "headless/quiz_command.hpp"    // visualizer/: `stepwise quiz`
#include "panels/chart.hpp"             // visualizer/: the chart's note
#include "headless/render_command.hpp"  // visualizer/: `stepwise render`
#endif

using namespace sw;

namespace {

// Writes through `body` to a file atomically, or streams to stdout for "" or "-", at most
// max_output bytes. Bodies validate their input and its budget before writing anything.
template <class F> void write_output(const std::string& path, std::uint64_t max_output, F&& body) {
  if (path.empty() || path == "-") {
    BudgetedStream out(std::cout, max_output);
    body(static_cast<std::ostream&>(out));
    std::cout.flush();
    return;
  }
  OutputFile file(path);
  BudgetedStream out(file.stream(), max_output);
  body(static_cast<std::ostream&>(out));
  file.commit();
}

void add_budget_options(CLI::App* cmd, Budget& b) {
  cmd->add_option("--max-steps", b.max_steps, "Refuse inputs that imply more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));
  cmd->add_option("--max-output", b.max_output, "Stop and write nothing past this many bytes (default 1073741824)")->check(CLI::Validator(budget_count_error, "COUNT"));
}

void print_bench(const Algorithm& alg, const std::vector<BenchRow>& rows, int repeats, bool quick, bool json) {
  if (json) {  // units: docs/cli.md
    for (const BenchRow& r : rows)
      std::cout << Json{{"algorithm", alg.id}, {"set", r.set}, {"numeric", numeric_name(r.numeric)}, {"ns_per_op", r.ns_per_op},
                        {"mismatches", r.mismatches}, {"cases", r.cases}, {"full_cases", r.full_cases}, {"ops", r.ops}, {"fallbacks", r.fallbacks},
                        {"later_stage", r.later_stage}, {"max_error", r.max_error}, {"max_error_unit", r.error_unit}, {"compared_with", judge_name(r.judge)}}
                       .dump()
                << '\n';
    return;
  }
  const BenchSummary sum = bench_summary(rows, quick);
  std::printf("%s: %s, %s; outputs compared with %s; %s\n", std::string(alg.id).c_str(), std::string(kBenchTimeLabel).c_str(),
              repeats_text(repeats, quick).c_str(), std::string(judge_text(sum.judge)).c_str(), sum.cases.c_str());
  const std::string differs = mismatch_label(sum.judge), error = error_label(sum.error_unit);
  const int wd = int(differs.size()), we = int(error.size());
  int ws = 8;  // the set column: as wide as its longest name
  for (const BenchRow& r : rows) ws = std::max(ws, int(r.set.size()));
  std::printf("%-*s %-9s %8s %10s %12s %8s %*s %15s %16s%s%*s\n", ws, "set", "numeric", "cases", "ops", "ns/op (ns)", "x double", wd, differs.c_str(),
              "stage 2 (cases)", "fallback (cases)", we ? " " : "", we, error.c_str());
  for (const BenchRow& r : rows) {
    double base = 0;
    for (const BenchRow& b : rows)
      if (b.set == r.set && b.numeric == Numeric::f64) base = b.ns_per_op;
    std::printf("%-*s %-9s %8zu %10zu %12.2f %8.2f %*zu %15zu %16zu", ws, r.set.c_str(), std::string(numeric_name(r.numeric)).c_str(), r.cases, r.ops,
                r.ns_per_op, base > 0 ? r.ns_per_op / base : 0.0, wd, r.mismatches, r.later_stage, r.fallbacks);
    if (we) std::printf(" %*.3g", we, r.max_error);
    std::printf("\n");
  }
}

// The live progress line of `bench` on a terminal (standard error), redrawn at most every 100 ms
// and cleared when the bench ends, however it ends. Off the terminal it writes nothing.
class ProgressLine {
 public:
  explicit ProgressLine(std::string_view alg) : alg_(alg), on_(::isatty(STDERR_FILENO) == 1) {}
  ~ProgressLine() {
    if (drawn_) std::fputs("\r\x1b[K", stderr), std::fflush(stderr);
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // The callback for BenchOptions::progress; empty off a terminal.
  std::function<void(const BenchProgress&)> callback() {
    if (!on_) return {};
    return [this](const BenchProgress& p) { show(p); };
  }

 private:
  void show(const BenchProgress& p) {
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now, drawn_ = true;
    std::fprintf(stderr, "\r%s\x1b[K", bench_progress_text(alg_, p).c_str());
    std::fflush(stderr);
  }
  std::string_view alg_;
  bool on_, drawn_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace

static int run_command(int argc, char** argv) {
  CLI::App app{"stepwise: step through classic graphics algorithms, exactly"};
  app.set_version_flag("--version", "stepwise " SW_VERSION "\ndata: " + data_root().string());
  app.require_subcommand(1);

  auto* list = app.add_subcommand("list", "One line per algorithm: its id and what it does");
  bool list_markdown = false, list_json = false;
  std::string list_listing, list_contract;
  auto* markdown_opt = list->add_flag("--markdown", list_markdown, "The README's algorithm table (family, id, what, modes)");
  list->add_flag("--json", list_json, "One JSON object per algorithm: id, family, what, modes, example input (with --contract: the contract as JSON)");
  auto* listing_opt = list->add_option("--listing", list_listing, "Print one algorithm's listing, or a callee's (refract, scene-hit): line id, name and text");
  auto* contract_opt = list->add_option("--contract", list_contract, "Print what a trace of ALG must record for `check`: per listing line its kinds, variables and geometry, the header, the result and the tolerances");
  contract_opt->excludes(markdown_opt)->excludes(listing_opt);

  auto* schema = app.add_subcommand("schema", "Print the JSON schema of a trace line (docs/trace.schema.json)");

  std::string alg_id, input_arg, numeric = "double", out_path, inputs_path, trace_path;
  bool decisions_only = false, results_only = false, json = false, bench_full = false;
  int repeats = 3;
  Budget budget;
  std::vector<std::string> bench_numerics;
  std::string bench_set, bench_plot, bench_plot_size = "1280x720";

  auto* trace = app.add_subcommand("trace", "Write a JSONL step trace of one run");
  trace->add_option("algorithm", alg_id, "Algorithm id (see `stepwise list`)")->required();
  trace->add_option("--input", input_arg, "Input as JSON text or a file holding it")->required();
  trace->add_option("--numeric", numeric, "float | double | int | filtered | exact | reference");
  trace->add_option("--out", out_path, "Output file (default: standard output)");
  add_budget_options(trace, budget);

  auto* run = app.add_subcommand("run", "Run a batch of inputs untraced: one result line per input line");
  run->add_option("algorithm", alg_id, "Algorithm id")->required();
  run->add_option("--inputs", inputs_path, "JSONL file, one input per line")->required();
  run->add_option("--numeric", numeric, "float | double | int | filtered | exact | reference");
  run->add_option("--out", out_path, "Output file (default: standard output)");
  add_budget_options(run, budget);

  auto* check = app.add_subcommand("check", "Replay a trace against the exact oracle; exit 0 agree, 1 diverge, 2 malformed");
  check->add_option("trace", trace_path, "Trace file (JSONL), or - for standard input")->required();
  auto* decisions = check->add_flag("--decisions-only", decisions_only, "Compare lines, kinds, integers and pixels, not rounded numbers; a step may leave out its geometry");
  check->add_flag("--results-only", results_only, "Compare the result alone; the steps are read past")->excludes(decisions);
  check->add_option("--max-steps", budget.max_steps, "Refuse traces whose replay implies more steps (default 4000000)")->check(CLI::Validator(budget_count_error, "COUNT"));

  auto* bench = app.add_subcommand("bench", "Accuracy against time in every numeric mode, on seeded sets");
  bench->add_option("algorithm", alg_id, "Algorithm id")->required();
  bench->add_flag("--json", json, "One JSON object per line per mode and set");
  bench->add_option("--numeric", bench_numerics, "Only these modes (repeatable)");
  auto* set_opt = bench->add_option("--set", bench_set, "Only this input set (e.g. random, long)");
  bench->add_option("--repeats", repeats, "Timed repeats; the best is reported")->check(CLI::Range(1, 100));
  bench->add_flag("--full", bench_full, "Every case of each set (default: at most " + std::to_string(BenchOptions::kQuickCases) + " a set, evenly spaced)");
  auto* plot_opt = bench->add_option("--plot", bench_plot, "Also draw the results as a chart: FILE.png or FILE.svg");
  bench->add_option("--plot-size", bench_plot_size, "The chart's size WxH (default 1280x720)");

  sw::cli::SceneCommands scene_cmds;
  sw::cli::add_scene_commands(app, scene_cmds);

#ifdef SW_HAVE_RENDER
  sw::vis::RenderOptions render_opts;
  auto* render = sw::vis::add_render_command(app, render_opts);
  sw::vis::QuizOptions quiz_opts;
  auto* quiz = sw::vis::add_quiz_command(app, quiz_opts);
  sw::vis::LessonCommands lesson_cmds;
  sw::vis::add_lesson_commands(app, lesson_cmds);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "stepwise: error: " << one_line(e.what()) << '\n';
    return 2;
  }

  try {
#ifdef SW_HAVE_RENDER
    if (*render) return sw::vis::run_render(render_opts);
    if (*quiz) return sw::vis::run_quiz(quiz_opts);
    if (*lesson_cmds.group) return sw::vis::run_lesson_commands(lesson_cmds);
#endif
    if (*scene_cmds.group) return sw::cli::run_scene_commands(scene_cmds);
    if (*schema) {
      std::cout << trace_schema();
      return 0;
    }
    if (*list) {
      if (contract_opt->count()) {
        if (!algorithm_by_id(list_contract) && find_listing(list_contract))
          throw InputError("'" + list_contract + "' is a callee with no input of its own: its steps are in its callers' contracts (list --listing " + list_contract + " prints its listing)");
        const Contract contract = make_contract(find_algorithm(list_contract));
        std::cout << (list_json ? contract_json(contract) + "\n" : contract_text(contract));
        return 0;
      }
      if (list_markdown) {
        std::cout << catalog_markdown();
        return 0;
      }
      if (list_json) {
        std::cout << catalog_jsonl();
        return 0;
      }
      if (listing_opt->count()) {
        const Listing* l = find_listing(list_listing);
        if (!l) {
          std::string known;
          for (std::string_view id : listing_ids()) known += (known.empty() ? "" : ", ") + std::string(id);
          throw InputError("no listing named '" + one_line(list_listing, 60) + "' (algorithms and their callees: " + known + ")");
        }
        std::printf("%s\n", std::string(l->title).c_str());
        for (std::size_t i = 0; i < l->lines.size(); ++i)
          std::printf("%2zu %-14s %s\n", i + 1, std::string(l->lines[i].name).c_str(), std::string(l->lines[i].text).c_str());
        return 0;
      }
      for (const Algorithm& a : catalog()) std::printf("%-26s %s\n", std::string(a.id).c_str(), std::string(a.summary).c_str());
      return 0;
    }
    if (*trace) {
      const Algorithm& alg = find_algorithm(alg_id);
      const Run run = alg.open(read_input_arg(input_arg), parse_numeric_for(alg, numeric));
      run.check_budget(budget);
      write_output(out_path, budget.max_output, [&](std::ostream& os) { write_trace(run, os); });
      if (!out_path.empty() && out_path != "-") std::cerr << "stepwise: wrote trace to " << out_path << '\n';
      return 0;
    }
    if (*run) {
      const Algorithm& alg = find_algorithm(alg_id);
      const Numeric n = parse_numeric_for(alg, numeric);
      std::ifstream in = open_input_file(inputs_path, "inputs file");
      write_output(out_path, budget.max_output, [&](std::ostream& os) { run_batch(alg, n, in, os, budget); });
      return 0;
    }
    if (*check) {
      CheckReport rep;
      const CheckScope scope = results_only ? CheckScope::result : decisions_only ? CheckScope::decisions : CheckScope::everything;
      if (trace_path == "-") {
        rep = check_trace(std::cin, scope, budget);
      } else {
        std::ifstream in = open_input_file(trace_path, "trace file");
        rep = check_trace(in, scope, budget);
      }
      (rep.status == 0 ? std::cout : std::cerr) << (rep.status == 2 ? "stepwise: error: " : "") << one_line(rep.message, 2000) << '\n';
      if (!rep.context.empty()) std::cerr << "  " << one_line(rep.context, 1000) << '\n';
      return rep.status;
    }
    if (*bench) {
      const Algorithm& alg = find_algorithm(alg_id);
      // Given empty, they would mean "not given" (every set, no plot): refused instead.
      if (set_opt->count() && bench_set.empty()) throw InputError("--set: give a set's name (e.g. random, long)");
      if (plot_opt->count() && bench_plot.empty()) throw InputError("--plot: give a file name (.png or .svg)");
#ifdef SW_HAVE_RENDER
      std::pair<int, int> plot_size;
      if (!bench_plot.empty()) plot_size = sw::vis::check_plot_target(bench_plot, bench_plot_size);
#else
      if (!bench_plot.empty()) throw InputError("--plot needs the visualizer (this build has no OSMesa)");
#endif
      std::vector<Numeric> modes = alg.numerics;
      if (!bench_numerics.empty()) {
        modes.clear();
        for (const auto& m : bench_numerics) modes.push_back(parse_numeric_for(alg, m));
      }
      std::vector<BenchRow> rows;
      {
        ProgressLine progress(alg.id);
        rows = alg.bench(modes, {.repeats = repeats, .only_set = bench_set, .max_cases = bench_full ? 0 : BenchOptions::kQuickCases, .progress = progress.callback()});
      }
      if (rows.empty()) throw InputError("no bench set named '" + bench_set + "'");
      std::stable_sort(rows.begin(), rows.end(), [](const BenchRow& a, const BenchRow& b) { return a.set < b.set; });
      print_bench(alg, rows, repeats, !bench_full, json);
#ifdef SW_HAVE_RENDER
      if (!bench_plot.empty()) {
        sw::vis::write_bench_plot(bench_plot, alg.id, rows, plot_size, sw::vis::bench_chart_note(rows, repeats, !bench_full));
        std::cerr << "stepwise: wrote chart to " << bench_plot << '\n';
      }
#endif
      return 0;
    }
  } catch (const std::exception& e) {  // InputError and anything else: one line, exit 2
    std::cerr << "stepwise: error: " << one_line(e.what()) << '\n';
    return 2;
  }
  return 0;
}

#ifdef SW_RENDERER_EXE
namespace {

// Whether this command draws (or lists every command): those run in the renderer's build.
bool draws(int argc, char** argv) {
  if (argc < 2) return true;
  const std::string_view first = argv[1];
  if (first == "-h" || first == "--help" || first == "render" || first == "quiz" || first == "lesson") return true;
  if (first != "bench") return false;
  for (int i = 2; i < argc; ++i)
    if (std::string_view(argv[i]).starts_with("--plot")) return true;
  return false;
}

// Runs the same command line in the renderer's build beside this executable (found from
// /proc/self/exe, else from argv[0]); returns only on failure.
int run_in_renderer(char** argv) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path renderer = (ec ? std::filesystem::path(argv[0]) : exe).parent_path() / SW_RENDERER_EXE;
  execv(renderer.c_str(), argv);
  std::cerr << "stepwise: error: cannot run " << renderer.string() << ", the build with the renderer that draws and lists every command: "
            << std::strerror(errno) << '\n';
  return 2;
}

}  // namespace
#endif

int main(int argc, char** argv) {
  guard_standard_descriptors();
#ifdef SW_RENDERER_EXE
  if (draws(argc, argv)) return run_in_renderer(argv);
#endif
  const int status = run_command(argc, argv);
  // What a command wrote to standard output must have reached it: a full disk, /dev/full or a
  // closed descriptor is an error, not a silent truncation.
  if (const std::string why = stdout_error(); !why.empty()) {
    std::cerr << "stepwise: error: cannot write to standard output: " << why << '\n';
    return 2;
  }
  return status;
}
