#include "anvil/scene/Scene.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/die/overlap_volume.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/mesh_io.h"
#include "anvil/mesh/node_budget.h"
#include "anvil/scene/MaterialCard.h"
#include "anvil/scene/effects.h"
#include "anvil/scene/fingerprint.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace anvil::scene {
namespace {

/// Nodes the generated shape of `spec` will have, counted before it is built.
double generated_nodes(const MeshSpec& spec) {
  if (spec.generate == "box") return mesh::box_node_count(spec.size, spec.element_size);
  if (spec.generate == "cylinder") return mesh::cylinder_node_count(spec.radius, spec.height, spec.element_size);
  if (spec.generate == "quarter_cylinder")
    return mesh::quarter_cylinder_node_count(spec.radius, spec.height, spec.element_size);
  return mesh::quarter_ring_node_count(spec.radius, spec.inner_radius, spec.height, spec.element_size);
}

mesh::TetMesh build_mesh(const MeshSpec& spec, const std::string& key) {
  if (!spec.file.empty()) return mesh::read_mesh(spec.file);
  mesh::check_node_budget(generated_nodes(spec), spec.source + ": key '" + key + ".element_size' " +
                                                     std::to_string(spec.element_size) + " mm");
  mesh::TetMesh m = spec.generate == "box"        ? mesh::make_box(spec.origin, spec.size, spec.element_size)
                    : spec.generate == "cylinder" ? mesh::make_cylinder(spec.radius, spec.height, spec.element_size)
                    : spec.generate == "quarter_cylinder"
                        ? mesh::make_quarter_cylinder(spec.radius, spec.height, spec.element_size)
                        : mesh::make_quarter_ring(spec.radius, spec.inner_radius, spec.height, spec.element_size);
  mesh::validate(m, spec.source + " (generated " + spec.generate + ")");
  return m;
}

double mean_boundary_edge(const mesh::TetMesh& mesh) {
  double sum = 0.0;
  for (const mesh::Triangle& f : mesh.boundary_faces)
    for (int k = 0; k < 3; ++k)
      sum += (mesh.nodes[f[k]] - mesh.nodes[f[(k + 1) % 3]]).norm();
  return sum / (3.0 * static_cast<double>(mesh.boundary_faces.size()));
}

/// Vertical distance (mm) between the two dies at zero displacement: lowest
/// point of the upper die above the highest point of the lower one.
double initial_die_gap(const std::vector<Die>& dies, int& upper) {
  auto z_range = [](const Die& d) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const mesh::Point& p : d.surface->triangles().vertices)
      low = std::min(low, p.z()), high = std::max(high, p.z());
    return std::pair{low, high};
  };
  const auto a = z_range(dies[0]), b = z_range(dies[1]);
  upper = a.first + a.second > b.first + b.second ? 0 : 1;
  return upper == 0 ? a.first - b.second : b.first - a.second;
}

