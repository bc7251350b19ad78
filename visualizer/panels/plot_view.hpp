// The plot view: one column of the table view (table_view.hpp) over its rows, and, for a trace
// that is not exact, the same column of an exact run of the same input, or their difference: a
// float difference table drifting away from the cubic shows as a growing curve. The current row
// is marked; a click goes to the row under the mouse.
#pragma once
#include <memory>
#include <string>
#include <vector>
#include "panels/table_view.hpp"

namespace sw::vis {

inline constexpr ImU32 kPlotValue = IM_COL32(110, 190, 255, 255);   // the trace's column
inline constexpr ImU32 kPlotExact = IM_COL32(150, 230, 150, 200);   // the exact run's
inline constexpr ImU32 kPlotCurrent = IM_COL32(255, 225, 70, 255);  // the current row

class PlotCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override {}
  void follow(const Canvas&) override {}

  // Exact runs of traces longer than this are not recorded for the plot (the exact recorder holds
  // every rational): only the values are plotted then.
  static constexpr std::size_t kMaxExactSteps = 400000;

  // Test hooks: the column plotted, whether against exact, and the plotted series (per row).
  int column() const { return column_; }
  bool difference() const { return difference_ && !exact_.empty(); }
  const std::vector<double>& values() const { return values_; }
  const std::vector<double>& exact() const { return exact_; }
  // The screen x of row r in the last frame.
  float row_x(std::size_t r) const;

 private:
  void load(const std::shared_ptr<const TraceModel>& m);
  void pick(int column);
  CanvasEvents draw_inside(const CanvasInput& in, ImVec2 size);

  std::shared_ptr<const TraceModel> model_, exact_model_;
  StepTable table_, exact_table_;
  std::vector<std::vector<double>> all_, all_exact_;
  int column_ = 0;
  bool difference_ = true;  // plot value - exact (when there is an exact run)
  std::vector<double> values_, exact_;
  float x0_ = 0, x1_ = 1;  // the plot area's left and right in the last frame
};

}  // namespace sw::vis
