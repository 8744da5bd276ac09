#include "anvil/run/trim.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/Timers.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/io/JsonWriter.h"
#include "anvil/io/RunWriter.h"
#include "anvil/io/atomic_file.h"
#include "anvil/mesh/level_set_cut.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/Remesher.h"
#include "anvil/scene/Die.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/Scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numeric>
#include <span>

namespace anvil::run {
namespace {

/// An edge the cut crosses within this share of its length from one end
/// has that end put onto the cut: a split so near a node leaves a sliver.
constexpr double kSnapShare = 0.3;
/// The quality that move may take an element around the node down to, at
/// worst half of this (or of what it had, when less); and below which a
/// piece of the cut has its nodes put onto the cut in a second pass.
constexpr double kSnapFloor = 0.2;
/// Passes of that second chance.
constexpr int kSnapPasses = 3;
/// A node of the part's surface put onto the cut may change the volume of
/// its elements by at most this share (an interior node changes none).
constexpr double kShapeChange = 0.2;

/// The nearest point to `x` on segment [a, b] (in a plane).
Eigen::Vector2d nearest_on_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return a + t * ab;
}

/// The cut of a closed line in the plane normal to z, extruded along z.
Cut line_cut(const std::vector<Eigen::Vector2d>& line) {
  const auto nearest_xy = [line](const Eigen::Vector2d& x) {
    Eigen::Vector2d best = line.front();
    for (std::size_t i = 0; i < line.size(); ++i) {
      const Eigen::Vector2d p = nearest_on_segment(x, line[i], line[(i + 1) % line.size()]);
      if ((p - x).squaredNorm() < (best - x).squaredNorm()) best = p;
    }
    return best;
  };
  const auto inside = [line](const Eigen::Vector2d& x) { // crossing number
    bool in = false;
    for (std::size_t i = 0, j = line.size() - 1; i < line.size(); j = i++)
      if ((line[i].y() > x.y()) != (line[j].y() > x.y()) &&
          x.x() < line[j].x() + (x.y() - line[j].y()) * (line[i].x() - line[j].x()) / (line[i].y() - line[j].y()))
        in = !in;
    return in;
  };
  Cut cut;
  cut.distance = [=](const mesh::Point& x) {
    const double d = (nearest_xy(x.head<2>()) - x.head<2>()).norm();
    return inside(x.head<2>()) ? -d : d;
  };
  cut.nearest = [=](const mesh::Point& x) {
    const Eigen::Vector2d p = nearest_xy(x.head<2>());
    return mesh::Point(p.x(), p.y(), x.z());
  };
  return cut;
}

/// Mass (kg) of `volume` mm³ of body `b`, or NaN when its card gives no density.
double mass_of(const scene::Scene& scene, int b, double volume) {
  const auto& thermal = scene.bodies[b].thermal;
  return thermal ? 1e-9 * thermal->density * volume : std::numeric_limits<double>::quiet_NaN();
}

/// summary.json of a trim: each body's volume cut off and the change of
/// what it keeps by the nodes put onto the cut (`cut`) and by the remesh
/// along it (`remeshed_volume`), mm³, model.
void write_trim_summary(const std::string& directory, const scene::Scene& scene, const CutPart& cut,
                        const scene::RunState& after, const std::string& remeshed,
                        std::span<const double> remeshed_volume, double seconds) {
  const std::vector<double>& removed = cut.removed;
  io::JsonWriter json;
  json.begin_object()
      .member("case", scene.input.path)
      .member("operation", "trim")
      .member("increments", 0)
      .member("time_s", 0.0)
      .member("symmetry_copies", scene.symmetry_copies)
      .member("remesh", remeshed)
      .key("bodies")
      .begin_array();
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    json.begin_object()
        .member("name", scene.bodies[b].name)
        .member("nodes", after.bodies[b].node_count)
        .member("elements", after.bodies[b].tet_count)
        .member("volume_mm3", mesh::volume(after.mesh, after.bodies[b]))
        .member("removed_volume_model_mm3", removed[b])
        .member("reshaped_volume_model_mm3", cut.reshaped[b])
        .member("remeshed_volume_model_mm3", remeshed_volume[b])
        .member("removed_volume_whole_part_mm3", scene.symmetry_copies * removed[b]);
    if (const double mass = mass_of(scene, int(b), scene.symmetry_copies * removed[b]); !std::isnan(mass))
      json.member("removed_mass_whole_part_kg", mass);
    if (!after.temperature.empty()) {
      const auto first = after.temperature.begin() + after.bodies[b].first_node;
      const auto [low, high] = std::minmax_element(first, first + after.bodies[b].node_count);
      json.member("temperature_min_C", *low).member("temperature_max_C", *high);
    }
    json.end_object();
  }
  json.end_array().key("wall_time_s").begin_object().member("total", seconds).end_object().end_object();
  io::write_file_atomically(directory + "/summary.json", json.str());
}

} // namespace

