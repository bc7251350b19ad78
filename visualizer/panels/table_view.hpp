// The table view: steps x recorded variables. A row starts at each step on one of the listing
// lines the algorithm declares (Algorithm::table_lines; every step when it declares none) and runs
// until the next such step, so a row is one loop iteration. Its columns are the variables those
// rows record, in order of first appearance; a cell holds the column's first value in the row, or
// (dimmed) its latest earlier value. The current step's row is highlighted and scrolled into view;
// clicking a row goes to its first step.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include "panels/canvas.hpp"

namespace sw::vis {

struct StepTable {
  std::vector<std::string_view> columns;
  std::vector<std::uint32_t> rows;  // the first step of each row, ascending
  // The row holding `step`: the last row starting at or before it, if any.
  std::optional<std::size_t> row_of(std::size_t step) const;
};

struct TableCell {
  std::string text;       // lossless ("p/q" for exact values); empty when never set
  double value = 0;
  bool recorded = false;  // set within the row (else carried from earlier)
};

StepTable build_step_table(const TraceModel& m);
// The cells of row r, one per column.
std::vector<TableCell> table_row(const TraceModel& m, const StepTable& t, std::size_t r);
// Every cell's value, column by column (out[c][r]), in one pass over the trace; NaN where a
// column was never set.
std::vector<std::vector<double>> table_values(const TraceModel& m, const StepTable& t);

class TableCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { scroll_pending_ = true; }
  void focus(const TraceModel&, std::size_t, double) override { scroll_pending_ = true; }
  void follow(const Canvas&) override {}

  // Test hooks: the table of the last drawn model, the row highlighted, and a drawn row's screen
  // rectangle (x0, y0, x1, y1), if it was drawn.
  const StepTable& table() const { return table_; }
  std::optional<std::size_t> highlighted_row() const { return highlighted_; }
  std::optional<std::array<float, 4>> row_rect(std::size_t row) const;

 private:
  std::shared_ptr<const TraceModel> model_;
  StepTable table_;
  std::optional<std::size_t> highlighted_, scrolled_to_;
  bool scroll_pending_ = true;
  std::vector<std::pair<std::size_t, std::array<float, 4>>> drawn_;
};

}  // namespace sw::vis
