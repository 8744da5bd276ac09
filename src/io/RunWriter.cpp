#include "anvil/io/RunWriter.h"

#include "anvil/io/Checkpoint.h"

#include "anvil/io/RunResults.h"

#include "anvil/contact/folds.h"
#include "anvil/scene/damage_peak.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/fem/element_fields.h"
#include "anvil/io/JsonWriter.h"
#include "anvil/io/atomic_file.h"
#include "anvil/material/mandel.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/thermal/HeatStep.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

namespace anvil::io {
namespace {

void put_load_rows(std::ostream& out, const scene::Scene& scene, const std::vector<scene::LoadRecord>& loads,
                   std::size_t first) {
  out.precision(10);
  for (std::size_t i = first; i < loads.size(); ++i) {
    const scene::LoadRecord& r = loads[i];
    out << r.increment << "," << r.time << "," << scene.surfaces[r.surface].name << "," << r.stroke << ","
        << r.force.x() << "," << r.force.y() << "," << r.force.z() << "," << scene.whole_part_load(r) << ",";
    if (std::isfinite(r.contact_area))
      out << r.contact_area << "," << r.fill;
    else
      out << ",";
    out << "\n";
  }
}

} // namespace

RunWriter::RunWriter(std::string directory, const scene::RunState& state, bool resume)
    : directory_(std::move(directory)), series_(directory_, "anvil") {
  if (!resume) return;
  processes::on_root([&] { series_.resume(state.outputs, state.time); });
  last_vtk_ = last_checkpoint_ = state.increment;
}

bool RunWriter::write(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, bool force,
                      Timers& timers) {
  return processes::on_root_answer([&] { return write_due(scene, disc, state, force, timers); });
}

void RunWriter::write_frame(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state,
                            Timers& timers) {
  processes::on_root([&] { write_frame_due(scene, disc, state, false, timers); });
}

void RunWriter::write_frame_due(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state,
                                bool force, Timers& timers) {
  Timers::Scope scope(timers, "output");
  write_loads(scene, state);
  const bool vtk_due = scene.input.write_vtk && (force || state.increment % scene.input.vtk_every == 0);
  if (vtk_due && last_vtk_ != state.increment) {
    write_vtk(scene, disc, state);
    if (disc.pair_contact) write_interface(scene, disc, state);
    state.outputs = series_.entries();
    last_vtk_ = state.increment;
  }
}

bool RunWriter::write_due(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state,
                          bool force, Timers& timers) {
  write_frame_due(scene, disc, state, force, timers);
  const int every = scene.input.checkpoint_every;
  const bool checkpoint_due =
      scene.input.time.enabled && every > 0 && !checkpoints_stopped_ && (force || state.increment % every == 0);
  if (!checkpoint_due || last_checkpoint_ == state.increment) return false;
  Timers::Scope scope(timers, "checkpoint");
  write_checkpoint(directory_ + "/checkpoint.h5", state, scene.fingerprint);
  last_checkpoint_ = state.increment;
  return true;
}

void RunWriter::write_loads(const scene::Scene& scene, const scene::RunState& state) {
  const std::string path = directory_ + "/loads.csv";
  if (!loads_started_) {
    std::ostringstream whole;
    whole << kLoadsHeader << "\n";
    put_load_rows(whole, scene, state.loads, 0);
    write_file_atomically(path, whole.str());
    loads_started_ = true;
  } else if (loads_written_ < state.loads.size()) {
    std::ostringstream rows;
    put_load_rows(rows, scene, state.loads, loads_written_);
    append_whole(path, rows.str());
  }
  loads_written_ = state.loads.size();
}

void RunWriter::write_vtk(const scene::Scene& scene, const scene::Discretisation& disc, const scene::RunState& state) {
  const mesh::TetMesh& mesh = state.mesh;
  const bool elastic = scene.solve_displacement;
  fem::ElementFields fields = fem::element_fields(mesh, disc.element_laws, disc.point_states, state.unknowns);
  // An elastic body in velocity form carries σ_{n+1}, accepted with the increment.
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].velocity_form)
      for (int e = state.bodies[b].first_tet; e < state.bodies[b].first_tet + state.bodies[b].tet_count; ++e)
        fields.stress[e] = Eigen::Map<const material::Vec6>(&state.elastic_stress[6 * e]);
  Field velocity{elastic ? "displacement" : "velocity", 3, {}}, pressure{"pressure", 1, {}};
  Field contact_status{"contact_status", 1, std::vector<double>(mesh.nodes.size(), 0.0)};
  Field contact_pressure{"contact_pressure", 1, std::vector<double>(mesh.nodes.size(), 0.0)};
  Field gap{"gap", 1, std::vector<double>(mesh.nodes.size(), -1.0)};
  for (int i = 0; i < mesh.node_count(); ++i) {
    for (int k = 0; k < 3; ++k)
      velocity.values.push_back(state.unknowns.nodal[4 * i + k]);
    pressure.values.push_back(state.unknowns.nodal[4 * i + 3]);
  }
  if (disc.pair_contact) {
    // Body pairs: the same fields at the nodes projected onto the other body.
    const auto& points = disc.pair_contact->projected_nodes();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int node = points[i].node();
      const double p = disc.pair_contact->node_pressure(int(i), state.unknowns.nodal);
      contact_status.values[node] = std::max(contact_status.values[node], p > 0.0 ? 2.0 : 1.0);
      contact_pressure.values[node] = std::max(contact_pressure.values[node], p);
      gap.values[node] = std::max(points[i].gap, 0.0);
    }
  }
  if (!scene.dies.empty()) {
    // Status: 0 far from dies, 1 candidate (near a die), 2 in contact. Gap at
    // the start of the increment (mm), −1 where no die is near.
    const auto& candidates = disc.die_contact.candidates();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const int node = candidates[i].node;
      const double p = disc.die_contact.pressure(int(i), state.unknowns.nodal);
      contact_status.values[node] = p > 0.0 ? 2.0 : 1.0;
      contact_pressure.values[node] = p;
      gap.values[node] = std::max(candidates[i].gap, 0.0);
    }
  }
  Field stress{"stress", 6, {}}, rate{elastic ? "equivalent_strain" : "equivalent_strain_rate", 1, {}},
      strain{"equivalent_strain", 1, {}}, body_id{"body_id", 1, {}}, quality{"element_quality", 1, {}};
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const material::Vec6 s = material::to_components(fields.stress[e]);
    stress.values.insert(stress.values.end(), s.data(), s.data() + 6);
    rate.values.push_back(fields.rate[e]);
    strain.values.push_back(state.equivalent_strain[e]);
    body_id.values.push_back(0.0);
    quality.values.push_back(mesh::quality(mesh, e));
  }
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    std::fill_n(body_id.values.begin() + state.bodies[b].first_tet, state.bodies[b].tet_count, double(b));
  std::vector<Field> cell_fields{stress, rate, body_id, quality};
  if (!elastic && scene.input.time.enabled) cell_fields.push_back(strain);
  for (std::size_t k = 0; k < state.damage.size(); ++k)
    cell_fields.push_back({"damage_" + material::to_string(scene.input.damage[k].criterion), 1, state.damage[k]});
  // Von Mises stress: what a die designer reads off a deformable die.
  Field von_mises{"von_mises_stress", 1, {}};
  for (const material::Vec6& sigma : fields.stress)
    von_mises.values.push_back(material::von_mises(sigma));
  cell_fields.push_back(von_mises);
  std::vector<Field> point_fields{velocity, pressure};
  if (scene.has_contact()) point_fields.insert(point_fields.end(), {contact_status, contact_pressure, gap});
  if (!state.temperature.empty()) point_fields.push_back({"temperature", 1, state.temperature});
  if (std::any_of(state.body_wear.begin(), state.body_wear.end(), [](const auto& w) { return !w.empty(); })) {
    Field wear{"wear", 1, std::vector<double>(mesh.nodes.size(), 0.0)}; // meshed dies' wear, 0 elsewhere
    for (std::size_t b = 0; b < state.body_wear.size(); ++b)
      std::copy(state.body_wear[b].begin(), state.body_wear[b].end(), wear.values.begin() + state.bodies[b].first_node);
    point_fields.push_back(std::move(wear));
  }
  // Folds: 1 on the nodes of the faces where a body's surface meets itself.
  if (scene.input.detect_folds && scene.input.time.enabled) {
    Field fold{"fold", 1, std::vector<double>(mesh.nodes.size(), 0.0)};
    const contact::FoldScan scan = contact::find_folds(mesh, state.bodies, disc.symmetry_faces, scene.reference_length);
    for (std::size_t f = 0; f < scan.faces.size(); ++f)
      if (scan.faces[f])
        for (const int n : mesh.boundary_faces[f])
          fold.values[n] = 1.0;
    point_fields.push_back(std::move(fold));
  }
  // Flow lines: the coordinate along the planes' normal where each node's
  // material started, and the planes' levels (docs/reading-a-run.md §4).
  std::vector<Field> field_data;
  if (const int axis = scene.input.flow_line_axis; axis >= 0) {
    Field started{std::string("material_") + char('x' + axis), 1, {}};
    for (int i = 0; i < mesh.node_count(); ++i)
      started.values.push_back(state.material_position[3 * i + axis]);
    point_fields.push_back(std::move(started));
    field_data.push_back({"flow_line_levels", 1, scene.flow_line_levels});
  }
  std::string names = scene.bodies.front().name;
  for (std::size_t b = 1; b < scene.bodies.size(); ++b)
    names += "+" + scene.bodies[b].name;
  series_.write(state.increment, state.time, 0, names, mesh, point_fields, cell_fields, field_data);
  std::vector<std::optional<contact::DieFill>> fills = scene::die_fills(scene, mesh, state.dies, true);
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const die::SurfaceTriangles& t = scene.dies[d].shown();
    std::vector<mesh::Point> moved = t.vertices;
    for (auto& p : moved)
      p += state.dies[d].displacement;
    std::vector<Field> die_fields;
    if (fills[d]) die_fields.push_back({"underfill", 1, std::move(fills[d]->underfill)});
    if (scene.dies[d].wear) die_fields.push_back({"wear", 1, state.wear[d]});
    series_.write_surface(state.increment, state.time, int(d) + 1, scene.dies[d].name, moved, t.faces, die_fields);
  }
}

