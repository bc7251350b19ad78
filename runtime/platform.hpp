// What the browser page (emscripten, visualizer/web/) lacks, in one place. Threads: it has none (no
// pthreads), so the work that runs on threads on the desktop runs on the calling thread there, in
// parts where a frame must not wait for all of it (the Accuracy window times one number type a frame).
// Trace files and the oracle: the page writes no traces and checks none (`stepwise trace` and `check`
// do), so its algorithms leave the JSONL writer and the oracle out (register.hpp).
#pragma once
#include <algorithm>
#include <thread>

namespace sw {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kHaveThreads = false;
#else
inline constexpr bool kHaveThreads = true;
#endif

#ifdef __EMSCRIPTEN__
inline constexpr bool kBrowser = true;
#else
inline constexpr bool kBrowser = false;
#endif

// The threads parallel work takes when not told: the machine's cores, or 1 where there are no threads.
inline unsigned worker_threads() { return kHaveThreads ? std::max(1u, std::thread::hardware_concurrency()) : 1u; }

}  // namespace sw
