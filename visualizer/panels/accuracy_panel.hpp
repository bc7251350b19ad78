// The Accuracy window: a short bench of the open algorithm (Algorithm::bench, every mode, one
// repeat, one bench set: the first unless chosen) on a background thread, with a progress bar,
// then the chart of `stepwise bench --plot`. Where there are no threads (the browser build,
// platform.hpp), the window times one mode a frame instead.
// The thread only calls the catalog and fills rows under a mutex; ImGui is touched by draw() alone.
#pragma once
#include <atomic>
#include <imgui.h>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>
#include "catalog.hpp"
#include "platform.hpp"
#include "panels/chart.hpp"

namespace sw::vis {

// One algorithm's bench on one set ("": its first), running from construction on its own thread
// (or, without threads, a mode per advance()).
class AccuracyRun {
 public:
  AccuracyRun(const Algorithm& alg, std::string set, int repeats = 1);
  ~AccuracyRun();  // asks the thread to stop after the mode it is timing, then joins it
  AccuracyRun(const AccuracyRun&) = delete;
  AccuracyRun& operator=(const AccuracyRun&) = delete;

  const Algorithm& algorithm() const { return *alg_; }
  void cancel() {  // no mode starts after this
    stop_ = true;
    if (!kHaveThreads) finished_ = true;  // nothing runs it any more
  }
  std::size_t modes_done() const { return done_.load(); }
  std::size_t modes() const { return alg_->numerics.size(); }
  bool finished() const { return finished_.load(); }
  std::vector<BenchRow> rows() const;  // what is measured so far
  std::string error() const;           // what the bench threw, if anything
  std::vector<std::string> sets() const;  // the algorithm's bench sets, once the thread has them
  std::string set() const;                // the set timed, once known
  // Times the next mode (the first call also reads the sets); false once every mode is done.
  // The thread calls it until then; without threads, AccuracyWindow::draw once a frame.
  bool advance();

 private:
  const Algorithm* alg_;
  int repeats_;
  std::atomic<bool> stop_{false}, finished_{false};
  std::atomic<std::size_t> done_{0};
  mutable std::mutex mu_;
  std::vector<BenchRow> rows_;
  std::string error_, set_;
  std::vector<std::string> sets_;
  bool started_ = false;  // the sets are read (advance's own state: one caller at a time)
  std::thread thread_;    // started once the members above exist
};

class AccuracyWindow {
 public:
  // Draws the window for `alg` (nothing when null) while *open; the close button clears *open. A
  // new algorithm starts a new run; a superseded run finishes on its own and is joined then.
  void draw(const Algorithm* alg, bool* open);
  // Test hooks.
  const AccuracyRun* run() const { return run_.get(); }
  const Chart& chart() const { return chart_; }
  // The chart's top-left corner on screen in the last frame.
  ImVec2 chart_origin() const { return origin_; }

 private:
  void reap();  // joins superseded runs that have finished
  std::unique_ptr<AccuracyRun> run_;
  std::vector<std::unique_ptr<AccuracyRun>> retiring_;
  Chart chart_;
  ImVec2 origin_{0, 0};
};

}  // namespace sw::vis
