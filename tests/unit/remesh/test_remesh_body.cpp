// remesh_body: a new mesh of the same volume, tags kept on flat faces.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/grid_snap.h"
#include "anvil/mesh/manifold.h"
#include "anvil/mesh/node_budget.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/expected_nodes.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/region_window.h"
#include "anvil/remesh/remesh_body.h"
#include "shaken_mesh.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <stop_token>

using namespace anvil;

namespace {
/// Tags present on the boundary of `m`.
std::set<int> tags_of(const mesh::TetMesh& m) {
  return {m.boundary_tags.begin(), m.boundary_tags.end()};
}
/// Checks that the tets of `body` not `rebuilt` are `out`'s first tets, in
/// order, on the same nodes with the same coordinates bit for bit.
void check_kept_bit_for_bit(const mesh::TetMesh& body, const std::vector<char>& rebuilt,
                            const remesh::RegionRemesh& out) {
  int kept = 0;
  for (int e = 0; e < body.tet_count(); ++e) {
    if (rebuilt[e]) continue;
    REQUIRE(kept < out.kept_tets);
    for (int a = 0; a < 4; ++a) {
      const int node = out.mesh.tets[kept][a];
      CHECK(out.old_node[node] == body.tets[e][a]);
      CHECK(out.mesh.nodes[node] == body.nodes[body.tets[e][a]]);
    }
    ++kept;
  }
  CHECK(kept == out.kept_tets);
}
/// A box whose interior nodes near x = 0 are squeezed towards the plane
/// x = 2 (poor elements there).
mesh::TetMesh squeezed_box() {
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 1.0);
  const std::vector<char> on_boundary = mesh::boundary_node_flags(box);
  for (std::size_t n = 0; n < box.nodes.size(); ++n)
    if (!on_boundary[n] && box.nodes[n].x() < 2.5) box.nodes[n].x() = 2.0 + 0.2 * (box.nodes[n].x() - 2.0);
  return box;
}
} // namespace

TEST_CASE("Remeshing a box keeps its volume, faces and tags", "[unit][remesh]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 2.0);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const mesh::TetMesh out = remesh::remesh_body(box, settings);
  CHECK(out.tet_count() > 2 * box.tet_count()); // refined: h 2 → 1
  // Flat faces marked as patches: the volume is kept to round-off (docs/libraries.md §2: 1.000).
  CHECK(mesh::volume(out) == Approx(240.0).epsilon(1e-9));
  CHECK(tags_of(out) == std::set<int>{1, 2, 3, 4, 5, 6});
  // Every face keeps its tag: its nodes lie on the plane the tag names.
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f) {
    const int tag = out.boundary_tags[f];
    const int axis = (tag - 1) / 2;
    const double plane = tag % 2 == 1 ? 0.0 : std::array<double, 3>{10, 6, 4}[axis];
    for (int n : out.boundary_faces[f])
      CHECK(out.nodes[n][axis] == Approx(plane).margin(1e-9));
  }
  CHECK(remesh::worst_quality(out) > 0.1);
}

TEST_CASE("Remeshing a quarter cylinder keeps its volume and its lateral surface", "[unit][remesh]") {
  const double radius = 10.0, h_old = 1.5;
  const mesh::TetMesh body = mesh::make_quarter_cylinder(radius, 15.0, h_old);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const mesh::TetMesh out = remesh::remesh_body(body, settings);
  // The lateral nodes are shifted along their normal to restore the volume.
  CHECK(mesh::volume(out) == Approx(mesh::volume(body)).epsilon(1e-9));
  CHECK(tags_of(out) == tags_of(body));
  // ... by about the chord error of the facets, so they stay on the cylinder
  // to within the sagitta of the old facets, h²/8R = 0.028 mm.
  const double sagitta = h_old * h_old / (8.0 * radius);
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f)
    if (out.boundary_tags[f] == 2)
      for (int n : out.boundary_faces[f])
        CHECK(out.nodes[n].head<2>().norm() == Approx(radius).margin(sagitta));
  // The node estimate a remesh makes before CGAL runs (the node budget)
  // holds within 20 %: its fit's worst over the bodies of tools/remesh_nodes
  // is 12 %, and the mesh CGAL starts from moves the count by 7 % more (this
  // body: 2761 nodes from a mesh at 1.0 mm there, 2943 from this one at 1.5).
  const double estimate = mesh::remeshed_nodes(mesh::volume(out), mesh::boundary_area(out), 1.0);
  INFO("nodes " << out.node_count() << ", estimated " << estimate);
  CHECK(std::abs(out.node_count() / estimate - 1.0) < 0.2);
}

