// The accuracy chart of `stepwise bench --plot` and the app's Accuracy window: one layout (a list
// of lines, rectangles, markers and text in pixels, y down) and two painters, SVG text (chart.cpp)
// and ImDrawList (chart_draw.cpp), so a slide's PNG and the app show the same picture.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"

namespace sw::vis {

struct ChartItem {
  enum class Kind : std::uint8_t { line, rect, fill_rect, marker, text };
  enum class Shape : std::uint8_t { circle, square, diamond, triangle };
  Kind kind = Kind::line;
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // line ends; rect corners; a marker's centre (x0, y0)
  std::uint32_t rgba = 0xffffffffu;      // 0xAABBGGRR, as ImGui's IM_COL32
  float size = 1;                        // stroke width; a marker's radius; a text's font size
  Shape shape = Shape::circle;
  int anchor = -1;                       // text: -1 left, 0 centre, 1 right of x0; y0 is its top
  std::string text;
  std::string role;                      // what the item shows ("marker float", "axis x", ...)
};

struct Chart {
  float width = 0, height = 0;
  std::uint32_t background = 0;
  std::vector<ChartItem> items;
};

// Width of `text` at font size `size` as the layout assumes it (both painters' fonts come close).
float chart_text_width(std::string_view text, float size);

// Every set of `rows` in its own panel: x = time per output unit in ns (log), y = the percentage of
// cases whose output differs from the rows' judge (exact, or the 300-bit reference), one marker per
// mode (colour and shape) labelled with its max error and unit, a shared legend. `note` goes under
// the title (default: bench_chart_note(rows, 0)). Empty rows: a chart saying so.
Chart bench_chart(std::string_view alg_id, const std::vector<BenchRow>& rows, float width, float height, std::string_view note = {});
// The line under the chart's title: the repeats (none if repeats <= 0; repeats_text), what y
// counts against which judge, and the max error's unit.
std::string bench_chart_note(const std::vector<BenchRow>& rows, int repeats, bool quick = false);

// The chart as a standalone SVG document.
std::string chart_svg(const Chart& chart);

// A mode's colour in charts (0xAABBGGRR) and its marker shape.
std::uint32_t mode_colour(Numeric n);
// The smallest of 1, 2, 2.5, 5 times a power of ten that is >= v (v > 0): an axis's round end.
double nice_ceil(double v);
ChartItem::Shape mode_shape(Numeric n);

}  // namespace sw::vis
