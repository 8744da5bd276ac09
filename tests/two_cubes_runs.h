// Two Newtonian cubes squeezed between sticking plates (Fourment 2008 §5.3,
// cases/two_cubes.yaml), run with chosen meshes, roles and formulation, and
// what a swap of master and slave must leave unchanged: shared by the
// regression and hard tests.
#pragma once
#include "anvil/io/RunResults.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>

namespace two_cubes {

/// Element sizes (mm) of the 10 mm cubes and the pair's roles.
struct Setup {
  double lower_size, upper_size;
  bool lower_is_master;
  std::string formulation;
};

struct Outcome {
  double load = 0.0;                          ///< N, on the top plate
  std::array<double, 2> interface_velocity{}; ///< mm/s, area-weighted mean vz of the lower and upper interface
  double master_closing = 0.0;                ///< mm/s, fastest approach of a master node to the slave (0 if none)
  int master_nodes = 0, unloaded_master = 0;  ///< master interface nodes, and those transmitting no stress
  int newton_iterations = 0;
};

inline Outcome run(const Setup& s, const std::string& source_dir, const std::string& out) {
  const std::string master = s.lower_is_master ? "lower" : "upper", slave = s.lower_is_master ? "upper" : "lower";
  anvil::scene::Case c = anvil::scene::read_case(
      source_dir + "/cases/two_cubes.yaml",
      {"bodies[0].mesh.element_size=" + std::to_string(s.lower_size),
       "bodies[1].mesh.element_size=" + std::to_string(s.upper_size), "contact_pairs[0].master=" + master,
       "contact_pairs[0].slave=" + slave, "contact_pairs[0].formulation=" + s.formulation,
       "solver.tolerance=1e-8"}); // the tolerance the tests' 1e-6 bounds are built on (default 1e-6)
  std::filesystem::remove_all(out);
  anvil::run::run(c, {out});
  Outcome o;
  o.load = anvil::io::read_loads(out, "top").back().force.z();
  std::array<double, 2> weighted{}, area{};
  for (const anvil::io::InterfaceRow& row : anvil::io::read_interface(out)) {
    const int body = row.body == "lower" ? 0 : 1;
    weighted[body] += row.area * row.velocity.z();
    area[body] += row.area;
    if (row.body != master) continue;
    ++o.master_nodes;
    if (row.normal_stress <= 0.0) ++o.unloaded_master;
    o.master_closing = std::max(o.master_closing, -row.gap_rate);
  }
  for (int b = 0; b < 2; ++b)
    o.interface_velocity[b] = weighted[b] / area[b];
  o.newton_iterations = static_cast<int>(anvil::io::read_summary_number(out, "newton_iterations"));
  return o;
}

/// Relative change of a quantity when the roles are swapped.
inline double change(double before, double after) {
  return std::abs(after - before) / std::abs(before);
}

} // namespace two_cubes
