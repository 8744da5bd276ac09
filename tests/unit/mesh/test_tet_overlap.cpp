// The intersection of two tets, checked against a tiling: the pieces a tet
// leaves in each tet of a mesh that covers it add up to the tet itself.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/mesh/tet_overlap.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("A tet's overlaps with the tets of a mesh around it add up to the tet", "[unit][mesh]") {
  // A slanted tet inside a 0.4 mm box mesh: cut by every plane orientation
  // the clipping meets (one, two and three corners kept).
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {2, 2, 2}, 0.4);
  const mesh::TetCorners tet{mesh::Point(0.13, 0.21, 0.17), mesh::Point(1.87, 0.43, 0.31),
                             mesh::Point(0.52, 1.71, 0.23), mesh::Point(0.71, 0.64, 1.93)};
  const double volume = mesh::signed_volume(tet[0], tet[1], tet[2], tet[3]);
  const mesh::Point centroid = 0.25 * (tet[0] + tet[1] + tet[2] + tet[3]);
  double covered = 0.0;
  mesh::Point moment = mesh::Point::Zero();
  int cut = 0;
  for (const mesh::Tet& t : box.tets) {
    const mesh::Overlap o =
        mesh::tet_overlap(tet, {box.nodes[t[0]], box.nodes[t[1]], box.nodes[t[2]], box.nodes[t[3]]});
    covered += o.volume;
    moment += o.volume * o.centroid;
    if (o.volume > 0.0) ++cut;
  }
  INFO(cut << " box tets overlap it");
  CHECK(cut > 100);
  CHECK(covered == Approx(volume).epsilon(1e-12)); // rounding only
  CHECK((moment / covered - centroid).norm() < 1e-12);
}

TEST_CASE("Overlap of nested, identical and apart tets", "[unit][mesh]") {
  const mesh::TetCorners corner{mesh::Point(0, 0, 0), mesh::Point(1, 0, 0), mesh::Point(0, 1, 0), mesh::Point(0, 0, 1)};
  mesh::TetCorners half, apart;
  for (int k = 0; k < 4; ++k)
    half[k] = 0.5 * corner[k], apart[k] = corner[k] + mesh::Point(2, 0, 0);
  CHECK(mesh::tet_overlap(corner, corner).volume == Approx(1.0 / 6.0).epsilon(1e-14));
  const mesh::Overlap inner = mesh::tet_overlap(corner, half);
  CHECK(inner.volume == Approx(1.0 / 48.0).epsilon(1e-14));
  CHECK((inner.centroid - mesh::Point(0.125, 0.125, 0.125)).norm() < 1e-14);
  CHECK(mesh::tet_overlap(half, corner).volume == Approx(1.0 / 48.0).epsilon(1e-14)); // either way round
  CHECK(mesh::tet_overlap(corner, apart).volume == 0.0);
}
