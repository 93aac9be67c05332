// Whether this process can run `count` threads at once, as OpenMP's team and the GPU runner's
// pool do: they are started, each waits until the last is up, and all are joined. A limit on
// address space (ulimit -v: each thread reserves a stack) or on processes then fails here, with
// a message for `--threads`, instead of inside the OpenMP runtime (exit 1, in its own words) or
// a thread pool (an abort). Header-only: the runner uses it too.
#pragma once
#include <condition_variable>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace tracer {

// "" when `count` threads (this one and count - 1 more) could all run at once; else why not.
inline std::string thread_start_failure(unsigned count) {
  std::mutex m;
  std::condition_variable cv;
  bool release = false;
  std::vector<std::thread> started;
  std::string failure;
  try {
    for (unsigned i = 1; i < count; ++i)
      started.emplace_back([&] {
        std::unique_lock<std::mutex> lock(m);
        cv.wait(lock, [&] { return release; });
      });
  } catch (const std::system_error& e) {
    failure = "the machine could not start thread " + std::to_string(started.size() + 2) + " of " +
              std::to_string(count) + " (" + e.what() + "; a limit on memory or processes: ulimit -v, -u, a cgroup)";
  }
  {
    const std::lock_guard<std::mutex> lock(m);
    release = true;
  }
  cv.notify_all();
  for (std::thread& t : started) t.join();
  return failure;
}

}  // namespace tracer
