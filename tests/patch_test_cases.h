// The contact patch test of Fourment 2008 §5.2 (El-Abbasi & Bathe 2001): its
// four cases, the mesh pairs and the error measures, shared by the regression
// test (tests/regression/test_patch.cpp) and the full table (tools/patch_test).
#pragma once
#include "anvil/core/processes.h"
#include "anvil/io/RunResults.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"

#include <algorithm>
#include <array>
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
  std::array<double, 2> body_max{}, body_rms{};    ///< σzz over the elements of the lower and upper body
  double master_penetration = 0.0; ///< deepest master node into the slave (mm; mm/s for flowing bodies), ≥ 0
  int interface_nodes = 0;
  double wall_time = 0.0;    ///< s, the whole run
  double contact_time = 0.0; ///< s, contact search and contact terms
  int newton_iterations = 0;
};

/// Runs `case_file` (relative to the source tree) with `overrides` into
/// `out` (emptied first) and measures the relative errors against the
/// uniform exact stress. Newton is converged far below the errors measured
/// (the runs' default 1e-6 would move their fourth digit).
/// Under mpirun every process solves; rank 0 alone measures (the others get zeros).
inline Errors run_case(const std::string& case_file, std::vector<std::string> overrides, double exact_stress,
                       const std::string& master_body, const std::string& source_dir, const std::string& out) {
  overrides.insert(overrides.end(), {"solver.tolerance=1e-10", "solver.increment_tolerance=1e-10"});
  anvil::scene::Case c = anvil::scene::read_case(source_dir + "/" + case_file, overrides);
  // Under mpirun rank 0 alone writes the run's files: it alone empties and
  // reads them (the others would race it to the next case's folder).
  if (anvil::processes::root()) std::filesystem::remove_all(out);
  anvil::run::run(c, {out});
  Errors e;
  if (!anvil::processes::root()) return e;
  double sum_sq = 0.0;
  for (const anvil::io::InterfaceRow& row : anvil::io::read_interface(out)) {
    const double error = std::abs(row.normal_stress - exact_stress) / exact_stress;
    e.interface_max = std::max(e.interface_max, error);
    sum_sq += error * error;
    ++e.interface_nodes;
    // The run starts touching (gap 0): the penetration is the closing motion.
    if (row.body == master_body) e.master_penetration = std::max(e.master_penetration, -(row.gap + row.gap_rate));
  }
  e.interface_rms = std::sqrt(sum_sq / std::max(e.interface_nodes, 1));
  const std::vector<double> stress = anvil::io::read_last_cell_field(out, "stress", 6);
  const std::vector<double> body = anvil::io::read_last_cell_field(out, "body_id", 1);
  std::array<int, 2> cells{};
  for (std::size_t cell = 0; cell < body.size(); ++cell) {
    const int b = body[cell] > 0.5 ? 1 : 0;
    const double error = std::abs(-stress[6 * cell + 2] - exact_stress) / exact_stress;
    e.body_max[b] = std::max(e.body_max[b], error);
    e.body_rms[b] += error * error;
    ++cells[b];
  }
  for (int b = 0; b < 2; ++b)
    e.body_rms[b] = std::sqrt(e.body_rms[b] / std::max(cells[b], 1));
  e.interior_max = std::max(e.body_max[0], e.body_max[1]);
  e.wall_time = anvil::io::read_summary_number(out, "total");
  e.contact_time = anvil::io::read_summary_number(out, "search") + anvil::io::read_summary_number(out, "contact");
  e.newton_iterations = static_cast<int>(anvil::io::read_summary_number(out, "newton_iterations"));
  return e;
}

/// One configuration of the paper's blocks: the lower block is the master.
inline Errors run(const LoadCase& load, const MeshPair& meshes, const std::string& formulation,
                  const std::string& source_dir, const std::string& out) {
  auto size = [](int cells) { return std::to_string(10.0 / cells); };
  return run_case(load.file,
                  {"bodies[0].mesh.element_size=" + size(meshes.master_cells),
                   "bodies[1].mesh.element_size=" + size(meshes.slave_cells),
                   "contact_pairs[0].formulation=" + formulation},
                  load.exact_stress, "lower", source_dir, out);
}