Cut make_cut(const scene::TrimSpec& spec, const std::string& where, double size) {
  if (!spec.line.empty()) return line_cut(spec.line);
  scene::DieSpec surface;
  surface.name = "trim";
  surface.stl_file = spec.stl_file;
  surface.source = where;
  auto die = std::make_shared<scene::Die>(scene::build_die(surface, size, size));
  Cut cut;
  cut.distance = [die](const mesh::Point& x) { return die->surface->project(x).distance; };
  cut.nearest = [die](const mesh::Point& x) { return die->surface->project(x).point; };
  return cut;
}

CutPart cut_part(const scene::RunState& part, const Cut& cut, std::span<const SymmetryPlane> planes) {
  const mesh::TetMesh& m = part.mesh;
  mesh::TetMesh moved = m;
  std::vector<double> phi(m.nodes.size());
  const double on_cut = 1e-9 * mesh::bounding_box(m).diagonal().norm(); // mm: a node this near is on it
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    phi[n] = cut.distance(m.nodes[n]);
    if (std::abs(phi[n]) < on_cut) phi[n] = 0.0;
  }
  CutPart result;
  // The exact split, no node moved: the volume the cut takes off.
  for (std::size_t b = 0; b < part.bodies.size(); ++b) {
    const mesh::MeshRange& r = part.bodies[b];
    const double kept = mesh::volume(
        mesh::cut_by_level_set(mesh::extract(m, r), std::span<const double>(phi).subspan(r.first_node, r.node_count),
                               cut.distance)
            .mesh);
    result.removed.push_back(mesh::volume(m, r) - kept);
    result.reshaped.push_back(-kept); // the kept part's volume is added below
  }
  // An edge the cut crosses near one end would leave a sliver: that end is
  // put onto the cut instead, unless the move spoils an element around it
  // (φ is 1-Lipschitz: it moves by at most kSnapShare of the edge).
  std::vector<char> snap(m.nodes.size(), 0);
  for (const mesh::Tet& t : m.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const int a = t[i], b = t[j];
        if (phi[a] * phi[b] >= 0.0) continue;
        const double share = std::abs(phi[a]) / (std::abs(phi[a]) + std::abs(phi[b]));
        if (share < kSnapShare) snap[a] = 1;
        if (share > 1.0 - kSnapShare) snap[b] = 1;
      }
  // The move is judged on the elements around the node that keep a part
  // (a node inside the cut, or all on it): it may not leave one below half
  // the lower of kSnapFloor and the worst of them before (a split this near
  // the node would leave far worse).
  const std::vector<std::vector<int>> around = mesh::tets_around_nodes(m);
  const auto worst_kept = [&](std::size_t node) {
    double worst = 1.0;
    for (int e : around[node]) {
      const mesh::Tet& t = m.tets[e];
      const bool kept = std::any_of(t.begin(), t.end(), [&](int v) { return phi[v] < 0.0; }) ||
                        std::none_of(t.begin(), t.end(), [&](int v) { return phi[v] > 0.0; });
      if (kept) worst = std::min(worst, mesh::quality(moved, e));
    }
    return worst;
  };
  // The nodes of the part's own surface (faces not on a symmetry plane)
  // move along it: the alternating projections onto the cut and onto the
  // surface (and onto the symmetry planes a node is on) meet where they
  // cross. Its faces around the node follow only to their chords, and
  // more at an edge of the surface: kShapeChange bounds that.
  std::vector<char> on_surface(m.nodes.size(), 0);
  std::vector<mesh::Triangle> surface_faces;
  for (const mesh::Triangle& f : m.boundary_faces) {
    const bool symmetry = std::any_of(planes.begin(), planes.end(), [&](const SymmetryPlane& p) {
      return std::all_of(f.begin(), f.end(), [&](int v) { return std::abs(m.nodes[v][p.axis] - p.at) < on_cut; });
    });
    if (symmetry) continue;
    surface_faces.push_back(f);
    for (int v : f)
      on_surface[v] = 1;
  }
  const contact::SurfaceSearch surface(m.nodes, surface_faces);
  // Puts node n onto the cut unless an element around it that keeps a part
  // would end below `floor`, or the part's shape would change too much.
  const auto put_onto_cut = [&](std::size_t n, double floor) {
    std::vector<const SymmetryPlane*> on;
    for (const SymmetryPlane& p : planes)
      if (std::abs(m.nodes[n][p.axis] - p.at) < on_cut) on.push_back(&p);
    mesh::Point to = m.nodes[n];
    for (int pass = 0; pass < (on.empty() && !on_surface[n] ? 1 : 50); ++pass) {
      to = cut.nearest(to);
      if (on_surface[n]) to = surface.closest(to).point;
      for (const SymmetryPlane* p : on)
        to[p->axis] = p->at;
    }
    if (std::abs(cut.distance(to)) > 1e-6 * (to - m.nodes[n]).norm() + on_cut) return false; // they do not meet
    // Judged as it will be cut: the node on the cut (an element may then be
    // kept whole). A surface node may not change the part's volume by more
    // than kShapeChange of its elements' (an edge node moved off its edge).
    const mesh::Point was = moved.nodes[n];
    const double level = phi[n];
    double before = 0.0, after = 0.0;
    for (int e : around[n])
      before += mesh::signed_volume(moved, e);
    moved.nodes[n] = to;
    phi[n] = 0.0;
    for (int e : around[n])
      after += mesh::signed_volume(moved, e);
    if (std::abs(after - before) <= kShapeChange * before && worst_kept(n) >= floor) return true;
    moved.nodes[n] = was;
    phi[n] = level;
    return false;
  };
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (snap[n]) put_onto_cut(n, 0.5 * std::min(kSnapFloor, worst_kept(n)));
  // Each body cut on its own.
  std::vector<mesh::LevelSetCut> pieces(part.bodies.size());
  const auto cut_bodies = [&] {
    for (std::size_t b = 0; b < part.bodies.size(); ++b) {
      const mesh::MeshRange& r = part.bodies[b];
      pieces[b] = mesh::cut_by_level_set(
          mesh::extract(moved, r), std::span<const double>(phi).subspan(r.first_node, r.node_count), cut.distance);
      if (pieces[b].mesh.tets.empty())
        throw InputError("the trim cut removes the whole of body " + std::to_string(b + 1));
    }
  };
  cut_bodies();
  // A piece still below kSnapFloor (a split near a node whose move was
  // refused, or near an edge): each node of its element that an edge
  // across the cut leaves is put onto the cut when that leaves the elements
  // around it better than the piece; then the part is cut again.
  for (int pass = 0; pass < kSnapPasses; ++pass) {
    bool again = false;
    for (std::size_t b = 0; b < part.bodies.size(); ++b)
      for (int e = 0; e < pieces[b].mesh.tet_count(); ++e) {
        const double q = mesh::quality(pieces[b].mesh, e);
        if (q >= kSnapFloor) continue;
        const mesh::Tet& t = m.tets[part.bodies[b].first_tet + pieces[b].parent[e]];
        for (int v : t)
          if (phi[v] != 0.0 && std::any_of(t.begin(), t.end(), [&](int w) { return phi[v] * phi[w] < 0.0; }))
            again = put_onto_cut(v, q * (1.0 + 1e-9)) || again;
      }
    if (!again) break;
    cut_bodies();
  }
  // The fields follow the pieces: an element's values to its pieces, a
  // node's interpolated along the edge it lies on.
  scene::RunState& out = result.part;
  std::vector<std::vector<int>> parents(part.bodies.size());
  std::vector<std::vector<mesh::NodeOrigin>> origins(part.bodies.size());
  for (std::size_t b = 0; b < part.bodies.size(); ++b) {
    out.bodies.push_back(mesh::append(out.mesh, pieces[b].mesh));
    result.reshaped[b] += mesh::volume(pieces[b].mesh);
    parents[b] = std::move(pieces[b].parent);
    origins[b] = std::move(pieces[b].origin);
  }
  const auto element_field = [&](const std::vector<double>& values, int per) {
    std::vector<double> kept;
    for (std::size_t b = 0; b < part.bodies.size(); ++b)
      for (int e : parents[b]) {
        const auto first = values.begin() + per * (part.bodies[b].first_tet + e);
        kept.insert(kept.end(), first, first + per);
      }
    return kept;
  };
  const auto body_nodal = [&](std::size_t b, const double* values, int per, std::vector<double>& to) {
    for (const mesh::NodeOrigin& o : origins[b])
      for (int k = 0; k < per; ++k)
        to.push_back((1.0 - o.t) * values[per * o.a + k] + o.t * values[per * o.b + k]);
  };
  const auto nodal_field = [&](const std::vector<double>& values, int per) {
    std::vector<double> kept;
    for (std::size_t b = 0; b < part.bodies.size(); ++b)
      body_nodal(b, values.data() + per * part.bodies[b].first_node, per, kept);
    return kept;
  };
  out.equivalent_strain = element_field(part.equivalent_strain, 1);
  for (const std::vector<double>& d : part.damage)
    out.damage.push_back(element_field(d, 1));
  if (!part.elastic_stress.empty()) out.elastic_stress = element_field(part.elastic_stress, 6);
  if (!part.temperature.empty()) out.temperature = nodal_field(part.temperature, 1);
  if (!part.material_position.empty()) out.material_position = nodal_field(part.material_position, 3);
  out.unknowns = {Eigen::VectorXd::Zero(4 * out.mesh.node_count()), Eigen::VectorXd::Zero(3 * out.mesh.tet_count())};
  out.die_extent = part.die_extent, out.die_sampling = part.die_sampling;
  out.body_wear.resize(part.body_wear.size());
  for (std::size_t b = 0; b < part.body_wear.size(); ++b)
    if (!part.body_wear[b].empty()) body_nodal(b, part.body_wear[b].data(), 1, out.body_wear[b]);
  return result;
}

