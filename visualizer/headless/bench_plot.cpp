#include "headless/bench_plot.hpp"
#include "panels/chart_draw.hpp"
#include "headless/headless.hpp"
#include "headless/image_io.hpp"
#include "headless/render_command.hpp"  // parse_frame_size
#include "output.hpp"

namespace sw::vis {
namespace {

bool ends_with(const std::string& s, std::string_view tail) {
  if (s.size() < tail.size()) return false;
  for (std::size_t i = 0; i < tail.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - tail.size() + i])) != tail[i]) return false;
  return true;
}

}  // namespace

std::pair<int, int> check_plot_target(const std::string& path, const std::string& size) {
  if (!ends_with(path, ".png") && !ends_with(path, ".svg")) throw InputError("--plot '" + path + "': the file name must end in .png or .svg");
  const auto [w, h] = parse_frame_size(size, "--plot-size");
  { OutputFile trial(path); }  // throws naming the path if it cannot be written; leaves nothing
  return {w, h};
}

void write_bench_plot(const std::string& path, std::string_view alg_id, const std::vector<BenchRow>& rows, std::pair<int, int> size,
                      std::string_view note) {
  const auto [w, h] = size;
  const Chart chart = bench_chart(alg_id, rows, float(w), float(h), note);
  if (ends_with(path, ".svg")) {
    OutputFile file(path);
    file.stream() << chart_svg(chart);
    if (!file.stream()) throw InputError("cannot write " + path);
    file.commit();
    return;
  }
  HeadlessHost host(w, h);
  const auto& pixels = host.render_with([&] { paint_chart(ImGui::GetBackgroundDrawList(), chart, ImVec2(0, 0)); });
  write_png(path, pixels.data(), w, h);
}

}  // namespace sw::vis
