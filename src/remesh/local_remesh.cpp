#include "anvil/remesh/local_remesh.h"

#include "anvil/core/error.h"
#include "anvil/mesh/boundary_slivers.h"
#include "anvil/mesh/edge_bisection.h"
#include "anvil/mesh/grid_snap.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/field_transfer.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/rebuild_region.h"
#include "anvil/remesh/remesh_due.h"
#include "anvil/remesh/surface_mending.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <span>

namespace anvil::remesh {
namespace {

/// Layers of elements around the poor ones that a local remesh rebuilds too.
constexpr int kRegionLayers = 2;
/// A region larger than this share of a body is rebuilt whole.
constexpr double kMostLocal = 0.5;
/// CGAL splits edges longer than 4/3 of its length (with a margin): a region
/// whose surface is rebuilt has such edges of its border bisected first, in
/// up to kBorderPasses passes (a bisection can leave another long edge).
constexpr double kCgalSplits = 4.0 / 3.0 / 1.01;
constexpr int kBorderPasses = 3;
/// Rebuilds of a region whose kept contact nodes hold a poor element, each
/// letting go of those nodes.
constexpr int kLetGoPasses = 2;
/// A split over a sunk die feature keeps every element it makes or moves at
/// this many times remeshing.quality: one just above the trigger falls below
/// it in an increment or two, and a poor element on the surface takes a
/// whole remesh.
constexpr double kSplitQuality = 2.0;

/// The tets of `m` that `keep` flags, as a mesh of their own.
mesh::TetMesh tets_of(const mesh::TetMesh& m, const std::vector<char>& keep) {
  std::vector<mesh::Tet> kept;
  for (int e = 0; e < m.tet_count(); ++e)
    if (keep[e]) kept.push_back(m.tets[e]);
  return mesh::tets_mesh(m.nodes, kept);
}

/// The nodal fields of the nodes `old_node` names (in their order), the
/// rest dropped: fields.mesh has lost nodes.
void keep_nodes(BodyFields& fields, const std::vector<int>& old_node) {
  auto keep = [&](auto& values, int stride) {
    if (values.size() == 0) return;
    std::vector<double> kept;
    kept.reserve(stride * old_node.size());
    for (int n : old_node)
      for (int k = 0; k < stride; ++k)
        kept.push_back(values[stride * n + k]);
    values.resize(kept.size());
    std::copy(kept.begin(), kept.end(), values.data());
  };
  keep(fields.nodal, 4);
  keep(fields.temperature, 1);
  keep(fields.material, 3);
  std::vector<int> touching;
  for (int n : old_node)
    touching.push_back(fields.touching_die[n]);
  fields.touching_die = std::move(touching);
}

/// `fields` (mesh, nodal and element fields as they are) moved into `out`.
void take_fields(BodyFields& fields, LocalRemesh& out) {
  out.mesh = std::move(fields.mesh);
  out.nodal = std::move(fields.nodal);
  out.strain = std::move(fields.strain);
  out.damage = std::move(fields.damage);
  if (!fields.temperature.empty())
    out.temperature =
        Eigen::Map<const Eigen::VectorXd>(fields.temperature.data(), Eigen::Index(fields.temperature.size()));
  if (!fields.material.empty())
    out.material = Eigen::Map<const Eigen::VectorXd>(fields.material.data(), Eigen::Index(fields.material.size()));
}

/// Bisects the edges `edges` of fields.mesh, each tet's halves taking its
/// ε̄, D (and `region` flag, when given) and each midpoint the mean of its
/// edge's nodal values (P1: exact), the die its ends both press on.
mesh::Bisection bisect_carrying(BodyFields& fields, const std::vector<std::array<int, 2>>& edges,
                                std::vector<char>* region) {
  mesh::TetMesh& m = fields.mesh;
  const int nodes_before = m.node_count();
  const mesh::Bisection cut = mesh::bisect_edges(m, edges);
  if (region) mesh::carry_to_halves(cut, *region);
  mesh::carry_to_halves(cut, fields.strain);
  for (std::vector<double>& d : fields.damage)
    mesh::carry_to_halves(cut, d);
  auto at_midpoints = [&](auto& values, int stride) {
    values.conservativeResize(stride * m.node_count());
    for (std::size_t k = 0; k < cut.midpoint_of.size(); ++k) {
      const auto& [a, c] = cut.midpoint_of[k];
      values.segment(stride * (nodes_before + k), stride) =
          0.5 * (values.segment(stride * a, stride) + values.segment(stride * c, stride));
    }
  };
  at_midpoints(fields.nodal, 4);
  auto at_midpoints_std = [&](std::vector<double>& values, int stride) {
    if (values.empty()) return;
    Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
    at_midpoints(v, stride);
    values.assign(v.data(), v.data() + v.size());
  };
  at_midpoints_std(fields.temperature, 1);
  at_midpoints_std(fields.material, 3);
  for (const auto& [a, c] : cut.midpoint_of)
    fields.touching_die.push_back(fields.touching_die[a] == fields.touching_die[c] ? fields.touching_die[a] : -1);
  return cut;
}

/// Shifts the temperatures `t` of the nodes of `part` that `fresh` flags by
/// one amount, so that the heat `part` stores equals that of `old` at
/// `old_t`: interpolation at new nodes smooths the field and changes it a
/// little. `part` must hold the volume of `old` (the mesh before its fit to
/// the dies): the heat of the volume that fit moves goes with it, at its own
/// temperature, and given to the few new nodes instead it heated them by
/// hundreds of degrees (a split's midpoints put 0.2 mm into a die).
void keep_stored_heat(const mesh::TetMesh& old, const double* old_t, const mesh::TetMesh& part, Eigen::VectorXd& t,
                      const std::vector<char>& fresh, const thermal::ThermalMaterial& material) {
  const thermal::NodalMass m_new = nodal_mass(part, material);
  const double before = stored_heat(old, old_t, material);
  const double after = thermal::enthalpy(m_new, mesh::whole_range(part), {t.data(), std::size_t(part.node_count())});
  double capacity = 0.0;
  for (int n = 0; n < part.node_count(); ++n)
    if (fresh[n]) capacity += m_new.mass[n] * material.specific_heat.at(t[n]);
  if (capacity > 0.0)
    for (int n = 0; n < part.node_count(); ++n)
      if (fresh[n]) t[n] += (before - after) / capacity;
}

/// A die fillet or edge sunk between the contact nodes: the boundary edges
/// over it (`sunk_edges`) are bisected and their midpoints put onto the die;
/// every other node stays where it is and every element keeps its fields
/// (its halves take them). Nothing, with `why_not`, when no midpoint could
/// be put onto a die without an element falling below remeshing.quality.
std::optional<LocalRemesh> split_sunk_edges(const scene::Scene& scene, const scene::RunState& state, int b,
                                            const std::vector<SunkEdge>& sunk_edges, BodyFields fields,
                                            std::string& why_not) {
  const scene::Body& body = scene.bodies[b];
  const double floor = kSplitQuality * scene.input.remeshing.quality;
  const mesh::TetMesh old = fields.mesh;
  // An edge whose tets' halves would fall below that, with the midpoint
  // where the split makes it or on the die, stays: the quality trigger
  // would take them next, with a remesh that resamples the surface the split
  // keeps, and a midpoint that cannot go onto the die is a node for nothing.
  std::map<std::array<int, 2>, mesh::Point> on_die;
  for (const SunkEdge& e : sunk_edges)
    on_die.emplace(e.nodes, e.on_die);
  std::set<std::array<int, 2>> poor;
  for (const mesh::Tet& t : old.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto edge = on_die.find({std::min(t[i], t[j]), std::max(t[i], t[j])});
        if (edge == on_die.end()) continue;
        std::array<mesh::Point, 4> half{old.nodes[t[0]], old.nodes[t[1]], old.nodes[t[2]], old.nodes[t[3]]};
        for (const mesh::Point& at : {mesh::Point(0.5 * (half[i] + half[j])), edge->second})
          for (int k : {i, j}) {
            const mesh::Point end = half[k];
            half[k] = at;
            if (mesh::quality(half[0], half[1], half[2], half[3]) < floor) poor.insert(edge->first);
            half[k] = end;
          }
      }
  std::vector<std::array<int, 2>> edges;
  for (const auto& [nodes, point] : on_die)
    if (!poor.count(nodes)) edges.push_back(nodes);
  if (edges.empty()) {
    why_not = "splitting any of the edges would leave an element below remeshing.quality";
    return std::nullopt;
  }
  const std::vector<int> touching = fields.touching_die;
  const mesh::Bisection cut = bisect_carrying(fields, edges, nullptr);
  mesh::TetMesh& part = fields.mesh;
  std::vector<char> fresh(part.nodes.size(), 0);
  std::fill(fresh.begin() + old.node_count(), fresh.end(), 1);
  LocalRemesh out;
  out.surface = RegionSurface::rebuilt;
  out.volume_remeshed = mesh::volume(part);
  out.put_back = put_onto_dies(part, old, touching, scene, b, state.dies, body.remesh_size, floor, fresh);
  if (out.put_back.nodes == 0) {
    why_not = "none of the split edges' midpoints could be put onto the dies";
    return std::nullopt;
  }
  out.volume_put_back = mesh::volume(part);
  const std::set<int> split(cut.parent.begin() + old.tet_count(), cut.parent.end());
  out.rebuilt = static_cast<int>(split.size());
  // The halves carry every field exactly (a midpoint's temperature is the
  // P1 field's value there): the stored heat changes only with the volume
  // the put-back moves, at the temperature where it moves.
  take_fields(fields, out);
  return out;
}

/// Bisects the edges longer than `longest` (mm) between two nodes of the
/// tets `region` flags that kept tets share too (the region's border),
/// carrying `fields` and `region` onto the halves. Returns whether any was.
bool bisect_long_border_edges(BodyFields& fields, std::vector<char>& region, double longest) {
  const std::vector<std::array<int, 2>> edges = long_border_edges(fields.mesh, region, longest);
  if (edges.empty()) return false;
  bisect_carrying(fields, edges, &region);
  return true;
}

} // namespace

thermal::NodalMass nodal_mass(const mesh::TetMesh& part, const thermal::ThermalMaterial& material) {
  return thermal::nodal_mass(part, std::vector<const thermal::ThermalMaterial*>(part.tets.size(), &material));
}

double stored_heat(const mesh::TetMesh& part, const double* t, const thermal::ThermalMaterial& material) {
  return thermal::enthalpy(nodal_mass(part, material), mesh::whole_range(part), {t, std::size_t(part.node_count())});
}

double relative(double after, double before) {
  return before != 0.0 ? after / before - 1.0 : after - before;
}

std::vector<char> contact_surface(const mesh::TetMesh& part, std::span<const int> touching_die,
                                  const scene::Scene& scene, int b, std::span<const scene::DieState> dies_now) {
  const double size = scene.bodies[b].remesh_size;
  const std::vector<char> on_boundary = mesh::boundary_node_flags(part);
  std::vector<char> kept(part.nodes.size(), 0);
  for (std::size_t n = 0; n < kept.size(); ++n) {
    kept[n] = touching_die[n] >= 0;
    for (std::size_t d = 0; d < scene.dies.size() && on_boundary[n] && !kept[n]; ++d) {
      // Inside by less than an element: a node in this body's contact (deeper
      // is the far side of an open die surface, as for put_onto_dies).
      const double distance = scene.dies[d].surface->project(part.nodes[n] - dies_now[d].displacement).distance;
      kept[n] = distance > -size && distance < kAboutToTouch * size;
    }
  }
  return kept;
}

/// Body `b`'s mesh `part` rebuilt where its elements are poor (rebuild_region)
/// or around the die corners of `due`, the rest kept bit for bit with its
/// fields; the fields transferred in the rebuilt region only. Poor elements
/// held by the surface are first mended on it (surface_mending.h). The
/// region's surface is kept when that is enough (a flat element CGAL leaves
/// on a sharp edge of it taken off); it is rebuilt around a die corner,
/// or when the poor elements are held by the surface, and then its new
/// nodes are put onto the dies and the material `material` (mm³) kept on
/// its new free surface. Nothing, with `why_not` saying why, when the
/// region is most of the body or its result is still below the trigger.
std::optional<LocalRemesh> remesh_locally(const scene::Scene& scene, const scene::RunState& state, int b,
                                          const RemeshDue& due, BodyFields fields, double material, double time_step,
                                          Region choice, std::string& why_not) {
  if (!due.sunk_edges.empty()) return split_sunk_edges(scene, state, b, due.sunk_edges, std::move(fields), why_not);
  const scene::RemeshSpec& spec = scene.input.remeshing;
  const scene::Body& body = scene.bodies[b];
  mesh::TetMesh& part = fields.mesh;
  const Eigen::VectorXd& part_nodal = fields.nodal;
  const std::vector<double>& part_strain = fields.strain;
  const std::vector<std::vector<double>>& part_damage = fields.damage;
  LocalRemesh out;
  // A poor element held by the surface (its poor face on it) is mended
  // first on the surface (an edge flipped or a short one collapsed), the
  // other nodes where they are: interior nodes alone cannot mend it, and a
  // rebuilt surface moves contact nodes.
  std::vector<std::vector<double>*> element_fields{&fields.strain};
  for (std::vector<double>& d : fields.damage)
    element_fields.push_back(&d);
  const double strain_integral = integral(part, fields.strain);
  const double strain_max = *std::max_element(fields.strain.begin(), fields.strain.end());
  const double worst_before = worst_quality(part);
  const SurfaceMending mended = mend_surface(part, element_fields, spec.quality, kFlatSurface);
  out.flips = mended.flips;
  out.collapses = mended.collapses;
  if (mended.collapses > 0) keep_nodes(fields, mended.old_node);
  std::vector<char> region = choice == Region::whole_body
                                 ? std::vector<char>(part.tets.size(), 1)
                                 : rebuild_region(part, part_nodal, time_step, spec.quality, kRegionLayers);
  if (!due.die_corners.empty()) {
    const std::vector<char> around = region_around(part, due.die_corners, body.remesh_size, kRegionLayers);
    for (std::size_t e = 0; e < region.size(); ++e)
      region[e] = region[e] || around[e];
  }
  out.rebuilt = static_cast<int>(std::count(region.begin(), region.end(), 1));
  char text[200];
  if (out.rebuilt == 0 && mended.flips + mended.collapses > 0) {
    // The mending was enough: the nodal fields stay on their nodes, the
    // element fields came with the new elements.
    out.rebuilt = static_cast<int>(std::count(mended.changed.begin(), mended.changed.end(), 1));
    out.worst = mended.worst_after;
    out.strain_integral_change = relative(integral(part, fields.strain), strain_integral);
    out.strain_max_change = relative(*std::max_element(fields.strain.begin(), fields.strain.end()), strain_max);
    take_fields(fields, out);
    return out;
  }
  if (out.rebuilt == 0) {
    why_not = "no element to rebuild locally";
    return std::nullopt;
  }
  int mended_outside = 0; // elements the mending made that the region does not rebuild
  for (std::size_t e = 0; e < region.size(); ++e)
    mended_outside += mended.changed[e] && !region[e];
  out.rebuilt += mended_outside;
  if (choice == Region::due && out.rebuilt > kMostLocal * part.tet_count()) {
    std::snprintf(text, sizeof text, "the region to rebuild holds %d of its %d elements", out.rebuilt,
                  part.tet_count());
    why_not = text;
    return std::nullopt;
  }
  RemeshSettings settings;
  // A uniform field asks for the body's size everywhere; an adaptive one
  // keeps the region as fine as it is (a fine flash is not coarsened by a
  // local remesh of its poor elements).
  settings.edge_length = spec.adaptive ? std::min(body.remesh_size, mean_edge_length(part, region)) : body.remesh_size;
  settings.feature_angle = spec.feature_angle;
  settings.iterations = spec.iterations;
  settings.quality_floor = spec.quality;
  settings.grid = mesh::remesh_grid(body.remesh_size, state.remeshes.size());
  settings.deadline = deadline_in(spec.time_limit);
  RegionRemesh local;
  mesh::TetMesh before_fit; // CGAL's mesh of the old region, before the fit to the dies: ε̄ is remapped on it
  // One try: the region remeshed with its surface kept or rebuilt; false,
  // with why_not, when it failed or left an element below the trigger. The
  // `last` try is also taken short of the trigger when it leaves a better
  // worst element than the body had, and none the lowered trigger would take
  // at once: the trigger then waits at kQualityAgain of itself (remesh_due.h),
  // as after a whole remesh short of it. The whole remesh it spares would
  // move every contact node (docs/remeshing.md: a local remesh of the
  // connecting rod lifting 0.056 to 0.142 had sent the body to one).
  auto rebuild = [&](RegionSurface surface, std::span<const char> pinned, bool last) {
    out.surface = surface;
    out.peeled = 0;
    try {
      local = remesh_region(part, region, settings, surface, pinned);
    } catch (const RunError& error) {
      local = {};
      why_not = error.what();
      return false;
    } catch (const RemeshStopped&) { // its deadline passed: nothing else stops a local remesh
      local = {};
      std::snprintf(text, sizeof text, "CGAL was still at work on the region after remeshing.time_limit (%g s)",
                    spec.time_limit);
      why_not = text;
      return false;
    }
    if (surface == RegionSurface::rebuilt) {
      std::vector<char> fresh(local.mesh.nodes.size(), 0);
      for (std::size_t n = 0; n < fresh.size(); ++n)
        fresh[n] = local.old_node[n] < 0;
      before_fit = local.mesh;
      out.volume_remeshed = mesh::volume(local.mesh);
      out.put_back = put_onto_dies(local.mesh, part, fields.touching_die, scene, b, state.dies, settings.edge_length,
                                   spec.quality, fresh);
      out.volume_put_back = mesh::volume(local.mesh);
      out.given_back = keep_material(local.mesh, scene, b, state.dies, material, settings.edge_length, fresh);
      if (const std::string fault = mesh::fault(local.mesh); !fault.empty()) {
        why_not = "locally remeshed body fitted to the dies: " + fault;
        return false;
      }
      if (const std::string lost = scene::condition_losing_faces(body.conditions, part, local.mesh); !lost.empty()) {
        why_not = "locally remeshed body has no face for boundary " + lost;
        return false;
      }
    }
    out.worst = worst_quality(local.mesh); // the kept tets too: a border bisection splits some
    if (out.worst < spec.quality && surface == RegionSurface::kept) {
      // CGAL cannot change a kept surface: where it folds to a sharp edge
      // (a lap starting at a die's rim, on the connecting rod), it leaves a
      // flat element with two faces on it, which would send the whole body
      // to a remesh. Taken off, the surface keeps its nodes and the kept
      // tets stay as they are (mesh/boundary_slivers.h).
      std::vector<int> left;
      if (const int peeled = mesh::peel_boundary_slivers(local.mesh, spec.quality, 0.0, local.kept_tets, &left)) {
        for (int& node : left)
          node = local.old_node[node];
        local.old_node = std::move(left);
        out.peeled = peeled;
        out.worst = worst_quality(local.mesh);
      }
    }
    if (out.worst >= spec.quality) return true;
    out.short_of_trigger = last && out.worst > worst_before && out.worst >= quality_due_below(out.worst, spec.quality);
    if (out.short_of_trigger) return true;
    std::snprintf(text, sizeof text, "a local remesh of %d elements, its surface %s, left worst quality %.3f",
                  out.rebuilt, surface == RegionSurface::kept ? "kept" : "rebuilt", out.worst);
    why_not = text;
    return false;
  };
  // The region rebuilt with its part of the surface, the nodes pressing on
  // a die kept. CGAL would split the border's edges longer than 4/3 of its
  // length: they are bisected first, on both sides (the kept tets keep their
  // nodes and shape, their fields exactly); a kept tet the bisection leaves
  // below the trigger joins the region. The whole body keeps its contact
  // surface (contact_surface: the nodes about to touch too); where those
  // nodes hold an element below the trigger, they are let go and the body
  // rebuilt again (up to kLetGoPasses times). In a local region, keeping the
  // nodes about to touch made no measured difference (docs/remeshing.md).
  auto rebuild_with_surface = [&] {
    for (int pass = 0; pass < kBorderPasses; ++pass) {
      if (!bisect_long_border_edges(fields, region, kCgalSplits * settings.edge_length)) break;
      for (int e = 0; e < part.tet_count(); ++e)
        region[e] = region[e] || mesh::quality(part, e) < spec.quality;
    }
    out.rebuilt = static_cast<int>(std::count(region.begin(), region.end(), 1)) + mended_outside;
    std::vector<char> pinned(part.nodes.size(), 0);
    if (choice == Region::whole_body)
      pinned = contact_surface(part, fields.touching_die, scene, b, state.dies);
    else
      for (std::size_t n = 0; n < pinned.size(); ++n)
        pinned[n] = fields.touching_die[n] >= 0;
    const int let_go_passes = choice == Region::whole_body ? kLetGoPasses : 0;
    for (int pass = 0;; ++pass) {
      if (rebuild(RegionSurface::rebuilt, pinned, pass == let_go_passes)) return true;
      if (pass == let_go_passes || local.mesh.tets.empty()) return false;
      int let_go = 0;
      for (int e = 0; e < local.mesh.tet_count(); ++e)
        if (mesh::quality(local.mesh, e) < spec.quality)
          for (int node : local.mesh.tets[e])
            if (const int old_node = local.old_node[node]; old_node >= 0 && pinned[old_node])
              pinned[old_node] = 0, ++let_go;
      if (let_go == 0) return false;
    }
  };
  // Poor elements are rebuilt inside the surface (the contact surface
  // stays where it is); a die corner needs new surface nodes around it,
  // and so does a region whose surface holds its poor elements (in the 75 %
  // upsetting, a per mille of load where a whole remesh moved it 3 %).
  // Not where sunk edges are split: the nodes the splits add stay until a
  // whole remesh resamples the surface at the body's size, and each whole
  // remesh put off lets more of them gather for the next one to drop (the
  // connecting rod's worst jump went from 4.4 to 6.7 %).
  bool rebuilt;
  if (!due.die_corners.empty() || choice == Region::whole_body)
    rebuilt = rebuild_with_surface();
  else
    rebuilt =
        rebuild(RegionSurface::kept, {}, spec.split_sunk_edges) || (!spec.split_sunk_edges && rebuild_with_surface());
  if (!rebuilt) return std::nullopt;
  // The nodal fields, taken after the bisection may have moved them.
  const double* part_temperature = fields.temperature.empty() ? nullptr : fields.temperature.data();
  const double* part_material = fields.material.empty() ? nullptr : fields.material.data();
  // Fields: the kept nodes and tets keep theirs; the new ones take them from
  // the old region, ε̄ and D by the conservative remap.
  const mesh::TetMesh old_region = tets_of(part, region);
  std::vector<char> is_new(local.mesh.tets.size(), 0);
  std::fill(is_new.begin() + local.kept_tets, is_new.end(), 1);
  const mesh::TetMesh new_region = tets_of(out.surface == RegionSurface::kept ? local.mesh : before_fit, is_new);
  const PointLocator in_old(old_region);
  // An element field of the body on the local mesh: kept tets first (remesh_region's order), then the new.
  auto element_field = [&](const std::vector<double>& values) {
    std::vector<double> old_values, result;
    for (int e = 0; e < part.tet_count(); ++e)
      if (region[e]) old_values.push_back(values[e]);
    const std::vector<double> new_values = transfer_element(old_region, old_values, in_old, new_region);
    result.reserve(local.mesh.tets.size());
    for (int e = 0; e < part.tet_count(); ++e)
      if (!region[e]) result.push_back(values[e]);
    result.insert(result.end(), new_values.begin(), new_values.end());
    return result;
  };
  out.strain = element_field(part_strain);
  for (const std::vector<double>& d : part_damage)
    out.damage.push_back(element_field(d));
  out.strain_integral_change = relative(integral(local.mesh, out.strain), strain_integral);
  out.strain_max_change = relative(*std::max_element(out.strain.begin(), out.strain.end()), strain_max);
  std::vector<mesh::Point> fresh;
  for (std::size_t n = 0; n < local.mesh.nodes.size(); ++n)
    if (local.old_node[n] < 0) fresh.push_back(local.mesh.nodes[n]);
  const std::vector<Location> at = in_old.locate(fresh);
  // The old region's nodal values, in its own numbering (tets_of's order).
  auto region_values = [&](const double* values, int stride) {
    Eigen::VectorXd v(stride * old_region.node_count());
    std::vector<int> number(part.nodes.size(), -1);
    int next_node = 0;
    for (int e = 0; e < part.tet_count(); ++e)
      if (region[e])
        for (int node : part.tets[e])
          if (number[node] < 0) {
            number[node] = next_node;
            v.segment(stride * next_node++, stride) = Eigen::Map<const Eigen::VectorXd>(values + stride * node, stride);
          }
    return v;
  };
  auto carry = [&](const double* values, int stride, bool extend) {
    const Eigen::VectorXd interpolated =
        interpolate_nodal(old_region, region_values(values, stride), stride, at, extend);
    Eigen::VectorXd all(stride * local.mesh.node_count());
    for (std::size_t n = 0, k = 0; n < local.mesh.nodes.size(); ++n)
      all.segment(stride * n, stride) =
          local.old_node[n] >= 0
              ? Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(values + stride * local.old_node[n], stride))
              : Eigen::VectorXd(interpolated.segment(stride * k++, stride));
    return all;
  };
  out.nodal = carry(part_nodal.data(), 4, false);
  if (part_material) out.material = carry(part_material, 3, true);
  if (part_temperature) {
    out.temperature = carry(part_temperature, 1, false);
    if (body.thermal) {
      std::vector<char> fresh_nodes(local.mesh.nodes.size(), 0);
      for (std::size_t n = 0; n < fresh_nodes.size(); ++n)
        fresh_nodes[n] = local.old_node[n] < 0;
      keep_stored_heat(part, part_temperature, out.surface == RegionSurface::kept ? local.mesh : before_fit,
                       out.temperature, fresh_nodes, *body.thermal);
    }
  }
  out.mesh = std::move(local.mesh);
  return out;
}

} // namespace anvil::remesh