TEST_CASE("A surface patch of a few crumpled faces joins its neighbour, and the faces of a box stay apart",
          "[unit][remesh]") {
  // A box whose top node nearest (5, 3, 4) is pulled 1.5 mm up: the faces
  // around it tilt by about 60°, more than the feature angle.
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 1.0);
  int bump = -1;
  for (int n = 0; n < box.node_count(); ++n)
    if (bump < 0 || (box.nodes[n] - mesh::Point(5, 3, 4)).norm() < (box.nodes[bump] - mesh::Point(5, 3, 4)).norm())
      bump = n;
  REQUIRE(box.nodes[bump].z() == 4.0);
  box.nodes[bump].z() += 1.5;
  auto patches_of = [&](double smallest_area) {
    const std::vector<int> patch = remesh::boundary_patches(box, 40.0, smallest_area);
    return std::set<int>(patch.begin(), patch.end()).size();
  };
  CHECK(patches_of(0.0) > 6);   // the bump's faces on patches of their own
  CHECK(patches_of(10.0) == 6); // joined to the top (about 5 mm² of them), the faces (24 mm² and more) not
  // Faces of different tags never join, however small the limit makes them.
  CHECK(patches_of(1e9) == 6);
  // The bump's faces took the top's patch: the faces around the bumped node share it with those far from it.
  const std::vector<int> patch = remesh::boundary_patches(box, 40.0, 10.0);
  std::set<int> top;
  for (std::size_t f = 0; f < box.boundary_faces.size(); ++f) {
    const mesh::Triangle& t = box.boundary_faces[f];
    if (std::all_of(t.begin(), t.end(), [&](int v) { return box.nodes[v].z() >= 4.0; })) top.insert(patch[f]);
  }
  CHECK(top.size() == 1);
}

TEST_CASE("An adaptive size field refines where it asks and keeps the volume", "[unit][remesh]") {
  // The flash case's billet; edges of 0.525 mm wanted below z = 4 mm,
  // growing by 0.5 mm per mm above, up to the coarse 1.05 mm from z = 5.05.
  const mesh::TetMesh body = mesh::make_quarter_cylinder(8.0, 15.7, 1.0);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.05;
  settings.smallest_edge_length = 0.525;
  settings.size = [](const mesh::Point& x) { return std::clamp(0.525 + 0.5 * (x.z() - 4.0), 0.525, 1.05); };
  const mesh::TetMesh out = remesh::remesh_body(body, settings);
  // Mean length of the element edges wholly below z = 3 and wholly above z = 7.
  double fine = 0.0, coarse = 0.0;
  int fine_count = 0, coarse_count = 0;
  for (const mesh::Tet& t : out.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double length = (out.nodes[t[a]] - out.nodes[t[b]]).norm();
        const double z = std::max(out.nodes[t[a]].z(), out.nodes[t[b]].z());
        if (z < 3.0) fine += length, ++fine_count;
        if (std::min(out.nodes[t[a]].z(), out.nodes[t[b]].z()) > 7.0) coarse += length, ++coarse_count;
      }
  // CGAL keeps edges within 4/5 to 4/3 of its target (measured 0.52 and 1.01 mm).
  CHECK(fine / fine_count == Approx(0.525).epsilon(0.15));
  CHECK(coarse / coarse_count == Approx(1.05).epsilon(0.15));
  CHECK(mesh::volume(out) == Approx(mesh::volume(body)).epsilon(1e-9));
  CHECK(tags_of(out) == tags_of(body));
  // Measured worst 0.26 (uniform: 0.27). Without the last pass over poor
  // cells 0.16, with one step of ½ instead of ¾ steps 0.08.
  CHECK(remesh::worst_quality(out) > 0.2);
  // The node estimate made before CGAL runs (the node budget) holds here as
  // on the graded bodies of tools/remesh_nodes (worst 12 %), a body its fit
  // did not see, within the 20 % of the uniform estimate's test above
  // (measured 4,509 against 4,635 nodes), and nearer than the sizes asked
  // alone, without the levels' borders (4,081).
  const double estimate = remesh::expected_nodes(body, settings.size, 1.05, 0.525).at(1.0);
  const double asked = remesh::expected_nodes(body, settings.size, 1.05, 1.05).at(1.0);
  INFO("nodes " << out.node_count() << ", estimated " << estimate << ", at the sizes asked " << asked);
  CHECK(std::abs(out.node_count() / estimate - 1.0) < 0.2);
  CHECK(std::abs(out.node_count() - estimate) < std::abs(out.node_count() - asked));
}

