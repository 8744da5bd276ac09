#include "anvil/run/trim.h"

#include "anvil/core/Timers.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/io/JsonWriter.h"
#include "anvil/io/RunWriter.h"
#include "anvil/io/atomic_file.h"
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

namespace anvil::run {
namespace {

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

/// summary.json of a trim; `removed` is each body's volume cut off (mm³, model).
void write_trim_summary(const std::string& directory, const scene::Scene& scene, const std::vector<double>& removed,
                        const scene::RunState& after, const std::string& remeshed, double seconds) {
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

scene::RunState cut_part(const scene::RunState& part, const Cut& cut, std::span<const SymmetryPlane> planes) {
  const mesh::TetMesh& m = part.mesh;
  std::vector<mesh::Point> x = m.nodes;
  std::vector<double> phi(x.size());
  const double on_cut = 1e-9 * mesh::bounding_box(m).diagonal().norm(); // mm: a node this near is on it
  for (std::size_t n = 0; n < x.size(); ++n) {
    phi[n] = cut.distance(x[n]);
    if (std::abs(phi[n]) < on_cut) phi[n] = 0.0;
  }
  // Each edge across the cut: its nearer end onto the cut (φ is 1-Lipschitz:
  // a node moves by at most half the edge). No edge crosses afterwards.
  std::vector<char> snap(x.size(), 0);
  for (const mesh::Tet& t : m.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const int a = t[i], b = t[j];
        if ((phi[a] < 0.0 && phi[b] > 0.0) || (phi[a] > 0.0 && phi[b] < 0.0))
          snap[std::abs(phi[a]) <= std::abs(phi[b]) ? a : b] = 1;
      }
  for (std::size_t n = 0; n < x.size(); ++n) {
    if (!snap[n]) continue;
    // Onto the cut, and back onto the symmetry planes the node is on: the
    // alternating projections meet where the cut crosses them.
    std::vector<const SymmetryPlane*> on;
    for (const SymmetryPlane& p : planes)
      if (std::abs(x[n][p.axis] - p.at) < on_cut) on.push_back(&p);
    for (int pass = 0; pass < (on.empty() ? 1 : 50); ++pass) {
      x[n] = cut.nearest(x[n]);
      for (const SymmetryPlane* p : on)
        x[n][p->axis] = p->at;
    }
    phi[n] = 0.0;
  }
  std::vector<char> keep_tet(m.tets.size(), 0);
  for (std::size_t e = 0; e < m.tets.size(); ++e) {
    const mesh::Tet& t = m.tets[e];
    double sum = 0.0;
    for (int v : t)
      sum += phi[v];
    if (sum == 0.0) // all four on the cut: the side its centre is on
      sum = cut.distance(0.25 * (x[t[0]] + x[t[1]] + x[t[2]] + x[t[3]]));
    keep_tet[e] = sum < 0.0;
  }
  scene::RunState out;
  std::vector<int> number(x.size(), -1); // each kept node's index in out.mesh
  for (std::size_t b = 0; b < part.bodies.size(); ++b) {
    const mesh::MeshRange& r = part.bodies[b];
    const int base = out.mesh.node_count();
    mesh::TetMesh piece;
    for (int e = r.first_tet; e < r.first_tet + r.tet_count; ++e) {
      if (!keep_tet[e]) continue;
      mesh::Tet t = m.tets[e];
      for (int& v : t) {
        if (number[v] < 0) {
          number[v] = base + piece.node_count();
          piece.nodes.push_back(x[v]);
        }
        v = number[v] - base;
      }
      piece.tets.push_back(t);
    }
    if (piece.tets.empty()) throw InputError("the trim cut removes the whole of body " + std::to_string(b + 1));
    std::vector<mesh::Triangle> faces; // the boundary faces that stay, with their tags
    std::vector<int> tags;
    for (int f = r.first_face; f < r.first_face + r.face_count; ++f) {
      mesh::Triangle face = m.boundary_faces[f];
      bool stays = true;
      for (int& v : face)
        stays = stays && number[v] >= 0, v = stays ? number[v] - base : v;
      if (stays) faces.push_back(face), tags.push_back(m.boundary_tags[f]);
    }
    mesh::build_boundary(piece, faces, tags);
    out.bodies.push_back(mesh::append(out.mesh, piece));
  }
  // Fields: the kept elements' and nodes', in their new order.
  const auto keep_elements = [&](const std::vector<double>& values, int per) {
    std::vector<double> kept;
    for (std::size_t e = 0; e < m.tets.size(); ++e)
      if (keep_tet[e]) kept.insert(kept.end(), values.begin() + per * e, values.begin() + per * (e + 1));
    return kept;
  };
  const auto keep_nodes = [&](const std::vector<double>& values, int per) {
    std::vector<double> kept(per * out.mesh.nodes.size());
    for (std::size_t n = 0; n < x.size(); ++n)
      if (number[n] >= 0) std::copy_n(values.begin() + per * n, per, kept.begin() + per * number[n]);
    return kept;
  };
  out.equivalent_strain = keep_elements(part.equivalent_strain, 1);
  for (const std::vector<double>& d : part.damage)
    out.damage.push_back(keep_elements(d, 1));
  if (!part.elastic_stress.empty()) out.elastic_stress = keep_elements(part.elastic_stress, 6);
  if (!part.temperature.empty()) out.temperature = keep_nodes(part.temperature, 1);
  if (!part.material_position.empty()) out.material_position = keep_nodes(part.material_position, 3);
  out.unknowns = {Eigen::VectorXd::Zero(4 * out.mesh.node_count()), Eigen::VectorXd::Zero(3 * out.mesh.tet_count())};
  out.body_wear.resize(part.body_wear.size());
  for (std::size_t b = 0; b < part.body_wear.size(); ++b)
    if (!part.body_wear[b].empty()) {
      out.body_wear[b].assign(out.bodies[b].node_count, 0.0);
      for (int n = 0; n < part.bodies[b].node_count; ++n)
        if (const int to = number[part.bodies[b].first_node + n]; to >= 0)
          out.body_wear[b][to - out.bodies[b].first_node] = part.body_wear[b][n];
    }
  return out;
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
  scene::RunState cut_state = cut_part(part, cut, symmetry_planes(op.input, part.mesh));
  std::vector<double> removed(part.bodies.size()); // mm³ of each body, model
  for (std::size_t b = 0; b < part.bodies.size(); ++b)
    removed[b] = mesh::volume(part.mesh, part.bodies[b]) - mesh::volume(cut_state.mesh, cut_state.bodies[b]);
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
      due.push_back({static_cast<int>(b), "the trim cut left elements below remeshing.quality", true});
  }
  std::string remeshed = "none";
  if (!due.empty()) {
    const std::vector<int> touching(state.mesh.node_count(), -1);
    const std::vector<double> rate(state.mesh.tet_count(), 0.0);
    remesh::remesh(scene, state, due, touching, rate, 0.0, timers);
    remeshed = state.remeshes.empty() ? "refused" : "along the cut";
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
    write_trim_summary(dir, scene, removed, state, remeshed, seconds);
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