/// Refuses stop criteria that the dies' motion can never meet, and a stroke
/// increment so small that the stop is out of time.max_increments' reach.
/// Exact for dies at rest or at constant velocity (constant, hydraulic: a
/// load limit only slows them); table and crank motions are not judged.
void check_stops_reachable(const Scene& scene) {
  const Case& c = scene.input;
  const TimeSpec& t = c.time;
  const auto judged = [&](int d) {
    return c.dies[d].motion == "fixed" || c.dies[d].motion == "constant" || c.dies[d].motion == "hydraulic";
  };
  const auto velocity = [&](int d) { return scene.dies[d].velocity(DieState{}, 1.0); };
  const double nominal = t.stroke_increment / scene.reference_velocity; // s an increment at the start
  const auto check_count = [&](double seconds, const std::string& what) {
    const double needed = seconds / nominal;
    if (t.max_increments_given || needed <= t.max_increments) return;
    char text[300];
    std::snprintf(text, sizeof text,
                  ": key 'time.stroke_increment' %g mm: reaching %s takes about %.3g increments, more than "
                  "time.max_increments (%d); is the stroke increment in mm?",
                  t.stroke_increment, what.c_str(), needed, t.max_increments);
    throw InputError(t.source + text);
  };
  if (std::isfinite(t.final_stroke) && judged(t.stroke_die)) {
    const double speed = velocity(t.stroke_die).norm();
    if (!(speed > 0.0))
      throw InputError(t.source + ": key 'time.stop.stroke': die '" + scene.dies[t.stroke_die].name +
                       "' does not move, its stroke stays 0 mm");
    check_count(t.final_stroke / speed, "the final stroke of " + std::to_string(t.final_stroke) + " mm");
    // Two flat dies facing each other along the press axis meet after a
    // known travel: a stroke at or past it can never be reached.
    const int other = 1 - t.stroke_die;
    const auto flat_along_z = [&](int d) {
      return c.dies[d].stl_file.empty() && std::abs(c.dies[d].plane_normal.normalized().z()) > 1.0 - 1e-9;
    };
    if (scene.dies.size() == 2 && judged(other) && flat_along_z(0) && flat_along_z(1)) {
      int upper = 0;
      const double gap = initial_die_gap(scene.dies, upper);
      const double closing = velocity(1 - upper).z() - velocity(upper).z();
      if (gap > 0.0 && closing > 0.0 && t.final_stroke >= speed * gap / closing) {
        char text[400];
        std::snprintf(text, sizeof text,
                      ": key 'time.stop.stroke': %g mm is never reached: die '%s' meets die '%s' after a stroke of "
                      "%.4g mm (the dies are %.4g mm apart at the start); give a stroke below that, or a gap stop",
                      t.final_stroke, scene.dies[t.stroke_die].name.c_str(), scene.dies[other].name.c_str(),
                      speed * gap / closing, gap);
        throw InputError(t.source + text);
      }
    }
  }
  if (t.final_gap > 0.0 && judged(scene.upper_die) && judged(1 - scene.upper_die)) {
    const double closing = velocity(1 - scene.upper_die).z() - velocity(scene.upper_die).z();
    char text[300];
    if (!(closing > 0.0)) {
      std::snprintf(text, sizeof text,
                    ": key 'time.stop.gap': %s (closing speed %g mm/s along z): the gap of %g mm is "
                    "never reached",
                    closing < 0.0 ? "the dies move apart" : "the dies do not close along z", closing, t.final_gap);
      throw InputError(t.source + text);
    }
    if (scene.die_gap0 > t.final_gap) check_count((scene.die_gap0 - t.final_gap) / closing, "the final die gap");
  }
  if (std::isfinite(t.max_load)) {
    // A load builds up when a die moves towards the bodies or a plate moves.
    mesh::Point centre = mesh::Point::Zero();
    for (const mesh::Point& x : scene.initial_mesh.nodes)
      centre += x / static_cast<double>(scene.initial_mesh.nodes.size());
    bool pressing = scene.surfaces.size() > scene.dies.size(); // a moving plate
    std::string away;
    for (std::size_t d = 0; d < scene.dies.size() && !pressing; ++d) {
      if (!judged(int(d))) pressing = true;
      const Eigen::Vector3d v = velocity(int(d));
      if (v.norm() == 0.0) continue;
      if (v.dot(centre - scene.dies[d].surface->project(centre).point) > 0.0)
        pressing = true;
      else
        away = scene.dies[d].name;
    }
    if (!pressing)
      throw InputError(t.source + ": key 'time.stop.load': no die moves towards the bodies" +
                       (away.empty() ? std::string() : " (die '" + away + "' moves away)") + ": no load builds up to " +
                       std::to_string(t.max_load) + " N");
  }
  if (std::isfinite(t.end_time)) check_count(t.end_time, "the end time");
}

