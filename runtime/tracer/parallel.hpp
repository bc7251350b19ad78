// Rows of work on a few threads, each row once, in any order; the caller makes the result independent
// of the order (each row writes its own slots). An exception in a row stops the rest and is rethrown.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>
#include "platform.hpp"

namespace sw::tracer {

// Runs work(row) for every row on `threads` threads, reporting progress from this thread. Where
// there are no threads (platform.hpp), all rows run on this one, and only the end is reported.
template <class Work> void parallel_rows(std::int64_t rows, unsigned threads, const std::function<void(double)>& progress, const Work& work) {
  std::atomic<std::int64_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::mutex error_lock;
  std::exception_ptr error;
  auto run = [&] {
    try {
      for (std::int64_t j; !failed && (j = next++) < rows;) {  // each row once; bounded by rows
        work(j);
        ++done;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> g(error_lock);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  // With progress, this thread only reports.
  const unsigned workers = !kHaveThreads ? 0 : progress ? threads : threads - 1;
  for (unsigned k = 0; k < workers; ++k) pool.emplace_back(run);
  if (progress && workers > 0) {
    while (done < rows && !failed) {
      progress(double(done) / double(rows));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  } else {
    run();
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress(1.0);
}

}  // namespace sw::tracer