TEST_CASE("A local remesh rebuilds its region only: the rest keeps its nodes and elements bit for bit",
          "[unit][remesh]") {
  // The squeezed box; the tets with a centroid below x = 3 are rebuilt.
  const mesh::TetMesh box = squeezed_box();
  std::vector<char> rebuilt(box.tets.size(), 0);
  double worst_before = 1.0;
  for (int e = 0; e < box.tet_count(); ++e)
    if (mesh::centroid(box, e).x() < 3.0) {
      rebuilt[e] = 1;
      worst_before = std::min(worst_before, mesh::quality(box, e));
    }
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const remesh::RegionRemesh out = remesh::remesh_region(box, rebuilt, settings);

  // The kept tets: the same, in order, on the same coordinates.
  check_kept_bit_for_bit(box, rebuilt, out);
  // The surface: every boundary face of the box, on the same nodes.
  CHECK(out.mesh.boundary_faces.size() == box.boundary_faces.size());
  for (std::size_t n = 0; n < out.mesh.nodes.size(); ++n)
    if (out.old_node[n] >= 0) CHECK(out.mesh.nodes[n] == box.nodes[out.old_node[n]]);
  // The same volume (the boundary did not move), a conforming mesh
  // (validate ran), better elements in the region.
  CHECK(mesh::volume(out.mesh) == Approx(240.0).epsilon(1e-12));
  double worst_after = 1.0;
  for (int e = out.kept_tets; e < out.mesh.tet_count(); ++e)
    worst_after = std::min(worst_after, mesh::quality(out.mesh, e));
  INFO("worst quality in the region " << worst_before << " -> " << worst_after);
  CHECK(worst_after > 2.0 * worst_before);
}