/// Refuses a die that starts inside a body deeper than half the mean
/// boundary edge (faceting and placement leave less): the first increment
/// would push the body out by that much, or, with an open die surface whose
/// normals point into the body, crush it.
void check_dies_outside_bodies(const Scene& scene) {
  const double tolerance = 0.5 * scene.reference_length;
  const std::vector<char> boundary = mesh::boundary_node_flags(scene.initial_mesh);
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      const mesh::MeshRange& range = scene.initial_ranges[b];
      double depth = 0.0;
      int deepest = -1;
      for (int i = range.first_node; i < range.first_node + range.node_count; ++i) {
        if (!boundary[i]) continue;
        const die::SurfaceProjection p = scene.dies[d].surface->project(scene.initial_mesh.nodes[i]);
        if (p.on_facet && -p.distance > depth) depth = -p.distance, deepest = i;
      }
      if (depth <= tolerance) continue;
      const mesh::Point& x = scene.initial_mesh.nodes[deepest];
      char text[400];
      std::snprintf(text, sizeof text,
                    ": die '%s' starts %.4g mm inside body '%s' (node %d at (%.4g, %.4g, %.4g) mm), more than half "
                    "the mean boundary edge (%.3g mm): move the die (plane.point or offset); an open STL surface "
                    "whose normals point into the body reads this way too",
                    scene.dies[d].name.c_str(), depth, scene.bodies[b].name.c_str(), deepest - range.first_node + 1,
                    x.x(), x.y(), x.z(), tolerance);
      throw InputError(scene.input.dies[d].source + text);
    }
}

} // namespace

