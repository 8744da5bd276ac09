// The contact patch tables.
//   tools/patch_test [DIR]               the 3D patch test on two stacked unit
//       cubes: 6 load cases × 9 mesh pairs × either body as master × 3
//       formulations × nodal and facet integration (648 runs, about 15 min);
//       normal-stress error over the interface nodes of both bodies, σzz
//       error over each body's elements, the deepest master node over the
//       penalty's own penetration, Newton iterations, then the worst figures
//       per formulation and integration, and the largest force change when
//       master and slave are swapped (displacement cases).
//   tools/patch_test --quadrature [DIR]  facet integration: error against the
//       quadrature's subdivision levels and the contact time they cost.
//   tools/patch_test --paper [DIR]       the blocks of Fourment 2008 §5.2: 4
//       load cases × 6 mesh pairs × 3 formulations, nodal.
//   tools/patch_test --curved [DIR]      a curved interface: the cylinder on a
//       block of cases/hertz_cylinder.yaml, 2 block meshes × either body as
//       master × master/slave and quasi-symmetric × nodal and facet, against
//       Hertz at the load each run transmits: the pressure at the line of
//       first contact, the profile, the contact width, the deepest master node.
// Prints Markdown tables and writes DIR/*.csv (default DIR: out/patch_test_table).
#include "anvil/contact/facet_quadrature.h"
#include "anvil/core/blas_kernels.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/solver/PetscSession.h"
#include "patch_test_cases.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>