TEST_CASE("A local remesh with its surface rebuilt keeps the rest and its border bit for bit, the volume and the "
          "pinned nodes",
          "[unit][remesh]") {
  // A box whose nodes near x = 0 (surface nodes too, within their faces'
  // planes) are squeezed towards x = 2. The tets with a centroid below
  // x = 3 are rebuilt, the top face's nodes from x = 2.5 on pinned.
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 1.0);
  for (mesh::Point& x : box.nodes)
    if (x.x() > 0.0 && x.x() < 2.5) x.x() = 2.0 + 0.05 * (x.x() - 2.0);
  std::vector<char> rebuilt(box.tets.size(), 0), pinned(box.nodes.size(), 0);
  for (int e = 0; e < box.tet_count(); ++e)
    rebuilt[e] = mesh::centroid(box, e).x() < 3.0;
  for (std::size_t n = 0; n < box.nodes.size(); ++n)
    pinned[n] = box.nodes[n].z() == 4.0 && box.nodes[n].x() >= 2.5; // the top face, as if on a die
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  auto worst_rebuilt = [](const mesh::TetMesh& m, int from) {
    double worst = 1.0;
    for (int e = from; e < m.tet_count(); ++e)
      worst = std::min(worst, mesh::quality(m, e));
    return worst;
  };
  const remesh::RegionRemesh frozen = remesh::remesh_region(box, rebuilt, settings);
  const remesh::RegionRemesh out =
      remesh::remesh_region(box, rebuilt, settings, remesh::RegionSurface::rebuilt, pinned);

  check_kept_bit_for_bit(box, rebuilt, out);
  // Pinned nodes kept where they were; every node with an old number unmoved.
  for (std::size_t n = 0; n < box.nodes.size(); ++n)
    if (pinned[n]) CHECK(std::count(out.old_node.begin(), out.old_node.end(), int(n)) == 1);
  for (std::size_t n = 0; n < out.mesh.nodes.size(); ++n)
    if (out.old_node[n] >= 0) CHECK(out.mesh.nodes[n] == box.nodes[out.old_node[n]]);
  // The same box: its volume, its six tags, every boundary node on its faces.
  CHECK(mesh::volume(out.mesh) == Approx(240.0).epsilon(1e-12));
  CHECK(tags_of(out.mesh) == tags_of(box));
  for (const mesh::Triangle& f : out.mesh.boundary_faces)
    for (int v : f) {
      const mesh::Point& x = out.mesh.nodes[v];
      const double off = std::min({x.x(), 10 - x.x(), x.y(), 6 - x.y(), x.z(), 4 - x.z()});
      CHECK(std::abs(off) < 1e-12);
    }
  // The region's surface was rebuilt: new boundary nodes (the frozen remesh has none).
  const std::vector<char> on_boundary = mesh::boundary_node_flags(out.mesh);
  int new_on_boundary = 0;
  for (std::size_t n = 0; n < out.mesh.nodes.size(); ++n)
    new_on_boundary += on_boundary[n] && out.old_node[n] < 0;
  INFO("worst quality in the region: surface kept " << worst_rebuilt(frozen.mesh, frozen.kept_tets) << ", rebuilt "
                                                    << worst_rebuilt(out.mesh, out.kept_tets));
  CHECK(new_on_boundary > 0);
  CHECK(worst_rebuilt(out.mesh, out.kept_tets) > 0.0);
}

TEST_CASE("A remesh past its deadline or asked to stop stops inside CGAL's pass", "[unit][remesh]") {
  // CGAL 5.5 has no way to stop a pass; the selection it asks at every cell
  // throws. A deadline already passed or a stop already asked stops the
  // pass at its first check, 1024 looks in; the box at h 1 needs far more.
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 2.0);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  settings.deadline = std::chrono::steady_clock::now();
  const std::vector<char> all(box.tets.size(), 1);
  auto stopped_for = [&](auto&& remesh) {
    try {
      remesh();
    } catch (const remesh::RemeshStopped& stopped) {
      return stopped.out_of_time ? 1 : 2;
    }
    return 0;
  };
  CHECK(stopped_for([&] { remesh::remesh_body(box, settings); }) == 1);
  CHECK(stopped_for([&] { remesh::remesh_region(box, all, settings); }) == 1);
  std::stop_source stop;
  stop.request_stop();
  settings.deadline = std::chrono::steady_clock::time_point::max();
  settings.stop = stop.get_token();
  CHECK(stopped_for([&] { remesh::remesh_body(box, settings); }) == 2);
  // Neither asked: the same remesh runs to its end.
  settings.stop = {};
  CHECK(stopped_for([&] { remesh::remesh_body(box, settings); }) == 0);
}

TEST_CASE("A CGAL pass that looks at its cells more often than any pass that ends fails", "[unit][remesh]") {
  // The count is checked every 1024 looks: at one look per cell and pass the
  // box's first check is past it. A failure, not a stop: the caller tries
  // another length or the whole body.
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 2.0);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  settings.most_looks_per_cell_pass = 1;
  const std::vector<char> all(box.tets.size(), 1);
  CHECK_THROWS_WITH(remesh::remesh_body(box, settings), Catch::Contains("CGAL's remeshing stalled"));
  CHECK_THROWS_WITH(remesh::remesh_region(box, all, settings), Catch::Contains("CGAL's remeshing stalled"));
  settings.most_looks_per_cell_pass = remesh::RemeshSettings{}.most_looks_per_cell_pass;
  CHECK_NOTHROW(remesh::remesh_body(box, settings));
}