Scene::Scene(const Case& c, Timers& timers, const RunState* carried) : input(c) {
  // The bodies are solved as one mesh of disjoint parts, each element with its body's law.
  std::array<bool, 2> symmetric_about = {false, false}; // symmetry planes normal to x, y
  // A chain's part keeps the volume the chain started with (less what a
  // trim cut off): what the operations before lost, compensation restores.
  const double kept_share = carried ? carried->volume.initial / mesh::volume(carried->mesh) : 1.0;
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const BodySpec& spec = c.bodies[b];
    MaterialCard card = read_material(spec.material_file);
    Body body;
    body.name = spec.name;
    body.material_file = spec.material_file;
    body.law = std::move(card.law);
    body.state.temperature = spec.temperature.value_or(card.temperature.value_or(20.0));
    if (spec.wear.enabled) {
      if (!body.law->is_elastic())
        throw InputError(spec.source + ": key 'bodies[" + std::to_string(b) +
                         "].wear': only a meshed (elastic) die wears; a flowing body is the part");
      body.wear = spec.wear.law;
      if (!(spec.wear.law.hardness > 0.0)) {
        if (!card.hardness)
          throw InputError(spec.source + ": key 'bodies[" + std::to_string(b) + "].wear': '" + spec.material_file +
                           "' has no hardness table ('hardness', HRC): give 'wear.hardness'");
        body.hardness = card.hardness;
        body.wear_temperature = spec.wear.temperature;
      }
    }
    if (c.thermal.enabled)
      body.thermal = card.thermal;
    else if (const auto* law = dynamic_cast<const material::NortonHoff*>(body.law.get());
             law && law->depends_on_temperature())
      // T is a constant of an isothermal scene: so is K(T).
      body.law = std::make_unique<material::NortonHoff>(law->at_temperature(body.state.temperature));
    const mesh::TetMesh part = carried ? mesh::extract(carried->mesh, carried->bodies[b])
                                       : build_mesh(spec.mesh, "bodies[" + std::to_string(b) + "].mesh");
    for (std::size_t i = 0; i < c.boundary.size(); ++i)
      if (c.boundary_body[i] == static_cast<int>(b)) body.conditions.push_back(c.boundary[i]);
    conditions.insert(conditions.end(), body.conditions.begin(), body.conditions.end());
    {
      Timers::Scope scope(timers, "effect boundary_conditions");
      body.initial_imposed = impose(part, body.conditions);
    }
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // of the nodes: which side of a plane the body is on
    for (const mesh::Point& x : part.nodes)
      centre += x / part.node_count();
    std::array<bool, 3> symmetry_normal = {false, false, false};
    bool held = false; // a face of prescribed velocity holds every rotation
    for (std::size_t i = 0; i < body.conditions.size(); ++i) {
      const BoundaryCondition& bc = body.conditions[i];
      held = held || ((bc.kind == BoundaryKind::velocity || bc.kind == BoundaryKind::sticking_plate) &&
                      std::all_of(bc.velocity.begin(), bc.velocity.end(), [](const auto& v) { return v.has_value(); }));
      const int axis = body.initial_imposed.symmetry_axis[i];
      if (axis < 0) continue;
      symmetry_normal[axis] = true;
      if (axis == 0 || axis == 1) symmetric_about[axis] = true;
      const double plane = part.nodes[body.initial_imposed.nodes_of_condition[i].front()][axis];
      if (centre[axis] > plane)
        model_side.min()[axis] = plane;
      else
        model_side.max()[axis] = plane;
    }
    // Two symmetry planes of other normals hold every rotation; one leaves
    // the rotation about its normal.
    free_rotations = free_rotations || (!held && std::count(symmetry_normal.begin(), symmetry_normal.end(), true) < 2);
    body.initial_volume = mesh::volume(part) * kept_share;
    body.remesh_size = c.remeshing.element_size > 0.0 ? c.remeshing.element_size : mean_boundary_edge(part);
    if (c.remeshing.enabled && c.remeshing.element_size > 0.0) {
      // Fewer than three elements across would remesh the body into a few
      // tetrahedra and lose its shape.
      const double thinnest = mesh::bounding_box(part).sizes().minCoeff();
      if (c.remeshing.element_size > thinnest / 3.0) {
        char text[300];
        std::snprintf(text, sizeof text,
                      ": key 'remeshing.element_size' %g mm: more than a third of the smallest extent of body '%s' "
                      "(%g mm): a remesh would leave fewer than three elements across it",
                      c.remeshing.element_size, body.name.c_str(), thinnest);
        throw InputError(c.path + text);
      }
    }
    if (c.remeshing.enabled)
      mesh::check_node_budget(mesh::remeshed_nodes(body.initial_volume, mesh::boundary_area(part), body.remesh_size),
                              c.path + ": key 'remeshing.element_size' " + std::to_string(body.remesh_size) +
                                  " mm, remeshing body '" + body.name + "'");
    initial_ranges.push_back(mesh::append(initial_mesh, part));
    bodies.push_back(std::move(body));
  }
  symmetry_copies = (symmetric_about[0] ? 2 : 1) * (symmetric_about[1] ? 2 : 1);
  if (const int axis = c.flow_line_axis; axis >= 0) {
    // Planes of the material where it was at the start (of the chain).
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t n = 0; n < initial_mesh.nodes.size(); ++n) {
      const double x = carried ? carried->material_position[3 * n + axis] : initial_mesh.nodes[n][axis];
      low = std::min(low, x), high = std::max(high, x);
    }
    for (int k = 0; k < c.flow_line_count; ++k)
      flow_line_levels.push_back(low + (k + 0.5) * (high - low) / c.flow_line_count);
  }
  std::vector<const material::Material*> laws;
  for (const Body& body : bodies)
    laws.push_back(body.law.get());
  all_elastic = std::all_of(laws.begin(), laws.end(), [](const material::Material* l) { return l->is_elastic(); });
  solve_displacement = !c.time.enabled && all_elastic;
  for (Body& body : bodies)
    body.velocity_form = body.law->is_elastic() && !solve_displacement;
  carries_stress = std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.velocity_form; });
  thermal = std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.thermal.has_value(); });
  if (c.thermal.enabled && !thermal)
    throw InputError(c.thermal.source + ": key 'thermal': no body's material card gives thermal properties "
                                        "(conductivity, specific_heat, density): nothing to solve for heat");
  effects = resolve_effects(c, laws);
  compensate_volume = std::find(effects.begin(), effects.end(), "volume_compensation") != effects.end();

  // Scales from the initial mesh, so that a resumed run uses the very same numbers.
  body_size = mesh::bounding_box(initial_mesh).diagonal().norm();
  reference_length = mean_boundary_edge(initial_mesh);
  const bool drawn = carried && carried->die_extent > 0.0;
  die_extent = drawn ? carried->die_extent : body_size;
  die_sampling = drawn ? carried->die_sampling : reference_length; // a worn die: a sample per boundary edge
  {
    Timers::Scope scope(timers, "effect rigid_dies (setup)");
    for (const DieSpec& spec : c.dies) {
      dies.push_back(build_die(spec, die_extent, die_sampling));
      // Pieces of at most ¾ of an edge: each sample stands for points less
      // than half an edge away, about the mesh's own resolution.
      if (spec.fill)
        dies.back().fill_samples =
            contact::fill_samples(dies.back().shown(), spec.fill_region, 0.75 * reference_length);
    }
  }
  for (std::size_t d = 0; d < dies.size(); ++d)
    surfaces.push_back({dies[d].name, int(d), -1});
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i].prescribes_velocity() && conditions[i].kind != BoundaryKind::symmetry)
      surfaces.push_back({conditions[i].name, -1, int(i)});
  if (c.time.final_gap > 0.0) die_gap0 = initial_die_gap(dies, upper_die);

  // Speed at t = 0 over a short probe step (an increment is far longer).
  const double probe = 1e-3 * std::max(c.time.stroke_increment, 1e-6);
  for (const Die& d : dies)
    reference_velocity = std::max(reference_velocity, d.velocity(DieState{}, probe).norm());
  for (const Body& body : bodies) {
    const ImposedConditions& imposed = body.initial_imposed;
    for (int k = 0; k < imposed.values.size(); ++k)
      if (imposed.prescribed[k] && k % 4 != 3)
        reference_velocity = std::max(reference_velocity, std::abs(imposed.values[k]));
  }
  heat_only = c.time.enabled && !(reference_velocity > 0.0);
  if (heat_only) {
    effects = heat_alone_effects(effects);
    compensate_volume = false;
    if (!thermal)
      throw InputError(c.path + ": nothing moves at t = 0 (no moving die, no prescribed velocity): the time loop "
                                "needs a motion, or a 'thermal' section to solve heat alone (cooling, dwell)");
    const bool cools_to = std::isfinite(c.time.stop_temperature);
    if (!(std::isfinite(c.time.end_time) || cools_to) || std::isfinite(c.time.final_stroke) || c.time.final_gap > 0.0 ||
        std::isfinite(c.time.max_load))
      throw InputError(c.time.source + ": key 'time.stop': nothing moves (heat alone): the run stops at an end "
                                       "time or a temperature, 'time: ...' or 'temperature: ...' and nothing else");
    if (!std::isfinite(c.time.end_time) && !(c.time.heat_step > 0.0))
      throw InputError(c.time.source + ": missing key 'time.heat_step': cooling to a temperature without an end "
                                       "time needs the length of its heat steps (s)");
  } else if (std::isfinite(c.time.stop_temperature)) {
    throw InputError(c.time.source + ": key 'time.stop.temperature': only for heat alone (nothing moves)");
  } else if (c.time.enabled && !(c.time.stroke_increment > 0.0)) {
    throw InputError(c.time.source + ": missing key 'time.stroke_increment': the travel of the fastest die per "
                                     "increment (mm)");
  }
  if (c.time.enabled && !heat_only) check_stops_reachable(*this);
  check_dies_outside_bodies(*this);
  fingerprint = case_fingerprint(c);
}

