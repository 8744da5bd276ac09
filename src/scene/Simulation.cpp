#include "anvil/scene/Simulation.h"

#include "anvil/core/Timers.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/fem/mini_element.h"
#include "anvil/io/VtkSeries.h"
#include "anvil/io/atomic_file.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/mesh_io.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/scene/effects.h"

#include <tbb/info.h>

#include <chrono>
#include <filesystem>
#include <sstream>

namespace anvil::scene {
namespace {

mesh::TetMesh build_mesh(const MeshSpec& spec) {
  if (!spec.file.empty()) return mesh::read_mesh(spec.file);
  mesh::TetMesh m = spec.generate == "box" ? mesh::make_box(spec.origin, spec.size, spec.element_size)
                                           : mesh::make_cylinder(spec.radius, spec.height, spec.element_size);
  mesh::validate(m, spec.source + " (generated " + spec.generate + ")");
  return m;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

} // namespace

std::string output_directory(const Case& c, const RunOptions& options) {
  if (!options.output_directory.empty()) return options.output_directory;
  if (!c.output_directory.empty()) return c.output_directory;
  return "out/" + std::filesystem::path(c.path).stem().string();
}

void run(const Case& c, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Timers timers;

  // Build everything that can fail on input before a single file is written.
  const BodySpec& body = c.bodies.front();
  std::unique_ptr<material::Material> law = read_material(body.material_file);
  mesh::TetMesh mesh = build_mesh(body.mesh);
  std::vector<BoundaryCondition> conditions;
  for (std::size_t i = 0; i < c.boundary.size(); ++i)
    if (c.boundary_body[i] == 0) conditions.push_back(c.boundary[i]);
  const ImposedConditions imposed = [&] {
    Timers::Scope scope(timers, "effect boundary_conditions");
    return impose(mesh, conditions);
  }();
  const std::vector<std::string> effects = resolve_effects(c, {law.get()});

  const std::string out = output_directory(c, options);
  std::filesystem::create_directories(out);
  log::open_file(out + "/anvil.log");
  log::info("anvil %s — %s", ANVIL_VERSION, c.path.c_str());
  if (!c.title.empty()) log::info("  %s", c.title.c_str());
  log::info("body '%s': %d nodes, %d tetrahedra, volume %.6g mm3", body.name.c_str(), mesh.node_count(),
            mesh.tet_count(), mesh::volume(mesh));
  log::info("  material %s: %s", body.material_file.c_str(), law->describe().c_str());
  for (std::size_t i = 0; i < conditions.size(); ++i)
    log::info("  boundary '%s': %zu nodes", conditions[i].name.c_str(), imposed.nodes_of_condition[i].size());
  std::string effect_list;
  for (const auto& e : effects) effect_list += " " + e;
  log::info("effects:%s", effect_list.c_str());

  // The increment.
  solver::IncrementSolver solver(mesh, imposed.prescribed, c.linear_solver, timers);
  log::info("unknowns: %d (velocity and pressure, after %d prescribed)", solver.free_count(),
            static_cast<int>(imposed.prescribed.size()) - solver.free_count());
  log::info("solver: %s (asked: %s), Newton tolerance %.1e, %d threads",
            solver::to_string(solver.linear_solver()).c_str(), solver::to_string(c.linear_solver).c_str(),
            c.newton.tolerance, tbb::info::default_concurrency());
  fem::BodyUnknowns unknowns{imposed.values, Eigen::VectorXd::Zero(3 * mesh.tet_count())};
  log::info("increment 1");
  const solver::NewtonReport report = solver.solve(*law, {}, imposed.nodal_forces, {}, c.newton, unknowns);
  if (!report.converged) throw RunError("increment 1 of body '" + body.name + "': " + report.failure);

  // Outputs.
  std::ostringstream loads;
  loads << "increment,time_s,surface,Fx_N,Fy_N,Fz_N\n";
  loads.precision(10);
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    if (!conditions[i].prescribes_velocity()) continue;
    // Force the body exerts on the surface (die load): minus the reaction on the body.
    const Eigen::Vector3d f = -reaction(imposed, static_cast<int>(i), solver.residual());
    loads << 1 << "," << 0.0 << "," << conditions[i].name << "," << f.x() << "," << f.y() << "," << f.z() << "\n";
    log::info("  load on '%s': Fx %.6g N  Fy %.6g N  Fz %.6g N", conditions[i].name.c_str(), f.x(), f.y(), f.z());
  }
  {
    Timers::Scope scope(timers, "output");
    if (c.write_vtk) {
      const bool elastic = law->is_elastic();
      io::Field velocity{elastic ? "displacement" : "velocity", 3, {}}, pressure{"pressure", 1, {}};
      for (int i = 0; i < mesh.node_count(); ++i) {
        for (int k = 0; k < 3; ++k) velocity.values.push_back(unknowns.nodal[4 * i + k]);
        pressure.values.push_back(unknowns.nodal[4 * i + 3]);
      }
      io::Field stress{"stress", 6, {}}, rate{elastic ? "equivalent_strain" : "equivalent_strain_rate", 1, {}},
          body_id{"body_id", 1, {}}, quality{"element_quality", 1, {}};
      fem::MiniElementInput in;
      for (int e = 0; e < mesh.tet_count(); ++e) {
        const mesh::Tet& t = mesh.tets[e];
        for (int a = 0; a < 4; ++a) {
          in.vertices[a] = mesh.nodes[t[a]];
          in.nodal_velocity[a] = unknowns.nodal.segment<3>(4 * t[a]);
          in.nodal_pressure[a] = unknowns.nodal[4 * t[a] + 3];
        }
        const fem::MiniElementFields f = fem::mini_element_fields(in, *law);
        const material::Vec6 s = material::to_components(f.stress);
        stress.values.insert(stress.values.end(), s.data(), s.data() + 6);
        rate.values.push_back(f.equivalent_strain_rate);
        body_id.values.push_back(0);
        quality.values.push_back(mesh::quality(mesh, e));
      }
      io::VtkSeries series(out, "anvil");
      series.write(1, 0.0, 0, body.name, mesh, {velocity, pressure}, {stress, rate, body_id, quality});
    }
    io::write_file_atomically(out + "/loads.csv", loads.str());
  }

  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream summary;
  summary.precision(10);
  summary << "{\n  \"case\": " << json_string(c.path) << ",\n  \"title\": " << json_string(c.title) << ",\n"
          << "  \"anvil_version\": " << json_string(ANVIL_VERSION) << ",\n"
          << "  \"bodies\": [{\"name\": " << json_string(body.name) << ", \"nodes\": " << mesh.node_count()
          << ", \"elements\": " << mesh.tet_count() << ", \"unknowns\": " << solver.free_count()
          << ", \"volume_mm3\": " << mesh::volume(mesh) << "}],\n"
          << "  \"increments\": 1,\n  \"newton_iterations\": " << report.iterations.size() << ",\n"
          << "  \"final_residual\": {\"force\": " << report.iterations.back().force_residual
          << ", \"div\": " << report.iterations.back().flux_residual << "},\n"
          << "  \"effects\": [";
  for (std::size_t i = 0; i < effects.size(); ++i) summary << (i ? ", " : "") << json_string(effects[i]);
  summary << "],\n  \"wall_time_s\": {";
  for (const auto& [phase, seconds] : timers.all()) summary << json_string(phase) << ": " << seconds << ", ";
  summary << "\"total\": " << total << "}\n}\n";
  io::write_file_atomically(out + "/summary.json", summary.str());
  log::info("done in %.2f s (assembly %.2f s, solve %.2f s, output %.2f s); results in %s/", total,
            timers.seconds("assembly"), timers.seconds("solve"), timers.seconds("output"), out.c_str());
  log::close_file();
}

} // namespace anvil::scene
