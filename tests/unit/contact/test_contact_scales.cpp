// contact_scales on a Newtonian block at rest beside an elastic one: the
// block's elements take the process rate, σ₀ = 3ηε̇_ref and K = η at its
// nodes, the elastic block's nodes are infinitely strong (friction against
// it is bounded by the other side), and the softer block alone sets the
// penalty and the force scale.
#include "test_common.h"

#include "anvil/contact/contact_scales.h"
#include "anvil/mesh/generators.h"

#include <cmath>

using namespace anvil;

TEST_CASE("contact_scales: the process rate where a body is at rest, the softest body sets the penalty",
          "[unit][contact]") {
  mesh::TetMesh mesh;
  const mesh::MeshRange soft = mesh::append(mesh, mesh::make_box({0, 0, 0}, {2, 2, 1}, {2, 2, 1}));
  const mesh::MeshRange stiff = mesh::append(mesh, mesh::make_box({0, 0, 1}, {2, 2, 1}, {2, 2, 1}));
  const double eta = 4.0; // MPa·s
  const material::NortonHoff newtonian(eta, 1.0, 0.0);
  const material::LinearElastic steel(210000.0, 0.3);
  const std::vector<contact::ScaledBody> bodies{{soft, &newtonian}, {stiff, &steel}};
  fem::ElementLaws laws(mesh.tets.size(), &newtonian);
  for (int e = stiff.first_tet; e < stiff.first_tet + stiff.tet_count; ++e)
    laws[e] = &steel;
  const std::vector<material::PointState> states(mesh.tets.size());
  const fem::BodyUnknowns at_rest{Eigen::VectorXd::Zero(4 * mesh.node_count()),
                                  Eigen::VectorXd::Zero(3 * mesh.tet_count())};
  const double rate = 0.5, size = 3.0, factor = 1000.0;

  const contact::ContactScales s = contact::contact_scales(mesh, bodies, laws, states, at_rest, rate, size, factor);
  for (int i = soft.first_node; i < soft.first_node + soft.node_count; ++i) {
    CHECK(s.flow_stress[i] == Approx(3.0 * eta * rate).epsilon(1e-12));
    CHECK(s.consistency[i] == Approx(eta).epsilon(1e-12));
  }
  for (int i = stiff.first_node; i < stiff.first_node + stiff.node_count; ++i) {
    CHECK(std::isinf(s.flow_stress[i]));
    CHECK(std::isinf(s.consistency[i]));
  }
  CHECK(s.penalty == Approx(factor * 3.0 * eta / size).epsilon(1e-12));
  CHECK(s.reference_force == Approx(3.0 * eta * rate * std::pow(8.0, 2.0 / 3.0)).epsilon(1e-12)); // V = 8 mm³
}