TEST_CASE("A region inside a kept surface is remeshed in a window cut out of the body and put back whole",
          "[unit][remesh]") {
  // The box of the local remesh above, squeezed near x = 0, its tets with a
  // centroid below x = 3 rebuilt: with a layer around them they are a ball
  // under half the box, cut out and remeshed alone. The result is the box
  // with the region rebuilt, as remesh_region's contract says: kept tets bit
  // for bit first, the surface face for face, the volume.
  const mesh::TetMesh box = squeezed_box();
  std::vector<char> rebuilt(box.tets.size(), 0);
  for (int e = 0; e < box.tet_count(); ++e)
    rebuilt[e] = mesh::centroid(box, e).x() < 3.0;
  const std::optional<remesh::RegionWindow> window = remesh::region_window(box, rebuilt);
  REQUIRE(window);
  CHECK(window->soup.tet_count() < box.tet_count() / 2);
  CHECK(mesh::is_ball(window->soup));
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const remesh::RegionRemesh out = remesh::remesh_region(box, rebuilt, settings);
  check_kept_bit_for_bit(box, rebuilt, out);
  CHECK(out.mesh.boundary_faces.size() == box.boundary_faces.size());
  CHECK(tags_of(out.mesh) == tags_of(box));
  CHECK(mesh::volume(out.mesh) == Approx(240.0).epsilon(1e-12));
  CHECK(mesh::manifold_fault(out.mesh).empty());
  // A region through the box from face to face, with its layer, is over half of it: no window.
  std::vector<char> slab(box.tets.size(), 0);
  for (int e = 0; e < box.tet_count(); ++e)
    slab[e] = mesh::centroid(box, e).x() < 6.0;
  CHECK_FALSE(remesh::region_window(box, slab));
}

TEST_CASE("Two meshes of a body that differ by round-off are remeshed alike on the grid", "[unit][remesh]") {
  // The squeezed box as two process counts would carry it: every coordinate
  // apart by up to 1e-9 mm. On the grid (mesh/grid_snap.h) CGAL is given
  // the same numbers for both, and makes the same mesh, whole and local;
  // the nodes it left where they were keep their own coordinates.
  const mesh::TetMesh one = shaken(squeezed_box(), 1e-9, 1), other = shaken(squeezed_box(), 1e-9, 2);
  remesh::RemeshSettings settings;
  settings.grid = {mesh::snap_spacing(1.0), 0.0};
  settings.edge_length = 0.8;
  const mesh::TetMesh whole = remesh::remesh_body(one, settings), whole_other = remesh::remesh_body(other, settings);
  CHECK(whole.tets == whole_other.tets);
  double apart = 0.0; // the nodes: the same, but for what settles onto each body's own surface
  for (std::size_t n = 0; n < whole.nodes.size() && whole.nodes.size() == whole_other.nodes.size(); ++n)
    apart = std::max(apart, (whole.nodes[n] - whole_other.nodes[n]).norm());
  CHECK(whole.nodes.size() == whole_other.nodes.size());
  CHECK(apart < 1e-8);

  std::vector<char> rebuilt(one.tets.size(), 0);
  for (int e = 0; e < one.tet_count(); ++e)
    rebuilt[e] = mesh::centroid(one, e).x() < 3.0;
  settings.edge_length = 1.0;
  const remesh::RegionRemesh local = remesh::remesh_region(one, rebuilt, settings);
  const remesh::RegionRemesh local_other = remesh::remesh_region(other, rebuilt, settings);
  CHECK(local.mesh.tets == local_other.mesh.tets);
  check_kept_bit_for_bit(one, rebuilt, local);
  for (std::size_t n = 0; n < local.mesh.nodes.size(); ++n)
    if (local.old_node[n] >= 0) CHECK(local.mesh.nodes[n] == one.nodes[local.old_node[n]]);
  CHECK(mesh::volume(local.mesh) == Approx(mesh::volume(one)).epsilon(1e-12));
}
