// Two cubes squeezed with non-matching meshes (Fourment 2008 §5.3):
// with the quasi-symmetric formulation the top load and the interface
// velocity change by less than 2 % when master and slave are swapped, on
// matching meshes and with one cube 2.25 times finer (lower 4, upper 9
// cells). Master/slave, run beside it, changes more: that is what the
// formulation is for.
#include "test_common.h"
#include "two_cubes_runs.h"

#include "anvil/core/log.h"

namespace {

two_cubes::Outcome run(double lower_size, double upper_size, bool lower_is_master, const char* formulation) {
  anvil::log::set_quiet(true);
  const auto out = std::filesystem::temp_directory_path() / "anvil_two_cubes";
  return two_cubes::run({lower_size, upper_size, lower_is_master, formulation}, ANVIL_SOURCE_DIR, out.string());
}

/// Largest relative change, over load and the two interface velocities, when the roles swap.
double swap_change(const two_cubes::Outcome& a, const two_cubes::Outcome& b) {
  return std::max({two_cubes::change(a.load, b.load),
                   two_cubes::change(a.interface_velocity[0], b.interface_velocity[0]),
                   two_cubes::change(a.interface_velocity[1], b.interface_velocity[1])});
}

} // namespace

TEST_CASE("two cubes: the quasi-symmetric load and interface velocity do not depend on which cube is master",
          "[regression]") {
  for (const auto& [lower, upper] : {std::pair{2.5, 2.5}, std::pair{2.5, 10.0 / 9.0}}) {
    const two_cubes::Outcome qs = run(lower, upper, true, "quasi_symmetric");
    const two_cubes::Outcome qs_swapped = run(lower, upper, false, "quasi_symmetric");
    const two_cubes::Outcome ms = run(lower, upper, true, "master_slave");
    const two_cubes::Outcome ms_swapped = run(lower, upper, false, "master_slave");
    INFO("lower " << lower << " mm, upper " << upper << " mm: QS load " << qs.load << " -> " << qs_swapped.load
                  << " N, interface vz " << qs.interface_velocity[0] << "/" << qs.interface_velocity[1] << " -> "
                  << qs_swapped.interface_velocity[0] << "/" << qs_swapped.interface_velocity[1] << " mm/s; M/S load "
                  << ms.load << " -> " << ms_swapped.load << " N");
    // 2 %: the bound. The Newton tolerance (1e-8) and the penalty
    // compliance (1e-5 of the plate speed) are far below it; what is left is
    // the formulation's own dependence on the roles (measured 0.55 %).
    CHECK(swap_change(qs, qs_swapped) < 0.02);
    if (lower == upper) {
      // Matching meshes: each node sits on a node, eq. 24 is eq. 19 either way.
      CHECK(swap_change(qs, qs_swapped) < 1e-6);
      CHECK(two_cubes::change(ms.load, qs.load) < 1e-6);
    } else {
      CHECK(swap_change(ms, ms_swapped) > 0.02); // measured 6.3 % on the load
      CHECK(swap_change(qs, qs_swapped) < swap_change(ms, ms_swapped));
    }
  }
}
