// Newton's velocity test: the error of the last iterate, estimated from the
// contraction of its last two steps (solver/IncrementSolver.h).
#include "anvil/solver/IncrementSolver.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using anvil::solver::NewtonIteration;
using anvil::solver::velocity_error_estimate;

namespace {
NewtonIteration step_of(double increment, double step = 1.0) {
  return {1e-7, 1e-9, increment, step};
}
} // namespace

TEST_CASE("Newton's velocity error estimate follows the contraction of its last two full steps", "[unit]") {
  SECTION("a contraction and Newton's iteration: the estimate bounds the true error of the last iterate") {
    // x = 0.4 cos x contracts linearly (rate 0.4 sin x* = 0.15), Newton's
    // x = (x + 2/x)/2 for √2 quadratically: after each step from the second
    // the true error is within the estimate, which is never above the last
    // step (until round-off).
    struct Iteration {
      double start, solution;
      double (*next)(double);
    };
    const Iteration iterations[] = {{1.0, 0.3725594958321101, [](double x) { return 0.4 * std::cos(x); }},
                                    {3.0, std::sqrt(2.0), [](double x) { return 0.5 * (x + 2.0 / x); }}};
    for (const Iteration& iteration : iterations) {
      std::vector<NewtonIteration> steps;
      double x = iteration.start;
      for (int k = 0; k < 6; ++k) {
        const double next = iteration.next(x);
        steps.push_back(step_of(std::abs(next - x)));
        x = next;
        if (steps.size() < 2 || steps.back().increment < 1e-10) continue; // round-off below
        const double estimate = velocity_error_estimate(steps);
        REQUIRE(estimate <= steps.back().increment);
        REQUIRE(std::abs(x - iteration.solution) <= estimate);
      }
    }
  }
  SECTION("Newton's quadratic end: the step that would only confirm convergence is not needed") {
    // |Δv| 1e-2 then 3e-4: θ = 0.03, the iterate after it within 9.3e-6.
    const std::vector<NewtonIteration> steps{step_of(1e-2), step_of(3e-4)};
    CHECK(velocity_error_estimate(steps) == Approx(3e-4 * 0.03 / 0.97));
  }
  SECTION("a slow contraction keeps the last step as the measure") {
    const std::vector<NewtonIteration> steps{step_of(1e-3), step_of(8e-4)};
    CHECK(velocity_error_estimate(steps) == 8e-4);
  }
  SECTION("a growing step, a cut step or a single step keeps the last step as the measure") {
    CHECK(velocity_error_estimate(std::vector<NewtonIteration>{step_of(1e-4), step_of(2e-4)}) == 2e-4);
    CHECK(velocity_error_estimate(std::vector<NewtonIteration>{step_of(1e-2), step_of(1e-4, 0.5)}) == 1e-4);
    CHECK(velocity_error_estimate(std::vector<NewtonIteration>{step_of(1e-2, 0.25), step_of(1e-4)}) == 1e-4);
    CHECK(velocity_error_estimate(std::vector<NewtonIteration>{step_of(5e-3)}) == 5e-3);
    CHECK(velocity_error_estimate(std::vector<NewtonIteration>{}) == 0.0);
  }
}
