// Wall-time accounting per named phase (assembly, solve, output, and one
// entry per effect) for the log and summary.json.
#pragma once
#include <chrono>
#include <map>
#include <string>

namespace anvil {

class Timers {
public:
  /// Adds the wall time of its lifetime to `timers[phase]`.
  class Scope {
  public:
    Scope(Timers& timers, std::string phase)
        : timers_(timers), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}
    ~Scope() { timers_.add(phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    Timers& timers_;
    std::string phase_;
    std::chrono::steady_clock::time_point start_;
  };

  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  double seconds(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  /// Phase name -> accumulated wall time in s.
  const std::map<std::string, double>& all() const { return seconds_; }

private:
  std::map<std::string, double> seconds_;
};

} // namespace anvil
