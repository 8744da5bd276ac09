// Field transfer between two meshes of the same box.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/field_transfer.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace anvil;

TEST_CASE("Linear nodal fields are interpolated exactly", "[unit][remesh]") {
  const mesh::TetMesh old_mesh = mesh::make_box({0, 0, 0}, {4, 3, 2}, 1.0);
  mesh::TetMesh new_mesh = mesh::make_box({0, 0, 0}, {4, 3, 2}, 0.7);
  // A new boundary node a hair outside the old mesh still gets a location.
  new_mesh.nodes[0] -= mesh::Point(1e-7, 1e-7, 1e-7);
  const auto linear = [](const mesh::Point& x) { return Eigen::Vector2d(1.0 + 2.0 * x.x() - x.y(), 3.0 * x.z()); };
  Eigen::VectorXd old_values(2 * old_mesh.node_count());
  for (int i = 0; i < old_mesh.node_count(); ++i)
    old_values.segment<2>(2 * i) = linear(old_mesh.nodes[i]);
  const remesh::PointLocator in_old(old_mesh);
  const std::vector<remesh::Location> at = in_old.locate(new_mesh.nodes);
  const Eigen::VectorXd values = remesh::interpolate_nodal(old_mesh, old_values, 2, at);
  for (int i = 0; i < new_mesh.node_count(); ++i) {
    const Eigen::Vector2d expected = linear(new_mesh.nodes[i]);
    CHECK(values[2 * i] == Approx(expected[0]).margin(1e-6)); // 1e-7 outside, slope 2
    CHECK(values[2 * i + 1] == Approx(expected[1]).margin(1e-6));
  }
}

TEST_CASE("Element fields are remapped conservatively, exactly for a linear field inside", "[unit][remesh]") {
  // f = x at the old centroids (0.5 mm), onto a 0.625 mm mesh of the same box.
  const mesh::TetMesh old_mesh = mesh::make_box({0, 0, 0}, {5, 5, 5}, 0.5);
  const mesh::TetMesh new_mesh = mesh::make_box({0, 0, 0}, {5, 5, 5}, 0.625);
  const std::vector<mesh::Point> old_centres = remesh::centroids(old_mesh), new_centres = remesh::centroids(new_mesh);
  std::vector<double> f;
  for (const mesh::Point& c : old_centres)
    f.push_back(c.x());
  const remesh::PointLocator in_old(old_mesh);
  const std::vector<double> moved = remesh::remap_element(old_mesh, f, in_old, new_mesh);
  // Same domain: ∫ f dV is kept to rounding.
  CHECK(remesh::integral(new_mesh, moved) == Approx(remesh::integral(old_mesh, f)).epsilon(1e-12));
  // Never outside the old range (the limiter; at the boundary it clips).
  for (double v : moved) {
    CHECK(v >= *std::min_element(f.begin(), f.end()) - 1e-12);
    CHECK(v <= *std::max_element(f.begin(), f.end()) + 1e-12);
  }
  // Exact (the mean of x is x at the centroid) for a new element more than
  // one old element's diameter (0.87 mm) from the boundary: the old elements
  // it overlaps have no boundary node, so their limiter stays off.
  int inside = 0;
  for (int n = 0; n < new_mesh.tet_count(); ++n) {
    bool deep = true;
    for (int v : new_mesh.tets[n])
      deep = deep && new_mesh.nodes[v].minCoeff() > 0.9 && new_mesh.nodes[v].maxCoeff() < 4.1;
    if (!deep) continue;
    ++inside;
    CHECK(moved[n] == Approx(new_centres[n].x()).margin(1e-12));
  }
  CHECK(inside == 4 * 4 * 4 * 6); // the inner 4×4×4 cells, six tets each
}

TEST_CASE("A peak smaller than the new elements keeps its value", "[unit][remesh]") {
  // One element of a 0.5 mm mesh at ε̄ 2, the rest at 1, onto a 1.3 mm mesh.
  const mesh::TetMesh old_mesh = mesh::make_box({0, 0, 0}, {4, 3, 2}, 0.5);
  const mesh::TetMesh new_mesh = mesh::make_box({0, 0, 0}, {4, 3, 2}, 1.3);
  const std::vector<mesh::Point> old_centres = remesh::centroids(old_mesh);
  std::vector<double> strain(old_centres.size(), 1.0);
  const mesh::Point inside(2.1, 1.6, 1.1); // away from the boundary and from the new mesh's nodes
  const auto peak =
      std::min_element(old_centres.begin(), old_centres.end(), [&](const mesh::Point& a, const mesh::Point& b) {
        return (a - inside).norm() < (b - inside).norm();
      });
  strain[peak - old_centres.begin()] = 2.0;
  const remesh::PointLocator in_old(old_mesh);
  const std::vector<double> remapped = remesh::remap_element(old_mesh, strain, in_old, new_mesh);
  const std::vector<double> moved = remesh::transfer_element(old_mesh, strain, in_old, new_mesh);
  // The remap alone averages the peak over larger elements.
  CHECK(*std::max_element(remapped.begin(), remapped.end()) < 1.2);
  // With the peak kept: in exactly one new element, the only one changed;
  // ∫ε̄ gains that element's rise times its volume and nothing else.
  CHECK(*std::max_element(moved.begin(), moved.end()) == 2.0);
  int changed = -1;
  for (int n = 0; n < new_mesh.tet_count(); ++n) {
    if (moved[n] == remapped[n]) continue;
    CHECK(changed == -1);
    changed = n;
  }
  REQUIRE(changed >= 0);
  CHECK(moved[changed] == 2.0);
  CHECK(remesh::integral(new_mesh, moved) - remesh::integral(old_mesh, strain) ==
        Approx((2.0 - remapped[changed]) * mesh::signed_volume(new_mesh, changed)).epsilon(1e-9));
}

TEST_CASE("A point is located by one rule, whatever order VTK lists the tets in", "[unit][remesh]") {
  // VTK's static locator builds its bins with threads: the order it lists a
  // bin's tets in, and so which tet FindCell returns for a point on a face
  // they share, changed from run to run and with the thread count (the
  // closed-die runs' remeshes then parted at round-off). The rule: the most
  // inside tet, ties to the lowest index; outside, the nearest, ties alike.
  const mesh::TetMesh mesh = mesh::make_box({0, 0, 0}, {2, 2, 2}, {2, 2, 2});
  const remesh::PointLocator locator(mesh);
  const mesh::Point vertex(1, 1, 1); // a node every central tet shares
  std::vector<int> sharing;
  for (int e = 0; e < mesh.tet_count(); ++e)
    for (const int n : mesh.tets[e])
      if (mesh.nodes[n] == vertex) sharing.push_back(e);
  REQUIRE(sharing.size() > 2);
  const remesh::Location at = locator.locate(vertex);
  CHECK(at.inside);
  CHECK(at.tet == sharing.front()); // all contain it equally (weights 0, 0, 0, 1): the lowest index
  std::vector<int> listed;
  locator.tets_in_box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, listed);
  CHECK(std::is_sorted(listed.begin(), listed.end()));
  // Outside, beyond a face: the nearest tet, found again alike.
  const remesh::Location outside = locator.locate({1.0, 1.0, 2.5});
  CHECK_FALSE(outside.inside);
  CHECK(outside.tet == locator.locate({1.0, 1.0, 2.5}).tet);
}