void RunWriter::write_interface(const scene::Scene& scene, const scene::Discretisation& disc,
                                const scene::RunState& state) const {
  // Per interface node of either body, whatever the formulation: its
  // tributary area, its signed distance to the other body (< 0 penetrating)
  // and the rate at which it opens (< 0 closing), the normal stress it
  // transmits (its nodal contact force over its tributary area, N/mm² = MPa)
  // and its velocity. The nodes are found by projecting both sides (a
  // symmetric search, for output only: master/slave itself never looks at
  // master nodes, and that is where its errors show). The reach is the
  // solver's own floor (0.05 of an edge): a node pressed deeper than a hair
  // into a soft body is still on the interface.
  const Eigen::VectorXd& nodal = state.unknowns.nodal;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(nodal.size());
  disc.pair_contact->add(nodal, force, nullptr); // residual = minus the force on the body
  std::vector<contact::BodyPair> both_sides = disc.pair_contact->pairs();
  for (contact::BodyPair& pair : both_sides)
    pair.method = {contact::PairFormulation::symmetric, contact::PairIntegration::nodal};
  contact::BodyContact probe(both_sides, disc.pair_contact->symmetry_faces());
  probe.search(state.mesh, 0.05 * scene.reference_length);
  std::ostringstream csv;
  csv.precision(10);
  csv << "pair,body,node,x_mm,y_mm,z_mm,area_mm2,gap_mm,gap_rate_mm_s,normal_stress_MPa,vx,vy,vz\n";
  for (const contact::ContactPoint& p : probe.projected_nodes()) {
    const scene::ContactPairSpec& pair = scene.input.contact_pairs[p.pair];
    const int body = p.on_slave ? pair.slave : pair.master;
    // The contact force pushes the node away from the facet it projects onto: along +n.
    const double stress = -force.segment<3>(4 * p.node()).dot(p.normal) / p.area;
    const mesh::Point& x = state.mesh.nodes[p.node()];
    csv << probe.pairs()[p.pair].name << "," << scene.bodies[body].name << ","
        << p.node() - state.bodies[body].first_node + 1 << "," << x.x() << "," << x.y() << "," << x.z() << "," << p.area
        << "," << p.gap << "," << contact::relative_velocity(p, nodal).dot(p.normal) << "," << stress << ","
        << nodal[4 * p.node()] << "," << nodal[4 * p.node() + 1] << "," << nodal[4 * p.node() + 2] << "\n";
  }
  write_file_atomically(directory_ + "/interface.csv", csv.str());
}

