// The CGAL side of remesh_body: our tets as a CGAL remeshing triangulation
// (tet soup, docs/libraries.md §2), one surface patch per boundary patch, isotropic
// remeshing, and back.
#include "anvil/remesh/remesh_body.h"
#include "anvil/remesh/region_window.h"
#include "anvil/remesh/settle_on_surface.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/mesh/boundary_slivers.h"
#include "anvil/mesh/edge_bisection.h"
#include "anvil/mesh/flat_tet_mending.h"
#include "anvil/mesh/grid_snap.h"
#include "anvil/mesh/manifold.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/rebuild_region.h"
#include "anvil/remesh/size_levels.h"
#include "anvil/remesh/surface_mending.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <boost/functional/hash.hpp>

namespace anvil::remesh {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<Kernel>;
using VertexHandle = Triangulation::Vertex_handle;

/// A region's remesh length is at least this share above 3/4 of its longest
/// border edge, so that CGAL (which splits edges beyond 4/3 of it) leaves the
/// border whole.
constexpr double kBorderMargin = 1.01;
/// Tries of one level of the size field, each with the region grown over
/// the border faces CGAL changed in the last (or, when it changed none,
/// at a shorter length).
constexpr int kLevelAttempts = 4;
/// Passes of bisecting a level's long border edges (a bisection can leave
/// another long edge).
constexpr int kBorderPasses = 3;
/// A level whose remesh failed without changing its border is tried again
/// with edges this much shorter.
constexpr double kLevelRetryScale = 0.95;
/// A surface patch smaller than this many squares of the remesh's edge (two
/// faces of that edge or so) joins a neighbour (boundary_patches): a crumple
/// of a few faces, not a feature an element that size resolves.
constexpr double kSmallestPatch = 1.0;
/// After the size field's levels, cells below this quality are rebuilt.
constexpr double kPoorAfterLevels = 0.25;

/// Flat tets on the surface below this share of settings.quality_floor are
/// taken off the new mesh (mesh/boundary_slivers.h): a third, where the
/// remesher refuses a result (remesh/Remesher.cpp).
constexpr double kPeelShare = 1.0 / 3.0;

/// Face key as build_triangulation looks it up: the smallest index first, the rest in order.
std::array<int, 3> facet_key(const mesh::Triangle& f) {
  int k = 0;
  while (f[k] != std::min({f[0], f[1], f[2]}))
    ++k;
  return {f[k], f[(k + 1) % 3], f[(k + 2) % 3]};
}
/// CGAL's own default selection, the cells of a subdomain (≠ 0), which
/// throws RemeshStopped once the settings' stop is asked or their deadline
/// has passed, and a RunError once CGAL has looked at cells more often than
/// any pass that ends does. CGAL 5.5 gives no way to stop a pass, but it
/// asks the selection at every cell it splits, collapses, flips or smooths
/// around; the clock is read every kLooksPerCheck looks.
class StoppableSelection {
public:
  /// For `tr` remeshed in `settings.iterations` passes.
  StoppableSelection(const RemeshSettings& settings, const Triangulation& tr)
      : settings_(settings),
        most_looks_(settings.most_looks_per_cell_pass * std::max<std::size_t>(tr.number_of_finite_cells(), 1) *
                    static_cast<std::size_t>(std::max(settings.iterations, 1))) {}
  /// The selection as CGAL takes it (copied by value into each step).
  auto map() {
    return [this](Triangulation::Cell_handle c) {
      if (++looks_ % kLooksPerCheck == 0) {
        if (settings_.stop.stop_requested()) throw RemeshStopped{false};
        if (std::chrono::steady_clock::now() > settings_.deadline) throw RemeshStopped{true};
        if (looks_ > most_looks_)
          throw RunError("CGAL's remeshing stalled: " + std::to_string(looks_) + " looks at its cells, over " +
                         std::to_string(settings_.most_looks_per_cell_pass) + " per cell and pass");
      }
      return c->subdomain_index() != 0;
    };
  }

private:
  static constexpr std::size_t kLooksPerCheck = 1024;
  const RemeshSettings& settings_;
  std::size_t looks_ = 0;
  const std::size_t most_looks_;
};

/// One CGAL isotropic remeshing at `length` of the cells `selected` picks
/// (boundaries remeshed too, patch borders kept where they are).
template <class Selector> void remesh_pass(Triangulation& tr, double length, int iterations, Selector selected) {
  CGAL::tetrahedral_isotropic_remeshing(tr, length,
                                        CGAL::parameters::number_of_iterations(iterations)
                                            .remesh_boundaries(true)
                                            .smooth_constrained_edges(false)
                                            .cell_is_selected_map(selected));
}

/// `body` as a CGAL remeshing triangulation into `tr`: tet e in subdomain
/// `subdomain(e)` (0: outside, which CGAL leaves as it is), each boundary
/// face on its patch (boundary_patches, one per face into `patch`).
/// `handles[i + 1]` is node i's vertex. Returns the boundary tag of each
/// patch number.
template <class Subdomain>
std::vector<int> build(const mesh::TetMesh& body, const RemeshSettings& settings, Subdomain subdomain,
                       Triangulation& tr, std::vector<VertexHandle>& handles, std::vector<int>& patch) {
  std::vector<Triangulation::Point> points;
  points.reserve(body.nodes.size());
  for (const mesh::Point& x : body.nodes)
    points.emplace_back(x.x(), x.y(), x.z());
  std::vector<std::array<int, 5>> cells;
  cells.reserve(body.tets.size());
  for (std::size_t e = 0; e < body.tets.size(); ++e) {
    const mesh::Tet& t = body.tets[e];
    cells.push_back({t[0], t[1], t[2], t[3], subdomain(e)});
  }
  patch = boundary_patches(body, settings.feature_angle, kSmallestPatch * settings.edge_length * settings.edge_length);
  std::map<std::array<int, 3>, int> patch_of_facet;
  std::vector<int> tag_of_patch(1, 0);
  for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
    patch_of_facet[facet_key(body.boundary_faces[f])] = patch[f];
    if (patch[f] >= static_cast<int>(tag_of_patch.size())) tag_of_patch.resize(patch[f] + 1, 0);
    tag_of_patch[patch[f]] = body.boundary_tags[f];
  }
  if (!CGAL::build_triangulation<Triangulation, false>(tr, points, cells, patch_of_facet, handles)) {
    std::string why = mesh::manifold_fault(body);
    if (why.empty()) why = mesh::fault(body); // an inverted tet breaks the orientation CGAL checks
    throw RunError("remeshing: CGAL cannot build a triangulation from the body's tets (" +
                   (why.empty() ? std::string("is the body one piece without holes?") : why) + ")");
  }
  return tag_of_patch;
}

} // namespace

