// Self-contact search (a body paired with itself: contact::BodyPair::self,
// ContactSurface::project_self) on two unit blocks of one body, 0.5 mm
// elements, the upper one `gap` mm above the lower: the facing faces'
// nodes, and only they, project onto each other, in front within the reach
// or behind by less than a tenth of an edge; a single block (its top and
// bottom faces facing away, 1 mm apart) has no self-contact within reach.
#include "test_common.h"

#include "anvil/contact/BodyContact.h"
#include "anvil/mesh/generators.h"

#include <cmath>

using namespace anvil;

namespace {

constexpr double kReach = 0.2; // mm

/// The points found by a self-contact search of `m` as one body.
std::vector<contact::ContactPoint> self_contact_points(const mesh::TetMesh& m) {
  const mesh::MeshRange body = mesh::whole_range(m);
  contact::BodyContact pairs({{"body (self-contact)",
                               body,
                               body,
                               {contact::PairFormulation::symmetric, contact::PairIntegration::nodal},
                               {}}});
  REQUIRE(pairs.pairs().front().self());
  pairs.search(m, kReach);
  return pairs.projected_nodes();
}

/// The lower block's nodes come first.
mesh::TetMesh two_blocks(double gap, int* lower_nodes = nullptr) {
  mesh::TetMesh m;
  const mesh::MeshRange lower = mesh::append(m, mesh::make_box({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
  if (lower_nodes) *lower_nodes = lower.node_count;
  mesh::append(m, mesh::make_box({0, 0, 1 + gap}, {1, 1, 1}, {2, 2, 2}));
  return m;
}

} // namespace

TEST_CASE("self-contact: the facing faces of a body project onto each other, not onto their own neighbours",
          "[unit][contact]") {
  CHECK(self_contact_points(mesh::make_box({0, 0, 0}, {1, 1, 1}, {2, 2, 2})).empty());

  for (const double gap : {0.05, -0.02}) {
    INFO("gap " << gap << " mm");
    int lower_nodes = 0;
    const mesh::TetMesh m = two_blocks(gap, &lower_nodes);
    const std::vector<contact::ContactPoint> points = self_contact_points(m);
    CHECK(points.size() == 18); // 3 × 3 nodes on each of the two facing faces
    for (const contact::ContactPoint& p : points) {
      const bool lower = p.node() < lower_nodes;
      CHECK(std::abs(m.nodes[p.node()].z() - (lower ? 1.0 : 1.0 + gap)) < 1e-12);
      CHECK(p.gap == Approx(gap).margin(1e-12));
      CHECK(p.share == 0.5);
      for (int node : p.facet) // the facet of the other block's face
        CHECK(std::abs(m.nodes[node].z() - (lower ? 1.0 + gap : 1.0)) < 1e-12);
      CHECK(p.normal.z() == Approx(lower ? -1.0 : 1.0));
    }
  }
  // Pushed 0.2 mm into each other, more than a tenth of an edge: the far
  // side of a thin section, not a contact.
  CHECK(self_contact_points(two_blocks(-0.2)).empty());
}