void RunWriter::write_summary(const scene::Scene& scene, const scene::Discretisation& disc,
                              const scene::RunState& state, const solver::NewtonReport& last, const Timers& timers,
                              double total) const {
  const double volume_end = mesh::volume(state.mesh);
  const double inside_dies = std::accumulate(state.inside_dies.begin(), state.inside_dies.end(), 0.0);
  const double initial = state.volume.initial;
  JsonWriter json;
  json.begin_object()
      .member("case", scene.input.path)
      .member("title", scene.input.title)
      .member("anvil_version", ANVIL_VERSION)
      .key("bodies")
      .begin_array();
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const mesh::MeshRange& range = state.bodies[b];
    json.begin_object()
        .member("name", scene.bodies[b].name)
        .member("nodes", range.node_count)
        .member("elements", range.tet_count)
        .member("volume_mm3", mesh::volume(state.mesh, range));
    if (!state.temperature.empty()) {
      const auto first = state.temperature.begin() + range.first_node;
      const auto [low, high] = std::minmax_element(first, first + range.node_count);
      json.member("temperature_min_C", *low).member("temperature_max_C", *high);
    }
    json.end_object();
  }
  json.end_array();
  std::vector<int> newton, krylov;
  for (const auto& i : state.iterations)
    newton.push_back(i[0]), krylov.push_back(i[1]);
  json.member("unknowns", disc.solver->free_count())
      .member("increments", state.increment)
      .member("time_s", state.time)
      .member("newton_iterations", state.newton_iterations)
      .member("linear_solver", solver::to_string(disc.solver->linear_solver().kind()))
      .member("krylov_iterations", std::accumulate(krylov.begin(), krylov.end(), 0L))
      .key("iterations_per_increment")
      .begin_object()
      .array("newton", newton)
      .array("krylov", krylov)
      .end_object();
  if (!last.iterations.empty())
    json.key("final_residual")
        .begin_object()
        .member("force", last.iterations.back().force_residual)
        .member("div", last.iterations.back().flux_residual)
        .end_object();
  json.key("volume_mm3")
      .begin_object()
      .member("start", initial)
      .member("end", volume_end)
      .member("change_solver", state.volume.solver)
      .member("of_which_compensation", state.volume.compensation)
      .member("change_contact_projection", state.volume.projection)
      .member("change_remeshing", state.volume.remeshing)
      .member("largest_relative_change_per_increment", state.volume.largest_increment)
      .member("relative_change", initial > 0 ? volume_end / initial - 1.0 : 0.0)
      .member("inside_dies_end", inside_dies)
      .member("material_relative_change", initial > 0 ? (volume_end - inside_dies) / initial - 1.0 : 0.0)
      .end_object();
  if (!state.temperature.empty()) {
    // The bodies' heat balance (mJ); the imbalance relative to the largest line.
    const scene::HeatBudget& h = state.heat;
    const double largest = std::max({std::abs(h.plastic), std::abs(h.friction), std::abs(h.to_dies),
                                     std::abs(h.to_environment), std::abs(h.stored)});
    const auto [low, high] = std::minmax_element(state.temperature.begin(), state.temperature.end());
    const double end_heat =
        thermal::stored_heat(state.mesh, mesh::whole_range(state.mesh), disc.heat->materials(), state.temperature);
    json.key("heat_mJ")
        .begin_object()
        .member("plastic_work_heat", h.plastic)
        .member("friction_heat", h.friction)
        .member("to_dies", h.to_dies)
        .member("to_environment", h.to_environment)
        .member("stored_change", h.stored)
        .member("imbalance", h.imbalance())
        .member("relative_imbalance", largest > 0.0 ? h.imbalance() / largest : 0.0)
        .member("stored_change_by_remeshing", h.remeshing)
        .member("stored_heat_start", h.initial_heat)
        .member("stored_heat_end", end_heat)
        // What the steps' balance does not see: the heat the bodies' change
        // of volume (volume compensation, contact projection) carries.
        .member("stored_change_by_volume", end_heat - h.initial_heat - h.stored - h.remeshing)
        .member("transfer_time_s", state.transfer_time)
        .member("temperature_min_C", *low)
        .member("temperature_max_C", *high)
        .end_object();
  }
  if (scene.input.remeshing.enabled) {
    double seconds = 0.0;
    for (const scene::RemeshRecord& r : state.remeshes)
      seconds += r.seconds;
    json.key("remeshing")
        .begin_object()
        .member("count", static_cast<long>(state.remeshes.size()))
        .member("seconds", seconds);
    json.key("remeshes").begin_array();
    for (const scene::RemeshRecord& r : state.remeshes) {
      json.begin_object()
          .member("increment", r.increment)
          .member("body", scene.bodies[r.body].name)
          .member("nodes_before", r.nodes_before)
          .member("nodes_after", r.nodes_after)
          .member("worst_quality_before", r.worst_quality_before)
          .member("worst_quality_after", r.worst_quality_after)
          .member("volume_change", r.volume_change)
          .member("strain_integral_change", r.strain_integral_change)
          .member("strain_max_change", r.strain_max_change)
          .member("seconds", r.seconds);
      if (!std::isnan(r.material_change)) json.member("material_change", r.material_change);
      if (!std::isnan(r.die_depth_after)) json.member("die_depth_after_mm", r.die_depth_after);
      if (!std::isnan(r.die_overlap_after)) json.member("die_overlap_after_mm3", r.die_overlap_after);
      if (!std::isnan(r.rebuilt_share)) json.member("rebuilt_share", r.rebuilt_share);
      if (!std::isnan(r.load_old_mesh) && !std::isnan(r.load_new_mesh))
        json.member("load_old_mesh_N", r.load_old_mesh)
            .member("load_new_mesh_N", r.load_new_mesh)
            .member("load_jump", r.load_jump());
      json.end_object();
    }
    json.end_array().end_object();
  }
  // Die fill at the final geometry: the model's areas, and the whole part's
  // (a symmetry model's die is that share of the whole die).
  const std::vector<std::optional<contact::DieFill>> fills = scene::die_fills(scene, state.mesh, state.dies, false);
  json.key("dies").begin_array();
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    json.begin_object().member("name", scene.dies[d].name).member("stroke_mm", state.dies[d].stroke);
    if (fills[d])
      json.key("fill")
          .begin_object()
          .member("fill", fills[d]->fraction())
          .member("contact_area_whole_part_mm2", scene.symmetry_copies * fills[d]->contact_area)
          .member("region_area_whole_part_mm2", scene.symmetry_copies * fills[d]->region_area)
          .member("contact_area_model_mm2", fills[d]->contact_area)
          .member("region_area_model_mm2", fills[d]->region_area)
          .member("tolerance_mm", scene::fill_tolerance(scene, int(d)))
          .end_object();
    json.end_object();
  }
  // The press load (along z) of each load surface, of the whole part and of
  // the model (a symmetry model's share): its peak and its last value.
  json.end_array().member("model", scene.model_text()).member("symmetry_copies", scene.symmetry_copies);
  if (scene.input.detect_folds) {
    // Each fold: the increment after which it was first found, where it was
    // last found and the largest area it covered (both sides).
    json.key("folds").begin_array();
    for (const scene::FoldRecord& f : state.folds)
      json.begin_object()
          .member("increment", f.increment)
          .member("body", scene.bodies[f.body].name)
          .array("centre_mm", std::vector<double>{f.centre.x(), f.centre.y(), f.centre.z()})
          .member("area_model_mm2", f.area)
          .end_object();
    json.end_array();
  }
  if (std::any_of(scene.input.dies.begin(), scene.input.dies.end(), [](const auto& d) { return d.wear.enabled; }) ||
      std::any_of(scene.input.bodies.begin(), scene.input.bodies.end(), [](const auto& b) { return b.wear.enabled; })) {
    // Each worn die's largest wear and where it sits: a rigid die's vertex in
    // its start position (its STL's coordinates plus its offset), a meshed
    // die's node where it is now.
    json.key("wear").begin_array();
    const auto peak = [&](const std::string& die, const std::vector<double>& w, const mesh::Point& at_vertex,
                          std::size_t at) {
      json.begin_object()
          .member("die", die)
          .member("max_mm", w[at])
          .array("at_mm", std::vector<double>{at_vertex.x(), at_vertex.y(), at_vertex.z()})
          .end_object();
    };
    for (std::size_t d = 0; d < scene.dies.size(); ++d)
      if (scene.dies[d].wear) {
        const std::vector<double>& w = state.wear[d];
        const std::size_t at = std::max_element(w.begin(), w.end()) - w.begin();
        peak(scene.dies[d].name, w, scene.dies[d].shown().vertices[at], at);
      }
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      if (scene.bodies[b].wear) {
        const std::vector<double>& w = state.body_wear[b];
        const std::size_t at = std::max_element(w.begin(), w.end()) - w.begin();
        peak(scene.bodies[b].name, w, state.mesh.nodes[state.bodies[b].first_node + at], at);
      }
    json.end_array();
  }
  if (!state.blows.empty()) {
    // Each blow of an energy press: its energy, the work it did on the whole
    // part (their difference is the blow's energy balance), stroke and peak load.
    json.key("blows").begin_array();
    for (const scene::BlowRecord& b : state.blows)
      json.begin_object()
          .member("die", scene.dies[b.die].name)
          .member("blow", b.blow)
          .array("increments", std::vector<int>{b.first_increment, b.last_increment})
          .member("start_s", b.start_time)
          .member("end_s", b.end_time)
          .member("energy_kJ", b.energy * 1e-6)
          .member("work_kJ", b.work * 1e-6)
          .member("energy_left_kJ", b.energy_left() * 1e-6)
          .member("stroke_mm", b.stroke)
          .member("peak_load_N", b.peak_load)
          .member("over", b.over)
          .end_object();
    json.end_array();
  }
  if (!state.damage.empty()) {
    // Each criterion's largest D and the centroid of the element holding it.
    json.key("damage").begin_array();
    for (std::size_t k = 0; k < state.damage.size(); ++k) {
      const scene::DamagePeak peak = scene::damage_peak(state, k);
      json.begin_object()
          .member("criterion", material::to_string(scene.input.damage[k].criterion))
          .member("max", peak.value)
          .member("body", scene.bodies[peak.body].name)
          .array("at_mm", std::vector<double>{peak.position.x(), peak.position.y(), peak.position.z()})
          .end_object();
    }
    json.end_array();
  }
  json.key("press_loads_N").begin_array();
  for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
    double peak = 0.0, last_load = 0.0;
    double work = 0.0, stroke = 0.0; // N mm: trapezoids of the load-stroke curve from rest
    for (const scene::LoadRecord& r : state.loads)
      if (r.surface == static_cast<int>(s)) {
        work += 0.5 * (r.press_load() + last_load) * (r.stroke - stroke);
        peak = std::max(peak, r.press_load()), last_load = r.press_load(), stroke = r.stroke;
      }
    json.begin_object()
        .member("surface", scene.surfaces[s].name)
        .member("peak_whole_part", scene.symmetry_copies * peak)
        .member("last_whole_part", scene.symmetry_copies * last_load)
        .member("work_whole_part_J", 1e-3 * scene.symmetry_copies * work)
        .member("peak_model", peak)
        .member("last_model", last_load)
        .end_object();
  }
  json.end_array().key("effects").begin_array();
  for (const std::string& effect : scene.effects)
    json.value(effect);
  json.end_array().key("wall_time_s").begin_object();
  for (const auto& [phase, seconds] : timers.all())
    json.member(phase, seconds);
  json.member("total", total).end_object().end_object();
  write_file_atomically(directory_ + "/summary.json", json.str());
}

} // namespace anvil::io
