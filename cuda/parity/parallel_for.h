// fn(i) for i in [0, n) on `threads` std::threads taking chunks from an atomic counter: the
// runner's CPU scheduler, which may not use OpenMP (its runtime is a shared library). What
// each fn(i) computes does not depend on the thread that runs it.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tracer {

inline unsigned default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

template <class Fn>
void parallel_for(size_t n, unsigned threads, Fn fn, size_t chunk = 64) {
  std::atomic<size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    try {
      for (size_t begin; (begin = next.fetch_add(chunk)) < n;)
        for (size_t i = begin; i < std::min(n, begin + chunk); ++i) fn(i);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
      next = n;
    }
  };
  std::vector<std::thread> pool;
  try {
    for (unsigned t = 1; t < std::max(1u, threads); ++t) pool.emplace_back(work);
  } catch (...) {  // a thread the machine could not start: stop the others, then report it
    next = n;
    for (std::thread& t : pool) t.join();
    throw;
  }
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace tracer
