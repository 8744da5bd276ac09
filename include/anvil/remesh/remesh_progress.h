// A line on the terminal while CGAL remeshes a body: CGAL gives no progress
// of its own, and a whole remesh of a large body takes minutes.
#pragma once
#include "anvil/core/log.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>

namespace anvil::remesh {

/// A line on the terminal every this often while CGAL works (s).
constexpr double kProgressEvery = 5.0;

/// Says every kProgressEvery seconds, while it lives, that body `name` is
/// still being remeshed: CGAL gives no progress of its own.
class RemeshProgress {
public:
  RemeshProgress(std::string name, double expected_nodes)
      : thread_([this, name = std::move(name), expected_nodes](std::stop_token stop) {
          const auto start = std::chrono::steady_clock::now();
          std::unique_lock lock(mutex_);
          while (!wake_.wait_for(lock, stop, std::chrono::duration<double>(kProgressEvery), [] { return false; })) {
            if (stop.stop_requested()) return;
            log::info("    remeshing '%s': %.0f s so far (about %.3g nodes expected)", name.c_str(),
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), expected_nodes);
          }
        }) {}

private:
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::jthread thread_; ///< last: stopped and joined before the mutex goes
};

} // namespace anvil::remesh