std::string Scene::model_text() const {
  if (symmetry_copies == 1) return "whole part";
  return std::string(symmetry_copies == 4 ? "quarter model (symmetry planes normal to x and y)"
                                          : "half model (a symmetry plane containing the press axis)") +
         ": the whole part's press load is " + std::to_string(symmetry_copies) + " x the model's";
}

double Scene::die_gap(std::span<const DieState> dies_now) const {
  return die_gap0 + dies_now[upper_die].displacement.z() - dies_now[1 - upper_die].displacement.z();
}

RunState initial_state(const Scene& scene, const RunState* part) {
  RunState state;
  state.mesh = scene.initial_mesh;
  state.bodies = scene.initial_ranges;
  state.unknowns = {Eigen::VectorXd::Zero(4 * state.mesh.node_count()),
                    Eigen::VectorXd::Zero(3 * state.mesh.tet_count())};
  state.equivalent_strain.assign(state.mesh.tets.size(), 0.0);
  state.damage.assign(scene.input.damage.size(), std::vector<double>(state.mesh.tets.size(), 0.0));
  if (scene.carries_stress) state.elastic_stress.assign(6 * state.mesh.tets.size(), 0.0);
  state.dies.assign(scene.dies.size(), DieState{});
  state.body_wear.resize(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].wear) state.body_wear[b].assign(state.bodies[b].node_count, 0.0);
  state.wear.resize(scene.dies.size());
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].wear) state.wear[d].assign(scene.dies[d].shown().vertices.size(), 0.0);
  if (scene.thermal)
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      state.temperature.insert(state.temperature.end(), state.bodies[b].node_count, scene.bodies[b].state.temperature);
  if (scene.input.flow_line_axis >= 0)
    for (const mesh::Point& x : state.mesh.nodes)
      state.material_position.insert(state.material_position.end(), x.data(), x.data() + 3);
  if (part) {
    state.equivalent_strain = part->equivalent_strain;
    // The part's last flow: the first Newton guess, and the rates the
    // friction's flow stress is read at in the first increment (contact_scales).
    if (part->unknowns.nodal.size() == state.unknowns.nodal.size() &&
        part->unknowns.bubble.size() == state.unknowns.bubble.size())
      state.unknowns = part->unknowns;
    state.damage = part->damage;
    if (scene.carries_stress) state.elastic_stress = part->elastic_stress;
    if (scene.thermal) state.temperature = part->temperature;
    if (scene.input.flow_line_axis >= 0) state.material_position = part->material_position;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      if (scene.bodies[b].wear && b < part->body_wear.size() && !part->body_wear[b].empty())
        state.body_wear[b] = part->body_wear[b];
    // A die worn in an operation before (the chain gives its wear in this
    // scene's order) wears on.
    for (std::size_t d = 0; d < scene.dies.size(); ++d) {
      if (d >= part->wear.size() || part->wear[d].empty() || state.wear[d].empty()) continue;
      if (part->wear[d].size() == state.wear[d].size())
        state.wear[d] = part->wear[d];
      else
        log::info("die '%s': another surface than the one of that name before (%zu vertices, then %zu): its wear "
                  "starts from zero",
                  scene.dies[d].name.c_str(), part->wear[d].size(), state.wear[d].size());
    }
  }
  state.volume.initial = part ? part->volume.initial : mesh::volume(state.mesh);
  state.die_extent = scene.die_extent, state.die_sampling = scene.die_sampling;
  state.inside_dies = inside_dies(scene, state);
  return state;
}

