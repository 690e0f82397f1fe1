// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file parallel.h
/// The parallel loop that every multi-threaded ShapeCorr function runs on (plain `std::thread`s,
/// no dependency), for programs that want the same threading.
#ifndef SHAPECORR_PARALLEL_H
#define SHAPECORR_PARALLEL_H

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrCore
/// Number of worker threads for a request of `requested` (0 = all hardware threads): the
/// meaning of the `number_of_threads` named parameter.
inline unsigned resolve_thread_count(unsigned requested) {
  if(requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1u : hw;
}

/// \ingroup PkgShapeCorrCore
/// Calls `fn(item, thread_id)` once for every item in [0, count), on up to `threads` threads (0 =
/// all hardware threads), items handed out one at a time (dynamic scheduling, so uneven items
/// balance). `thread_id` is in [0, number of threads used) and lets `fn` keep per-thread scratch
/// state; the calling thread is thread 0, and with one thread the items run in order on it.
/// The first exception thrown by `fn` stops the handing out of items and is rethrown in the caller
/// after all threads have stopped.
/// \code
///   std::vector<Eigen::VectorXd> d(sources.size());
///   shapecorr::parallel_for(sources.size(), 0, [&](std::size_t i, unsigned) { d[i] = engine.distances_from(sources[i]); });
/// \endcode
template <typename Fn>
void parallel_for(std::size_t count, unsigned threads, Fn&& fn) {
  threads = std::min<unsigned>(resolve_thread_count(threads), static_cast<unsigned>(std::max<std::size_t>(count, 1)));
  if(threads == 1) {
    for(std::size_t i = 0; i < count; ++i) fn(i, 0u);
    return;
  }
  std::atomic<std::size_t> next(0);
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&](unsigned tid) {
    try {
      for(std::size_t i = next++; i < count; i = next++) fn(i, tid);
    } catch(...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if(!error) error = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> pool;
  for(unsigned t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for(auto& th : pool) th.join();
  if(error) std::rethrow_exception(error);
}

} // namespace shapecorr

#endif
