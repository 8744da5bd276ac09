// The contact patch test of Fourment 2008 §5.2 (El-Abbasi & Bathe 2001): its
// four cases, the mesh pairs and the error measures, shared by the regression
// test (tests/regression/test_patch.cpp) and the full table (tools/patch_test).
#pragma once
#include "anvil/io/RunResults.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Simulation.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace patch_test {

struct LoadCase {
  const char* name;
  const char* file;    ///< relative to the source tree
  double exact_stress; ///< MPa, the uniform |σzz| of the exact solution
};

/// Exact stresses: pressure cases 100 MPa; imposed displacement E u/H =
/// 210000 × 0.01/10; imposed velocity 3ηV/H = 3 × 1 × 1/10 (uniaxial).
inline const std::vector<LoadCase>& load_cases() {
  static const std::vector<LoadCase> cases = {
      {"1 elastic, pressure", "cases/patch_test.yaml", 100.0},
      {"2 elastic, displacement", "cases/patch_test_displacement.yaml", 210.0},
      {"3 Newtonian, pressure", "cases/patch_test_newtonian.yaml", 100.0},
      {"4 Newtonian, velocity", "cases/patch_test_newtonian_velocity.yaml", 0.3},
  };
  return cases;
}

/// Cells along x and y of the lower (master) and upper (slave) 10 mm blocks.
/// The counts are not multiples of each other (except matching): nested
/// grids would put every coarse node on a fine one, which independently
/// meshed bodies never do.
struct MeshPair {
  const char* name;
  int master_cells, slave_cells;
};

inline const std::vector<MeshPair>& mesh_pairs() {
  static const std::vector<MeshPair> pairs = {
      {"matching 4/4", 4, 4},     {"similar 4/5", 4, 5},
      {"slave finer 4/7", 4, 7},  {"slave finer 1:3.75 4/15", 4, 15},
      {"master finer 7/4", 7, 4}, {"master finer 3.75:1 15/4", 15, 4},
  };
  return pairs;
}

struct Errors {
  double interface_max = 0.0, interface_rms = 0.0; ///< over the interface nodes of both bodies
  double interior_max = 0.0;                       ///< over the elements of both bodies
  int interface_nodes = 0;
  double wall_time = 0.0; ///< s
  int newton_iterations = 0;
};

/// Runs one configuration into `out` (emptied first) and measures the
/// relative errors against the uniform exact stress.
inline Errors run(const LoadCase& load, const MeshPair& meshes, const std::string& formulation,
                  const std::string& source_dir, const std::string& out) {
  auto size = [](int cells) { return std::to_string(10.0 / cells); };
  anvil::scene::Case c = anvil::scene::read_case(source_dir + "/" + load.file,
                                                 {"bodies[0].mesh.element_size=" + size(meshes.master_cells),
                                                  "bodies[1].mesh.element_size=" + size(meshes.slave_cells),
                                                  "contact_pairs[0].formulation=" + formulation,
                                                  // the table measures the formulation's error: Newton far below it
                                                  // (the run's default 1e-6 moves the errors' fourth digit)
                                                  "solver.tolerance=1e-10", "solver.increment_tolerance=1e-10"});
  std::filesystem::remove_all(out);
  anvil::scene::run(c, {out});
  Errors e;
  double sum_sq = 0.0;
  for (const anvil::io::InterfaceRow& row : anvil::io::read_interface(out)) {
    const double error = std::abs(row.normal_stress - load.exact_stress) / load.exact_stress;
    e.interface_max = std::max(e.interface_max, error);
    sum_sq += error * error;
    ++e.interface_nodes;
  }
  e.interface_rms = std::sqrt(sum_sq / std::max(e.interface_nodes, 1));
  const std::vector<double> stress = anvil::io::read_last_cell_field(out, "stress", 6);
  for (std::size_t k = 2; k < stress.size(); k += 6)
    e.interior_max = std::max(e.interior_max, std::abs(-stress[k] - load.exact_stress) / load.exact_stress);
  e.wall_time = anvil::io::read_summary_number(out, "total");
  e.newton_iterations = static_cast<int>(anvil::io::read_summary_number(out, "newton_iterations"));
  return e;
}

} // namespace patch_test