// The 3D patch test on two stacked unit cubes (cases/patch_test_cubes*.yaml),
// the set-up contact codes are compared on: n_l cells per edge in the lower
// cube, n_u in the upper one, either body as master, every formulation and
// integration.

struct CubesLoad {
  const char* name;
  const char* file;     ///< relative to the source tree
  const char* material; ///< card for both cubes, relative to the case file
  double stiffness;     ///< G (elastic) or η (Newtonian): the secant viscosity ρ is scaled by (MPa, MPa·s)
  double penalty;       ///< ρ wanted (MPa/mm elastic, MPa·s/mm Newtonian)
  double exact_stress;  ///< MPa, the uniform |σzz|
};

/// ρ = 1e6 MPa/mm for the elastic cubes (the compared codes' penalty), and
/// for the Newtonian ones the same compliance relative to the motion:
/// (σ/ρ)/(σH/3η) = 3η/(ρH) = E/(1e6 H) = 5e-4 gives ρ = 3000 MPa·s/mm.
/// Exact stresses: 1 MPa pressure; E u/H = 1000 × 0.002/2; 3ηV/H = 3 × 0.002/2.
inline const std::vector<CubesLoad>& cubes_loads() {
  static const std::vector<CubesLoad> loads = {
      {"elastic 0.3, pressure", "cases/patch_test_cubes.yaml", "../materials/patch_test_elastic.yaml", 1000.0 / 2.6,
       1e6, 1.0},
      {"elastic 0.49, pressure", "cases/patch_test_cubes.yaml",
       "../materials/patch_test_elastic_nearly_incompressible.yaml", 1000.0 / 2.98, 1e6, 1.0},
      {"elastic 0.3, displacement", "cases/patch_test_cubes_displacement.yaml", "../materials/patch_test_elastic.yaml",
       1000.0 / 2.6, 1e6, 1.0},
      {"elastic 0.49, displacement", "cases/patch_test_cubes_displacement.yaml",
       "../materials/patch_test_elastic_nearly_incompressible.yaml", 1000.0 / 2.98, 1e6, 1.0},
      {"Newtonian, pressure", "cases/patch_test_cubes.yaml", "../materials/newtonian_reference.yaml", 1.0, 3000.0, 1.0},
      {"Newtonian, velocity", "cases/patch_test_cubes_displacement.yaml", "../materials/newtonian_reference.yaml", 1.0,
       3000.0, 0.003},
  };
  return loads;
}

struct CubesMeshes {
  int lower, upper; ///< cells per edge
};

inline const std::vector<CubesMeshes>& cubes_meshes() {
  static const std::vector<CubesMeshes> meshes = {{2, 8}, {3, 7}, {4, 4},  {4, 5}, {5, 4},
                                                  {7, 3}, {8, 2}, {2, 16}, {16, 2}};
  return meshes;
}

struct CubesMethod {
  std::string formulation = "quasi_symmetric", integration = "facet";
  bool lower_master = true;
  int facet_subdivision = -1; ///< subdivision quadrature: levels; −1: the case's default
  std::string quadrature;     ///< facet integration: intersection or subdivision; empty: the case's default
};

/// A formulation and integration with the case's own quadrature.
inline CubesMethod cubes_method(const std::string& formulation, const std::string& integration, bool lower_master) {
  CubesMethod method;
  method.formulation = formulation;
  method.integration = integration;
  method.lower_master = lower_master;
  return method;
}