namespace {

/// remesh_body at settings.edge_length everywhere.
mesh::TetMesh remesh_uniform(const mesh::TetMesh& body, const RemeshSettings& settings) {
  const mesh::GridSnap on_grid(body, settings.grid);
  Triangulation tr;
  std::vector<VertexHandle> handles;
  std::vector<int> patch;
  const std::vector<int> tag_of_patch = build(
      on_grid.snapped(), settings, [](std::size_t) { return 1; }, tr, handles, patch);

  StoppableSelection selection(settings, tr);
  remesh_pass(tr, settings.edge_length, settings.iterations, selection.map());
  // Back to our mesh: the cells of the body (subdomain ≠ 0). CGAL's cell
  // order has no locality; the nodes are numbered along a Hilbert curve and
  // the elements sorted by their first node, so that neighbours in space are
  // neighbours in memory (assembly in chunks, matrix rows, multigrid).
  std::vector<Triangulation::Cell_handle> cells_out;
  std::vector<VertexHandle> vertices;
  std::unordered_map<VertexHandle, int> first_use;
  for (auto c : tr.finite_cell_handles()) {
    if (c->subdomain_index() == 0) continue;
    cells_out.push_back(c);
    for (int i = 0; i < 4; ++i)
      if (first_use.try_emplace(c->vertex(i), static_cast<int>(vertices.size())).second)
        vertices.push_back(c->vertex(i));
  }
  std::vector<Kernel::Point_3> locations;
  locations.reserve(vertices.size());
  for (VertexHandle v : vertices)
    locations.emplace_back(v->point().x(), v->point().y(), v->point().z());
  std::vector<std::size_t> order(vertices.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  CGAL::hilbert_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Kernel::Point_3>::type>(
                         CGAL::make_property_map(locations)));
  mesh::TetMesh out;
  std::unordered_map<VertexHandle, int> number;
  for (std::size_t k = 0; k < order.size(); ++k) {
    number.emplace(vertices[order[k]], static_cast<int>(k));
    const Kernel::Point_3& x = locations[order[k]];
    out.nodes.emplace_back(x.x(), x.y(), x.z());
  }
  auto node = [&](VertexHandle v) { return number.at(v); };
  std::vector<mesh::Triangle> tagged;
  std::vector<int> tags;
  for (auto c : cells_out) {
    out.tets.push_back({node(c->vertex(0)), node(c->vertex(1)), node(c->vertex(2)), node(c->vertex(3))});
    for (int i = 0; i < 4; ++i) {
      const int p = c->surface_patch_index(i);
      if (p <= 0) continue;
      tagged.push_back({node(c->vertex((i + 1) % 4)), node(c->vertex((i + 2) % 4)), node(c->vertex((i + 3) % 4))});
      tags.push_back(p < static_cast<int>(tag_of_patch.size()) ? tag_of_patch[p] : 0);
    }
  }
  std::stable_sort(out.tets.begin(), out.tets.end(), [](const mesh::Tet& a, const mesh::Tet& b) {
    return *std::min_element(a.begin(), a.end()) < *std::min_element(b.begin(), b.end());
  });
  mesh::build_boundary(out, tagged, tags);
  on_grid.restore(out);
  settle_on_old_surface(out, body, patch, tag_of_patch, std::vector<char>(out.nodes.size(), 1), mesh::volume(body),
                        settings.quality_floor);
  const double volume = mesh::volume(out);
  if (const int peeled = mesh::peel_boundary_slivers(out, kPeelShare * settings.quality_floor, settings.quality_floor);
      peeled > 0)
    log::info("    remeshing: %d flat tets on creases of the surface taken off (volume %+.2e %%)", peeled,
              100.0 * (mesh::volume(out) / volume - 1.0));
  // A flat tet the peel cannot take (all six edges on the surface: three of
  // its nodes nearly in a line on a patch border CGAL keeps, as on the hot
  // connecting rod's symmetry plane) is mended on the surface instead, by a
  // flip or a collapse of a surface edge.
  if (const SurfaceMending mended = mend_surface(out, {}, kPeelShare * settings.quality_floor, kFlatSurface);
      mended.flips + mended.collapses > 0)
    log::info("    remeshing: flat tets on the surface mended (%d edges flipped, %d collapsed; quality %.3g -> %.3g)",
              mended.flips, mended.collapses, mended.worst_before, mended.worst_after);
  // CGAL can join the two faces of a fin thinner than its elements at an
  // edge or a node (the connecting rod's flash near closure, at any size).
  if (const double before = mesh::volume(out); const int cut = mesh::cut_pinches(out))
    log::info("    remeshing: %d tets taken off where two parts of the surface touched (volume %+.2e %%)", cut,
              100.0 * (mesh::volume(out) / before - 1.0));
  if (const std::string why = mesh::fault(out); !why.empty()) throw RunError("remeshed body: " + why);
  return out;
}

} // namespace