void check_resumable(const Scene& scene, const RunState& state, const std::string& path) {
  if (state.dies.size() != scene.dies.size())
    throw InputError(path + ": checkpoint dataset 'dies' has " + std::to_string(state.dies.size()) +
                     " dies, the case " + std::to_string(scene.dies.size()));
  // Until a remesh the bodies keep the meshes the case builds.
  bool same_bodies = state.bodies.size() == scene.bodies.size();
  for (std::size_t b = 0; same_bodies && state.remeshes.empty() && b < scene.bodies.size(); ++b)
    same_bodies = state.bodies[b].node_count == scene.initial_ranges[b].node_count &&
                  state.bodies[b].tet_count == scene.initial_ranges[b].tet_count;
  if (!same_bodies)
    throw InputError(path + ": checkpoint dataset 'body_ranges': the bodies do not match the case's (was the case "
                            "changed?)");
  if (scene.thermal == state.temperature.empty())
    throw InputError(path + (scene.thermal ? ": the case is thermal, the checkpoint holds no temperatures"
                                           : ": the checkpoint holds temperatures, the case has no 'thermal' section"));
  if ((scene.input.flow_line_axis >= 0) == state.material_position.empty())
    throw InputError(path + (state.material_position.empty()
                                 ? ": the case asks for flow lines, the checkpoint holds no material positions"
                                 : ": the checkpoint holds material positions, the case asks for no flow lines"));
  if (state.damage.size() != scene.input.damage.size())
    throw InputError(path + ": the checkpoint holds " + std::to_string(state.damage.size()) +
                     " damage criteria, the case asks for " + std::to_string(scene.input.damage.size()) +
                     " (was the case's 'damage' section changed?)");
  if (scene.carries_stress != !state.elastic_stress.empty())
    throw InputError(path + ": checkpoint dataset 'elastic_stress' does not match the case's bodies (was the case "
                            "changed?)");
  for (std::size_t i = 0; i < state.loads.size(); ++i)
    if (state.loads[i].surface >= static_cast<int>(scene.surfaces.size()))
      throw InputError(path + ": checkpoint dataset 'loads', record " + std::to_string(i + 1) + ": surface " +
                       std::to_string(state.loads[i].surface) + " out of range (the case has " +
                       std::to_string(scene.surfaces.size()) + " load surfaces; damaged file)");
  for (std::size_t i = 0; i < state.outputs.size(); ++i)
    if (state.outputs[i].part > static_cast<int>(scene.dies.size()))
      throw InputError(path + ": checkpoint dataset 'outputs', record " + std::to_string(i + 1) + ": part " +
                       std::to_string(state.outputs[i].part) + " out of range (the bodies and " +
                       std::to_string(scene.dies.size()) + " dies; damaged file)");
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const std::size_t vertices = scene.dies[d].wear ? scene.dies[d].shown().vertices.size() : 0;
    if ((d < state.wear.size() ? state.wear[d].size() : 0) != vertices)
      throw InputError(path + ": the checkpoint's die wear of die '" + scene.dies[d].name +
                       "' does not match the case (was its 'wear' or its surface changed?)");
  }
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const std::size_t nodes =
        scene.bodies[b].wear && b < state.bodies.size() ? static_cast<std::size_t>(state.bodies[b].node_count) : 0;
    if ((b < state.body_wear.size() ? state.body_wear[b].size() : 0) != nodes)
      throw InputError(path + ": the checkpoint's wear of body '" + scene.bodies[b].name +
                       "' does not match the case (was its 'wear' changed?)");
  }
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].energy && std::none_of(state.blows.begin(), state.blows.end(),
                                             [&](const BlowRecord& b) { return b.die == static_cast<int>(d); }))
      throw InputError(path + ": the checkpoint has no blow of die '" + scene.dies[d].name +
                       "' (was its motion changed to a hammer or screw press?)");
  for (std::size_t i = 0; i < state.blows.size(); ++i)
    if (state.blows[i].die >= static_cast<int>(scene.dies.size()) || !scene.dies[state.blows[i].die].energy)
      throw InputError(path + ": checkpoint dataset 'blows', record " + std::to_string(i + 1) + ": die " +
                       std::to_string(state.blows[i].die) + " is no hammer or screw press of the case");
  for (std::size_t i = 0; i < state.folds.size(); ++i)
    if (state.folds[i].body >= static_cast<int>(scene.bodies.size()))
      throw InputError(path + ": checkpoint dataset 'folds', record " + std::to_string(i + 1) + ": body " +
                       std::to_string(state.folds[i].body) + " out of range (damaged file)");
  for (std::size_t i = 0; i < state.remeshes.size(); ++i)
    if (state.remeshes[i].body >= static_cast<int>(scene.bodies.size()))
      throw InputError(path + ": checkpoint dataset 'remeshes', record " + std::to_string(i + 1) + ": body " +
                       std::to_string(state.remeshes[i].body) + " out of range (damaged file)");
}

