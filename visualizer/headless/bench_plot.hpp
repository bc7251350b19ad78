// `stepwise bench ALG --plot FILE.png|FILE.svg [--plot-size WxH]`: the accuracy chart (chart.hpp)
// of what the bench measured, as SVG text or as a PNG painted through the OSMesa host.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include "catalog.hpp"

namespace sw::vis {

// Call before the bench runs: throws InputError (one line) unless `path` ends in .png or .svg, can
// be written (a trial temporary is made and removed) and `size` is WxH within 320x240..4096x4096.
// Returns the size.
std::pair<int, int> check_plot_target(const std::string& path, const std::string& size);

// Writes the chart atomically (no partial file on failure); throws InputError.
void write_bench_plot(const std::string& path, std::string_view alg_id, const std::vector<BenchRow>& rows, std::pair<int, int> size,
                      std::string_view note);

}  // namespace sw::vis