RunEnd trim(const scene::Operation& op, const RunOptions& options, scene::RunState& part) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& dir = options.output_directory;
  processes::on_root([&] { std::filesystem::create_directories(dir); });
  log::open_file(dir + "/anvil.log");
  Timers timers;
  if (part.mesh.node_count() == 0) { // the chain's first operation: the bodies as built
    const scene::Scene built(op.input, timers);
    part = scene::initial_state(built);
  }
  const Cut cut = make_cut(op.trim, op.source, 2.0 * mesh::bounding_box(part.mesh).diagonal().norm());
  CutPart cut_off = cut_part(part, cut, symmetry_planes(op.input, part.mesh));
  scene::RunState& cut_state = cut_off.part;
  const std::vector<double>& removed = cut_off.removed; // mm³ of each body, model
  for (std::size_t b = 0; b < part.bodies.size(); ++b)
    log::info("trim: body %zu: the nodes put onto the cut change the part's volume by %+.4f%%", b + 1,
              100.0 * cut_off.reshaped[b] / mesh::volume(cut_state.mesh, cut_state.bodies[b]));
  cut_state.volume.initial = part.volume.initial - std::accumulate(removed.begin(), removed.end(), 0.0);
  const scene::Scene scene(op.input, timers, &cut_state);
  scene::RunState state = scene::initial_state(scene, &cut_state);
  std::vector<remesh::RemeshDue> due;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const mesh::MeshRange& r = state.bodies[b];
    double worst = 1.0;
    for (int e = r.first_tet; e < r.first_tet + r.tet_count; ++e)
      worst = std::min(worst, mesh::quality(state.mesh, e));
    log::info("trim: body '%s' cut to %d of %d elements, worst quality %.3f", scene.bodies[b].name.c_str(), r.tet_count,
              part.bodies[b].tet_count, worst);
    if (worst < op.input.remeshing.quality && !scene.bodies[b].law->is_elastic())
      due.push_back({.body = static_cast<int>(b),
                     .why = "the trim cut left elements below remeshing.quality",
                     .local = true,
                     .die_corners = {},
                     .sunk_edges = {}});
  }
  std::string remeshed = "none";
  // mm³ of each body the remesh changed (a surface mending's slivers, a whole part's remesh).
  std::vector<double> remeshed_volume(scene.bodies.size(), 0.0);
  if (!due.empty()) {
    const std::vector<int> touching(state.mesh.node_count(), -1);
    const std::vector<double> rate(state.mesh.tet_count(), 0.0);
    auto add_volumes = [&](double sign) {
      for (std::size_t b = 0; b < scene.bodies.size(); ++b)
        remeshed_volume[b] += sign * mesh::volume(state.mesh, state.bodies[b]);
    };
    add_volumes(-1.0);
    remesh::remesh(scene, state, due, touching, rate, 0.0, timers);
    add_volumes(1.0);
    remeshed = state.remeshes.empty()                      ? "refused"
               : state.remeshes.back().rebuilt_share < 1.0 ? "along the cut"
                                                           : "whole part";
  }
  for (int e = 0; e < state.mesh.tet_count(); ++e)
    if (!(mesh::quality(state.mesh, e) > 0.0))
      throw RunError(op.source + ": the trim left an inverted element the remesh could not rebuild");
  scene::Discretisation disc = scene::discretise(scene, state, timers);
  io::RunWriter writer(dir, state, false);
  writer.write(scene, disc, state, true, timers);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  processes::on_root([&] {
    io::write_checkpoint(dir + "/checkpoint.h5", state, scene.fingerprint);
    write_trim_summary(dir, scene, cut_off, state, remeshed, remeshed_volume, seconds);
  });
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    log::info("trim: body '%s': %.6g mm3 removed (whole part %.6g mm3, %.4g kg)", scene.bodies[b].name.c_str(),
              removed[b], scene.symmetry_copies * removed[b],
              mass_of(scene, int(b), scene.symmetry_copies * removed[b]));
  log::close_file();
  part = std::move(state);
  return {"trimmed", true};
}

} // namespace anvil::run