namespace {

/// Where a table goes: `path` on rank 0; the other processes of an mpirun
/// solve the same cases with it and write nothing.
std::string table_file(const std::string& path) {
  return anvil::processes::root() ? path : "/dev/null";
}

using patch_test::CubesLoad;
using patch_test::CubesMeshes;
using patch_test::CubesMethod;
using patch_test::Errors;

const char* const kFormulations[] = {"master_slave", "quasi_symmetric", "symmetric"};

std::string pair_name(const CubesMeshes& m) {
  return std::to_string(m.lower) + "/" + std::to_string(m.upper);
}

void paper_table(const std::string& out) {
  std::ofstream csv(table_file(out + "/patch_test.csv"));
  csv << "case,meshes,formulation,interface_max,interface_rms,interior_max,interface_nodes,newton_iterations,wall_"
         "time_s\n";
  std::printf("| case | meshes (master/slave cells) | formulation | interface max | interface RMS | interior max | "
              "Newton | time |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (const auto& load : patch_test::load_cases())
    for (const auto& meshes : patch_test::mesh_pairs())
      for (const char* formulation : kFormulations) {
        const Errors e = patch_test::run(load, meshes, formulation, ANVIL_SOURCE_DIR, out + "/run");
        std::printf("| %s | %s | %s | %.2f %% | %.2f %% | %.2f %% | %d | %.2f s |\n", load.name, meshes.name,
                    formulation, 100 * e.interface_max, 100 * e.interface_rms, 100 * e.interior_max,
                    e.newton_iterations, e.wall_time);
        std::fflush(stdout);
        csv << '"' << load.name << "\",\"" << meshes.name << "\"," << formulation << "," << e.interface_max << ","
            << e.interface_rms << "," << e.interior_max << "," << e.interface_nodes << "," << e.newton_iterations << ","
            << e.wall_time << "\n";
      }
}

/// Total force through the support: the exact stress times the loaded area
/// is the same on every mesh; what the swap test compares is the run's.
double support_force(const std::string& dir) {
  return anvil::io::read_loads(dir, "support").back().force.z();
}

void cubes_table(const std::string& out) {
  std::ofstream csv(table_file(out + "/patch_test_cubes.csv"));
  csv << "case,lower_cells,upper_cells,master,formulation,integration,pressure_max,pressure_rms,lower_szz_max,lower_"
         "szz_rms,upper_szz_max,upper_szz_rms,master_penetration_ratio,newton_iterations,wall_time_s,support_force_N\n";
  std::printf("| case | n_l/n_u | master | formulation | integration | pressure max | pressure RMS | σzz max lower | "
              "σzz RMS lower | σzz max upper | σzz RMS upper | master depth / penalty | Newton | time |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  struct Worst {
    double pressure = 0, szz = 0, depth = 0, swap = 0;
    int extra_newton = -99;
    void include(const Worst& o) {
      pressure = std::max(pressure, o.pressure), szz = std::max(szz, o.szz), depth = std::max(depth, o.depth);
      swap = std::max(swap, o.swap), extra_newton = std::max(extra_newton, o.extra_newton);
    }
  };
  // The matching pair first: the others' Newton counts are compared with it.
  std::vector<CubesMeshes> pairs = patch_test::cubes_meshes();
  std::stable_partition(pairs.begin(), pairs.end(), [](const CubesMeshes& m) { return m.lower == m.upper; });
  std::map<std::string, std::map<std::string, Worst>> worst_of_load; // by load, then formulation + integration
  for (const CubesLoad& load : patch_test::cubes_loads()) {
    const bool displacement = std::strstr(load.name, "displacement") || std::strstr(load.name, "velocity");
    std::map<std::string, Worst>& worst = worst_of_load[load.name];
    std::map<std::string, int> matching_newton;
    for (const CubesMeshes& meshes : pairs)
      for (const char* formulation : kFormulations)
        for (const char* integration : {"nodal", "facet"}) {
          const std::string method = std::string(formulation) + " " + integration;
          std::array<double, 2> force{};
          for (const bool lower_master : {true, false}) {
            const Errors e =
                patch_test::run_cubes(load, meshes, patch_test::cubes_method(formulation, integration, lower_master),
                                      ANVIL_SOURCE_DIR, out + "/run");
            force[lower_master ? 0 : 1] = support_force(out + "/run");
            std::printf("| %s | %s | %s | %s | %s | %.3g %% | %.3g %% | %.3g %% | %.3g %% | %.3g %% | %.3g %% | %.3g | "
                        "%d | %.2f s |\n",
                        load.name, pair_name(meshes).c_str(), lower_master ? "lower" : "upper", formulation,
                        integration, 100 * e.interface_max, 100 * e.interface_rms, 100 * e.body_max[0],
                        100 * e.body_rms[0], 100 * e.body_max[1], 100 * e.body_rms[1], e.master_penetration,
                        e.newton_iterations, e.wall_time);
            std::fflush(stdout);
            csv << '"' << load.name << "\"," << meshes.lower << "," << meshes.upper << ","
                << (lower_master ? "lower" : "upper") << "," << formulation << "," << integration << ","
                << e.interface_max << "," << e.interface_rms << "," << e.body_max[0] << "," << e.body_rms[0] << ","
                << e.body_max[1] << "," << e.body_rms[1] << "," << e.master_penetration << "," << e.newton_iterations
                << "," << e.wall_time << "," << force[lower_master ? 0 : 1] << "\n";
            Worst& w = worst[method];
            w.pressure = std::max(w.pressure, e.interface_max);
            w.szz = std::max(w.szz, e.interior_max);
            w.depth = std::max(w.depth, e.master_penetration);
            if (meshes.lower == meshes.upper)
              matching_newton[method] = e.newton_iterations;
            else if (matching_newton.count(method))
              w.extra_newton = std::max(w.extra_newton, e.newton_iterations - matching_newton[method]);
          }
          if (displacement)
            worst[method].swap =
                std::max(worst[method].swap, std::abs(force[1] - force[0]) / std::max(std::abs(force[0]), 1e-300));
        }
  }
  auto print = [](const std::string& load, const std::string& method, const Worst& w) {
    const std::size_t space = method.find(' ');
    std::printf("| %s | %s | %s | %.3g %% | %.3g %% | %.3g | %d | %.3g %% |\n", load.c_str(),
                method.substr(0, space).c_str(), method.substr(space + 1).c_str(), 100 * w.pressure, 100 * w.szz,
                w.depth, w.extra_newton, 100 * w.swap);
  };
  std::printf("\nWorst over the 9 mesh pairs and both master choices, per case, then over the 6 cases:\n\n"
              "| case | formulation | integration | pressure max | σzz max | master depth / penalty | Newton above "
              "matching | swap force change (displacement cases) |\n|---|---|---|---|---|---|---|---|\n");
  std::map<std::string, Worst> overall;
  for (const auto& [load, worst] : worst_of_load)
    for (const auto& [method, w] : worst) {
      print(load, method, w);
      overall[method].include(w);
    }
  for (const auto& [method, w] : overall)
    print("all", method, w);
}

void quadrature_table(const std::string& out) {
  std::ofstream csv(table_file(out + "/facet_quadrature.csv"));
  csv << "meshes,master,formulation,quadrature,levels,pressure_max,szz_max,contact_time_s,wall_time_"
         "s\n";
  std::printf("| n_l/n_u | master | formulation | quadrature | pressure max | σzz max | contact time | run |\n"
              "|---|---|---|---|---|---|---|---|\n");
  const CubesLoad& load = patch_test::cubes_loads().front();
  for (const CubesMeshes& meshes : {CubesMeshes{3, 7}, CubesMeshes{2, 16}})
    for (const bool lower_master : {true, false})
      for (const char* formulation : {"master_slave", "quasi_symmetric"})
        for (int levels = -1; levels <= anvil::contact::kMaxFacetSubdivision; ++levels) {
          const bool intersection = levels < 0;
          const Errors e = patch_test::run_cubes(load, meshes,
                                                 {.formulation = formulation,
                                                  .integration = "facet",
                                                  .lower_master = lower_master,
                                                  .facet_subdivision = std::max(levels, 0),
                                                  .quadrature = intersection ? "intersection" : "subdivision"},
                                                 ANVIL_SOURCE_DIR, out + "/run");
          const std::string quadrature = intersection ? "intersection" : std::to_string(levels) + " levels";
          std::printf("| %s | %s | %s | %s | %.3g %% | %.3g %% | %.3f s | %.2f s |\n", pair_name(meshes).c_str(),
                      lower_master ? "lower" : "upper", formulation, quadrature.c_str(), 100 * e.interface_max,
                      100 * e.interior_max, e.contact_time, e.wall_time);
          std::fflush(stdout);
          csv << pair_name(meshes) << "," << (lower_master ? "lower" : "upper") << "," << formulation << ","
              << (intersection ? "intersection" : "subdivision") << "," << std::max(levels, 0) << "," << e.interface_max
              << "," << e.interior_max << "," << e.contact_time << "," << e.wall_time << "\n";
        }
}

void curved_table(const std::string& out) {
  std::ofstream csv(table_file(out + "/hertz_cylinder.csv"));
  csv << "cylinder_size,block_size,master,formulation,integration,support_force_N,hertz_half_width_mm,hertz_peak_MPa,"
         "peak_cylinder,peak_block,profile_max,profile_rms,contact_half_width_mm,master_depth_um,newton_iterations,"
         "contact_time_s\n";
  std::ofstream profile(table_file(out + "/hertz_cylinder_profile.csv"));
  profile << "cylinder_size,block_size,master,formulation,integration,body,y_mm,z_mm,normal_stress_MPa,hertz_MPa\n";
  std::printf(
      "| h cylinder/block | master | formulation | integration | load | Hertz b, p0 | peak / p0 cylinder, block | "
      "profile error max, RMS (of p0) | contact half-width / b | deepest master node | Newton | contact time |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double block_size : {0.15, 0.35})
    for (const char* master : {"block", "cylinder"})
      for (const char* formulation : {"master_slave", "quasi_symmetric"})
        for (const char* integration : {"nodal", "facet"}) {
          const std::string slave = std::string(master) == "block" ? "cylinder" : "block";
          const std::string dir = out + "/run";
          anvil::scene::Case c = anvil::scene::read_case(std::string(ANVIL_SOURCE_DIR) + "/cases/hertz_cylinder.yaml",
                                                         {"bodies[1].mesh.element_size=" + std::to_string(block_size),
                                                          "contact_pairs[0].master=" + std::string(master),
                                                          "contact_pairs[0].slave=" + slave,
                                                          "contact_pairs[0].formulation=" + std::string(formulation),
                                                          "contact_pairs[0].integration=" + std::string(integration)});
          std::filesystem::remove_all(dir);
          anvil::run::run(c, {dir});
          const std::vector<anvil::io::InterfaceRow> rows = anvil::io::read_interface(dir);
          const double force = std::abs(anvil::io::read_loads(dir, "support").back().force.x());
          const patch_test::HertzErrors e = patch_test::compare_with_hertz(rows, force, master);
          const patch_test::Hertz& h = e.hertz;
          for (const anvil::io::InterfaceRow& row : rows)
            profile << c.bodies[0].mesh.element_size << "," << block_size << "," << master << "," << formulation << ","
                    << integration << "," << row.body << "," << row.position.y() << "," << row.position.z() << ","
                    << row.normal_stress << "," << h.pressure(row.position.y()) << "\n";
          const double contact_time =
              anvil::io::read_summary_number(dir, "search") + anvil::io::read_summary_number(dir, "contact");
          const int newton = static_cast<int>(anvil::io::read_summary_number(dir, "newton_iterations"));
          std::printf(
              "| %.2g/%.2g mm | %s | %s | %s | %.4g N | %.3f mm, %.2f MPa | %.3f, %.3f | %.1f %%, %.1f %% | %.2f | "
              "%.2g µm | %d | %.2f s |\n",
              c.bodies[0].mesh.element_size, block_size, master, formulation, integration, force, h.half_width, h.peak,
              e.peak[0], e.peak[1], 100 * e.profile_max, 100 * e.profile_rms, e.contact_half_width / h.half_width,
              1e3 * e.master_depth, newton, contact_time);
          std::fflush(stdout);
          csv << c.bodies[0].mesh.element_size << "," << block_size << "," << master << "," << formulation << ","
              << integration << "," << force << "," << h.half_width << "," << h.peak << "," << e.peak[0] << ","
              << e.peak[1] << "," << e.profile_max << "," << e.profile_rms << "," << e.contact_half_width << ","
              << 1e3 * e.master_depth << "," << newton << "," << contact_time << "\n";
        }
}

} // namespace

int main(int argc, char** argv) {
  anvil::blas_kernels::pin(argv); // the kernels of anvil run (docs/parallel-runs.md)
  std::string mode = "cubes", out = "out/patch_test_table";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::puts("usage: tools/patch_test [--paper | --quadrature | --curved] [DIR]\n"
                "  (default) the unit-cube table: 648 runs, about 15 minutes; DIR/patch_test_cubes.csv\n"
                "  --quadrature  facet quadrature levels against error and contact time; DIR/facet_quadrature.csv\n"
                "  --paper       the blocks of Fourment 2008, nodal contact: 72 runs; DIR/patch_test.csv\n"
                "  --curved      a cylinder on a block against Hertz: 16 runs; DIR/hertz_cylinder*.csv\n"
                "  --swap        two cubes with either as master; --interface  one pair drawn (tools/patch_test only)\n"
                "  DIR defaults to out/patch_test_table; tools/patch_test writes the tables into docs/verification.md");
      return 0;
    }
    if (arg == "--paper" || arg == "--quadrature" || arg == "--curved")
      mode = arg.substr(2);
    else
      out = arg;
  }
  int petsc_argc = 1; // the tool's own arguments are not PETSc's
  anvil::solver::PetscSession petsc(petsc_argc, argv);
  if (!anvil::processes::root() && !std::freopen("/dev/null", "w", stdout)) return 1; // rank 0 prints the tables
  try {
    std::filesystem::create_directories(out);
    anvil::log::set_quiet(true);
    if (mode == "paper")
      paper_table(out);
    else if (mode == "quadrature")
      quadrature_table(out);
    else if (mode == "curved")
      curved_table(out);
    else
      cubes_table(out);
    std::printf("results in %s/\n", out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "patch_test: %s\n", e.what());
    return 1;
  }
  return 0;
}