inline Errors run_cubes(const CubesLoad& load, const CubesMeshes& meshes, const CubesMethod& method,
                        const std::string& source_dir, const std::string& out) {
  auto size = [](int cells) { return std::to_string(1.0 / cells); };
  // contact.penalty scales 3 × the secant viscosity over the scene size (the
  // stacked cubes' diagonal, √6 mm) into ρ.
  const double factor = load.penalty * std::sqrt(6.0) / (3.0 * load.stiffness);
  const std::string master = method.lower_master ? "lower" : "upper", slave = method.lower_master ? "upper" : "lower";
  std::vector<std::string> overrides = {"bodies[].material=" + std::string(load.material),
                                        "bodies[0].mesh.element_size=" + size(meshes.lower),
                                        "bodies[1].mesh.element_size=" + size(meshes.upper),
                                        "contact_pairs[0].master=" + master,
                                        "contact_pairs[0].slave=" + slave,
                                        "contact_pairs[0].formulation=" + method.formulation,
                                        "contact_pairs[0].integration=" + method.integration,
                                        "contact.penalty=" + std::to_string(factor)};
  if (!method.quadrature.empty()) overrides.push_back("contact_pairs[0].facet_quadrature=" + method.quadrature);
  if (method.facet_subdivision >= 0)
    overrides.push_back("contact_pairs[0].facet_subdivision=" + std::to_string(method.facet_subdivision));
  Errors e = run_case(load.file, overrides, load.exact_stress, master, source_dir, out);
  e.master_penetration /= load.exact_stress / load.penalty; // over the penalty's own penetration σ/ρ
  return e;
}

// The curved interface of cases/hertz_cylinder.yaml (a cylinder, R = 10 mm,
// on a block in a plane-strain slice 0.4 mm thick, half the cylinder
// modelled; E = 1000 MPa, ν = 0.3 both) against Hertz's line contact
// (Johnson 1985, §4.3) at the load each run transmits.

struct Hertz {
  double half_width, peak; ///< b (mm), p0 (MPa)
  double pressure(double y) const {
    return y >= half_width ? 0.0 : peak * std::sqrt(1.0 - (y * y) / (half_width * half_width));
  }
};

struct HertzErrors {
  Hertz hertz;
  std::array<double, 2> peak{};    ///< mean normal stress at the line of first contact / p0: cylinder, block
  std::array<int, 2> peak_nodes{}; ///< nodes on that line, per body
  double profile_max = 0.0, profile_rms = 0.0; ///< |p − p_Hertz| / p0 over the interface nodes within 1.5 b
  double contact_half_width = 0.0;             ///< mm, the farthest node carrying 1e-3 p0
  double master_depth = 0.0;                   ///< mm, the deepest master node
};

/// Hertz at the support force `force` (N, on the half model) and the
/// errors of the interface rows of a run whose master body is `master`.
inline HertzErrors compare_with_hertz(const std::vector<anvil::io::InterfaceRow>& rows, double force,
                                      const std::string& master) {
  const double load = 2.0 * force / 0.4, radius = 10.0, plane_modulus = 1000.0 / (2.0 * (1.0 - 0.3 * 0.3));
  const double b = std::sqrt(4.0 * load * radius / (M_PI * plane_modulus));
  HertzErrors e{.hertz = {b, 2.0 * load / (M_PI * b)}};
  double error_sq = 0.0;
  int count = 0;
  for (const anvil::io::InterfaceRow& row : rows) {
    const double y = row.position.y();
    const int body = row.body == "cylinder" ? 0 : 1;
    if (y < 1e-6) e.peak[body] += row.normal_stress, ++e.peak_nodes[body];
    if (row.normal_stress > 1e-3 * e.hertz.peak) e.contact_half_width = std::max(e.contact_half_width, y);
    if (row.body == master) e.master_depth = std::max(e.master_depth, -row.gap);
    if (y > 1.5 * b) continue;
    const double error = std::abs(row.normal_stress - e.hertz.pressure(y)) / e.hertz.peak;
    e.profile_max = std::max(e.profile_max, error);
    error_sq += error * error;
    ++count;
  }
  for (int body = 0; body < 2; ++body)
    e.peak[body] /= std::max(e.peak_nodes[body], 1) * e.hertz.peak;
  e.profile_rms = std::sqrt(error_sq / std::max(count, 1));
  return e;
}

} // namespace patch_test