RegionRemesh kept_part(const mesh::TetMesh& body, std::span<const char> rebuilt, RegionSurface surface,
                       std::vector<int>& number) {
  std::vector<char> stays(body.nodes.size(), 0);
  for (std::size_t e = 0; e < body.tets.size(); ++e)
    if (!rebuilt[e])
      for (int v : body.tets[e])
        stays[v] = 1;
  if (surface == RegionSurface::kept)
    for (const mesh::Triangle& f : body.boundary_faces)
      for (int v : f)
        stays[v] = 1;
  RegionRemesh out;
  number.assign(body.nodes.size(), -1);
  for (std::size_t i = 0; i < stays.size(); ++i)
    if (stays[i]) {
      number[i] = static_cast<int>(out.mesh.nodes.size());
      out.mesh.nodes.push_back(body.nodes[i]);
      out.old_node.push_back(static_cast<int>(i));
    }
  for (std::size_t e = 0; e < body.tets.size(); ++e)
    if (!rebuilt[e]) {
      mesh::Tet t = body.tets[e];
      for (int& v : t)
        v = number[v];
      out.mesh.tets.push_back(t);
    }
  out.kept_tets = out.mesh.tet_count();
  return out;
}

namespace {

/// remesh_region with CGAL given every tet of `body`.
RegionRemesh remesh_region_in(const mesh::TetMesh& body, std::span<const char> rebuilt, const RemeshSettings& settings,
                              RegionSurface surface, std::span<const char> pinned,
                              std::vector<std::array<int, 3>>* changed_border) {
  // The kept tets are outside for CGAL (subdomain 0): it changes the
  // region's inside only. With the surface kept every boundary is frozen,
  // the region's border with the kept tets included. With the surface
  // rebuilt the boundaries are remeshed, and the border with the kept tets
  // is held by making its edges constraints: their vertices become CGAL
  // corners (more than two constrained edges each), which no smoothing
  // moves and no collapse removes, and a constrained edge is not flipped.
  // CGAL may still split one longer than 4/3 of the length asked: that
  // border is then not the kept tets' any more, and the remesh is refused.
  const mesh::GridSnap on_grid(body, settings.grid);
  const mesh::TetMesh& given = on_grid.snapped(); // what CGAL is given
  Triangulation tr;
  std::vector<VertexHandle> handles;
  std::vector<int> patch;
  const std::vector<int> tag_of_patch = build(
      given, settings, [&](std::size_t e) { return rebuilt[e] ? 1 : 0; }, tr, handles, patch);
  const int n = body.node_count();
  // The border between the region and the kept tets, as sorted node triples.
  std::set<std::array<int, 3>> border;
  for (const mesh::InnerFace& f : mesh::inner_faces(body))
    if (rebuilt[f.tets[0]] != rebuilt[f.tets[1]]) border.insert(f.face);
  StoppableSelection selection(settings, tr);
  if (surface == RegionSurface::kept) {
    CGAL::tetrahedral_isotropic_remeshing(tr, settings.edge_length,
                                          CGAL::parameters::number_of_iterations(settings.iterations)
                                              .remesh_boundaries(false)
                                              .cell_is_selected_map(selection.map()));
  } else {
    // CGAL splits an edge longer than 4/3 of the length asked: the length
    // is raised so that no border edge is.
    double longest = 0.0;
    for (const std::array<int, 3>& f : border)
      for (int a = 0; a < 3; ++a)
        longest = std::max(longest, (given.nodes[f[a]] - given.nodes[f[(a + 1) % 3]]).norm());
    const double length = std::max(settings.edge_length, kBorderMargin * 0.75 * longest);
    if (length > settings.edge_length)
      log::detail("    local remesh at %.3g mm (asked %.3g): its border with the kept elements has an edge of %.3g mm",
                  length, settings.edge_length, longest);
    using Edge = std::pair<VertexHandle, VertexHandle>;
    std::unordered_set<Edge, boost::hash<Edge>> constrained;
    for (const std::array<int, 3>& f : border)
      for (int a = 0; a < 3; ++a) {
        VertexHandle v = handles[f[a] + 1], w = handles[f[(a + 1) % 3] + 1];
        constrained.insert(w < v ? Edge(w, v) : Edge(v, w));
      }
    if (!pinned.empty())
      for (const mesh::Triangle& f : body.boundary_faces)
        for (int a = 0; a < 3; ++a)
          if (pinned[f[a]] && pinned[f[(a + 1) % 3]]) {
            VertexHandle v = handles[f[a] + 1], w = handles[f[(a + 1) % 3] + 1];
            constrained.insert(w < v ? Edge(w, v) : Edge(v, w));
          }
    CGAL::tetrahedral_isotropic_remeshing(tr, length,
                                          CGAL::parameters::number_of_iterations(settings.iterations)
                                              .remesh_boundaries(true)
                                              .smooth_constrained_edges(false)
                                              .edge_is_constrained_map(CGAL::Boolean_property_map(constrained))
                                              .cell_is_selected_map(selection.map()));
  }

  // The nodes that stay, which CGAL could not move or remove: their handles live on.
  std::vector<int> kept_number;
  RegionRemesh out = kept_part(body, rebuilt, surface, kept_number);
  std::unordered_map<VertexHandle, int> number;
  // A region node CGAL left where it was keeps its number in the body.
  std::unordered_map<VertexHandle, int> original;
  for (int i = 0; i < n; ++i)
    if (kept_number[i] >= 0)
      number.emplace(handles[i + 1], kept_number[i]);
    else
      original.emplace(handles[i + 1], i);
  // The new region: its new vertices after the kept ones, its tets after the kept tets.
  std::vector<mesh::Triangle> tagged;
  std::vector<int> tags;
  std::size_t border_faces = 0;
  for (auto c : tr.finite_cell_handles()) {
    if (c->subdomain_index() == 0) continue;
    mesh::Tet t;
    for (int i = 0; i < 4; ++i) {
      const auto [it, added] = number.try_emplace(c->vertex(i), static_cast<int>(out.mesh.nodes.size()));
      if (added) {
        const auto& x = c->vertex(i)->point();
        const mesh::Point at(x.x(), x.y(), x.z());
        const auto was = original.find(c->vertex(i));
        const bool unmoved = was != original.end() && given.nodes[was->second] == at;
        out.mesh.nodes.push_back(unmoved ? body.nodes[was->second] : at);
        out.old_node.push_back(unmoved ? was->second : -1);
      }
      t[i] = it->second;
    }
    out.mesh.tets.push_back(t);
    if (surface == RegionSurface::kept) continue;
    for (int i = 0; i < 4; ++i) {
      const VertexHandle a = c->vertex((i + 1) % 4), b = c->vertex((i + 2) % 4), d = c->vertex((i + 3) % 4);
      if (c->neighbor(i)->subdomain_index() != 0) continue;
      std::array<int, 3> key{-1, -1, -1};
      const int pa = number.at(a), pb = number.at(b), pd = number.at(d);
      if (out.old_node[pa] >= 0 && out.old_node[pb] >= 0 && out.old_node[pd] >= 0) {
        key = {out.old_node[pa], out.old_node[pb], out.old_node[pd]};
        std::sort(key.begin(), key.end());
      }
      if (border.erase(key) > 0) {
        ++border_faces;
        continue;
      }
      const int p = c->surface_patch_index(i);
      tagged.push_back({pa, pb, pd});
      tags.push_back(p > 0 && p < static_cast<int>(tag_of_patch.size()) ? tag_of_patch[p] : 0);
    }
  }
  if (surface == RegionSurface::kept) {
    // The boundary is the body's, face for face.
    for (const mesh::Triangle& f : body.boundary_faces)
      tagged.push_back({number.at(handles[f[0] + 1]), number.at(handles[f[1] + 1]), number.at(handles[f[2] + 1])});
    tags = body.boundary_tags;
  } else {
    if (!border.empty()) {
      if (changed_border) changed_border->assign(border.begin(), border.end());
      throw RunError("locally remeshed body: CGAL changed " + std::to_string(border.size()) + " of the " +
                     std::to_string(border.size() + border_faces) +
                     " faces of the region's border with the kept elements");
    }
    // The kept tets' faces on the body's surface keep their tags.
    std::map<std::array<int, 3>, int> tag_of;
    for (std::size_t f = 0; f < body.boundary_faces.size(); ++f) {
      std::array<int, 3> key = body.boundary_faces[f];
      std::sort(key.begin(), key.end());
      tag_of.emplace(key, body.boundary_tags[f]);
    }
    for (int e = 0; e < out.kept_tets; ++e)
      for (const auto& fv : mesh::kFaceVertices) {
        const mesh::Tet& t = out.mesh.tets[e];
        std::array<int, 3> key{out.old_node[t[fv[0]]], out.old_node[t[fv[1]]], out.old_node[t[fv[2]]]};
        std::sort(key.begin(), key.end());
        if (const auto it = tag_of.find(key); it != tag_of.end()) {
          tagged.push_back({t[fv[0]], t[fv[1]], t[fv[2]]});
          tags.push_back(it->second);
        }
      }
  }
  mesh::build_boundary(out.mesh, tagged, tags);
  if (out.mesh.boundary_faces.size() != tagged.size())
    throw RunError("locally remeshed body: its rebuilt region does not fit the kept elements");
  if (surface == RegionSurface::rebuilt) {
    std::vector<char> movable(out.mesh.nodes.size(), 0);
    for (std::size_t v = 0; v < movable.size(); ++v)
      movable[v] = out.old_node[v] < 0;
    settle_on_old_surface(out.mesh, body, patch, tag_of_patch, movable, mesh::volume(body), settings.quality_floor);
  }
  // CGAL leaves flat tets of four border nodes, which it may not move,
  // where the border is planar (near closure on the adaptive hot connecting
  // rod, in most levels).
  if (const int mended = mesh::mend_flat_tets(out.mesh, out.kept_tets, kPeelShare * settings.quality_floor);
      mended > 0) {
    out.old_node.resize(out.mesh.nodes.size(), -1);
    log::detail("    remeshing: %d flat tets taken out of a rebuilt region", mended);
  }
  if (const std::string why = mesh::fault(out.mesh); !why.empty()) throw RunError("locally remeshed body: " + why);
  return out;
}

} // namespace