double inside_dies(const Scene& scene, const mesh::TetMesh& mesh, const mesh::MeshRange& range, int body,
                   std::span<const DieState> dies_now) {
  double inside = 0.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    inside += die::overlap_volume(mesh, range, *scene.dies[d].surface, dies_now[d].displacement,
                                  scene.bodies[body].remesh_size);
  return inside;
}

std::vector<double> inside_dies(const Scene& scene, const RunState& state) {
  std::vector<double> inside(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    inside[b] = inside_dies(scene, state.mesh, state.bodies[b], int(b), state.dies);
  return inside;
}

double fill_tolerance(const Scene& scene, int die) {
  // A tenth of an edge covers the chord of a facet over a die radius of
  // about an edge (sagitta h²/8R).
  const double given = scene.input.dies[die].fill_tolerance;
  return given > 0.0 ? given : 0.1 * scene.reference_length;
}

std::vector<std::optional<contact::DieFill>> die_fills(const Scene& scene, const mesh::TetMesh& mesh,
                                                       std::span<const DieState> dies_now, bool with_underfill) {
  std::vector<std::optional<contact::DieFill>> fills(scene.dies.size());
  const auto asks = [&](std::size_t d) { return scene.input.dies[d].fill; };
  bool any = false;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    any = any || asks(d);
  if (!any) return fills;
  const contact::PartSurface part(mesh);
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (asks(d))
      fills[d] = contact::measure_die_fill(scene.dies[d].fill_samples, scene.dies[d].shown(), dies_now[d].displacement,
                                           scene.model_side, part, fill_tolerance(scene, int(d)),
                                           0.5 * scene.reference_length, with_underfill);
  return fills;
}

} // namespace anvil::scene