RegionRemesh remesh_region(const mesh::TetMesh& body, std::span<const char> rebuilt, const RemeshSettings& settings,
                           RegionSurface surface, std::span<const char> pinned,
                           std::vector<std::array<int, 3>>* changed_border) {
  // Only inside a kept surface: there the window gave the same meshes as
  // the whole body (closed_die_flash's local remeshes, bit for bit). With
  // the surface rebuilt CGAL meets the cells in another order and makes
  // another mesh (a level of the flash billet's adaptive remesh: worst
  // quality 0.18 after the levels, against 0.22).
  const std::optional<RegionWindow> window =
      surface == RegionSurface::kept ? region_window(body, rebuilt) : std::nullopt;
  if (!window) return remesh_region_in(body, rebuilt, settings, surface, pinned, changed_border);
  // With the surface kept nothing is pinned (it all stays) and the border
  // cannot change (all of it is frozen).
  return merge_window(body, rebuilt, *window,
                      remesh_region_in(window->soup, window->rebuilt, settings, surface, {}, nullptr));
}

mesh::TetMesh remesh_body(const mesh::TetMesh& body, const RemeshSettings& settings) {
  mesh::TetMesh out = remesh_uniform(body, settings);
  if (!settings.size) return out;
  // CGAL 5.5 meets one length per call and remeshes unselected cells too
  // (docs/libraries.md §2): the finer levels are regions of their own,
  // each the cells whose centroid wants less than the geometric mean of the
  // level before and this one, rebuilt at a length ¾ of the level before
  // with their border to the rest frozen.
  const double border_splits = 1.0 / (kBorderMargin * 0.75); // remesh_region's border limit over its length
  double previous_level = settings.edge_length;
  auto out_of_time = [&] {
    log::info("    remeshing: the size field's finer levels stopped at %.3g mm (smallest asked %.3g mm): the "
              "remesh ran out of remeshing.time_limit",
              previous_level, settings.smallest_edge_length);
  };
  while (previous_level > settings.smallest_edge_length * (1.0 + 1e-9)) {
    if (std::chrono::steady_clock::now() > settings.deadline) {
      out_of_time();
      break;
    }
    RemeshSettings at_level = settings;
    at_level.edge_length = finer_level(previous_level, settings.smallest_edge_length);
    std::vector<char> region = level_cells(out, settings.size, previous_level, at_level.edge_length);
    if (std::find(region.begin(), region.end(), 1) == region.end()) break;
    // A border face CGAL changed anyway (a few in thousands) takes the kept
    // tets on it into the region, and the level is tried again.
    std::optional<RegionRemesh> level;
    std::vector<std::array<int, 3>> changed;
    for (int attempt = 0; attempt < kLevelAttempts && !level; ++attempt) {
      // CGAL would split the border's edges longer than its limit, which the
      // region's remesh refuses: they are bisected first, on both sides.
      for (int pass = 0; pass < kBorderPasses; ++pass) {
        const std::vector<std::array<int, 2>> long_edges =
            long_border_edges(out, region, border_splits * at_level.edge_length);
        if (long_edges.empty()) break;
        mesh::carry_to_halves(mesh::bisect_edges(out, long_edges), region);
      }
      changed.clear();
      try {
        level = remesh_region(out, region, at_level, RegionSurface::rebuilt, {}, &changed);
      } catch (const RemeshStopped& stopped) {
        if (!stopped.out_of_time) throw;
        out_of_time(); // the mesh stays at the last level made
        break;
      } catch (const RunError& error) {
        if (attempt + 1 == kLevelAttempts) {
          log::info("    remeshing: the size field's finer levels stopped at %.3g mm (smallest asked %.3g mm): %s",
                    previous_level, settings.smallest_edge_length, error.what());
          break;
        }
        if (changed.empty()) {
          // A degenerate or inverted result: CGAL splits and collapses
          // elsewhere at another length, as for the whole body's tries.
          log::detail("    remeshing: the level at %.3g mm failed (%s); tried again at %.3g mm", at_level.edge_length,
                      error.what(), kLevelRetryScale * at_level.edge_length);
          at_level.edge_length *= kLevelRetryScale;
          continue;
        }
        log::detail("    remeshing: the level at %.3g mm remade, its region grown over the %zu border faces CGAL "
                    "changed",
                    at_level.edge_length, changed.size());
        const std::set<std::array<int, 3>> faces(changed.begin(), changed.end());
        for (int e = 0; e < out.tet_count(); ++e)
          for (const auto& fv : mesh::kFaceVertices) {
            std::array<int, 3> key{out.tets[e][fv[0]], out.tets[e][fv[1]], out.tets[e][fv[2]]};
            std::sort(key.begin(), key.end());
            if (faces.count(key) > 0) region[e] = 1;
          }
      }
    }
    if (!level) break;
    out = std::move(level->mesh);
    previous_level = at_level.edge_length;
  }
  // Between two levels the cells on the coarse side keep the border the fine
  // side was made on, and some are poor: they and a layer around them are
  // rebuilt inside the surface at their own length, taken when that helps.
  const double worst = worst_quality(out);
  if (worst >= kPoorAfterLevels) return out;
  std::vector<char> poor(out.tets.size(), 0);
  for (int e = 0; e < out.tet_count(); ++e)
    poor[e] = mesh::quality(out, e) < kPoorAfterLevels;
  poor = grow_region(out, std::move(poor), 1);
  RemeshSettings inside = settings;
  inside.edge_length = mean_edge_length(out, poor);
  try {
    RegionRemesh mended = remesh_region(out, poor, inside, RegionSurface::kept);
    if (worst_quality(mended.mesh) > worst) out = std::move(mended.mesh);
  } catch (const RemeshStopped& stopped) {
    if (!stopped.out_of_time) throw;
  } catch (const RunError&) {
    // The levels' mesh stands: its worst is what the caller's checks judge.
  }
  return out;
}

} // namespace anvil::remesh
