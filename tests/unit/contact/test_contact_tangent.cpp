// The tangent blocks of the contact terms against central finite differences
// of their residual, for every friction law: die contact (RigidContact) and
// body-pair contact in each formulation (BodyContact). Newton's quadratic
// convergence rests on these blocks being the derivative of the residual.
#include "anvil/contact/BodyContact.h"
#include "anvil/contact/RigidContact.h"
#include "anvil/fem/DofMap.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>

using namespace anvil;

namespace {

constexpr int kDofs = fem::kDofsPerNode;

/// ∂r/∂v over the velocity dofs (3 per node), from the term's blocks.
Eigen::MatrixXd assembled(const solver::NodalTerm& term, const Eigen::VectorXd& nodal, int nodes) {
  Eigen::VectorXd residual = Eigen::VectorXd::Zero(nodal.size());
  std::vector<solver::NodeBlock> blocks;
  term.add(nodal, residual, &blocks);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  for (const solver::NodeBlock& b : blocks)
    k.block<3, 3>(3 * b.row_node, 3 * b.col_node) += b.tangent;
  return k;
}

/// The same by central differences of the residual, step `h` (mm/s).
Eigen::MatrixXd differenced(const solver::NodalTerm& term, const Eigen::VectorXd& nodal, int nodes, double h) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  for (int j = 0; j < nodes; ++j)
    for (int c = 0; c < 3; ++c) {
      Eigen::VectorXd plus = nodal, minus = nodal;
      plus[kDofs * j + c] += h, minus[kDofs * j + c] -= h;
      Eigen::VectorXd r_plus = Eigen::VectorXd::Zero(nodal.size()), r_minus = r_plus;
      term.add(plus, r_plus, nullptr);
      term.add(minus, r_minus, nullptr);
      for (int i = 0; i < nodes; ++i)
        k.block<3, 1>(3 * i, 3 * j + c) = (r_plus.segment<3>(kDofs * i) - r_minus.segment<3>(kDofs * i)) / (2.0 * h);
    }
  return k;
}

/// Velocities with a sliding part that differs from node to node (mm/s),
/// every node moving down at `down`.
Eigen::VectorXd sliding_velocities(const mesh::TetMesh& mesh, double down) {
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(kDofs * mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) {
    const mesh::Point& x = mesh.nodes[i];
    nodal.segment<3>(kDofs * i) = Eigen::Vector3d(0.3 + 0.7 * x.x() - 0.2 * x.y(), -0.4 + 0.5 * x.y() * x.x(), down);
  }
  return nodal;
}

std::vector<contact::FrictionLaw> every_law() {
  using contact::FrictionKind;
  return {{FrictionKind::frictionless, 0.0, 0.0, 0.0}, {FrictionKind::sticking, 0.0, 0.0, 0.0},
          {FrictionKind::tresca, 0.3, 0.0, 0.0},       {FrictionKind::coulomb, 0.0, 0.2, 0.0},
          {FrictionKind::coulomb, 0.4, 0.5, 0.0},      {FrictionKind::norton, 0.0, 0.1, 0.2}};
}

contact::ContactIncrement increment(int nodes) {
  return {.time_step = 0.1,
          .penalty = 1000.0,
          .regularisation = 0.05,
          .gap_tolerance = 1e-9,
          .recovery_time = 0.1,
          .flow_stress = std::vector<double>(nodes, 80.0),
          .consistency = std::vector<double>(nodes, 40.0)};
}

/// Largest entry of |assembled − differenced| against the largest
/// differenced one. Central differences at h = 1e-6 mm/s: truncation O(h²)
/// and round-off O(1e-16/h) of the entries, measured 1e-10 of the largest.
double tangent_error(const solver::NodalTerm& term, const Eigen::VectorXd& nodal, int nodes) {
  const Eigen::MatrixXd fd = differenced(term, nodal, nodes, 1e-6);
  return (assembled(term, nodal, nodes) - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
}

} // namespace

TEST_CASE("Die contact: the tangent blocks are the derivative of the residual for every friction law",
          "[unit][contact]") {
  // A block pressed 0.01 mm into the plane die z = 0 and sliding on it.
  mesh::TetMesh block = mesh::make_box({0, 0, -0.01}, {1, 1, 1}, std::array<int, 3>{2, 2, 1});
  const die::PlaneSurface die({0, 0, 0}, {0, 0, 1}, 10.0);
  const Eigen::VectorXd nodal = sliding_velocities(block, -0.2);
  for (const contact::FrictionLaw& law : every_law()) {
    INFO("friction " << contact::describe(law));
    contact::RigidContact contact;
    contact.search(block, {{&die, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.05, 0, 0), law}}, 0.5);
    REQUIRE(!contact.candidates().empty());
    contact.set_increment(increment(block.node_count()));
    contact.start(nodal);
    REQUIRE(contact.active_count() > 0);
    // 1e-6 leaves room over the measured 1e-10 and still catches a missing
    // or wrong term (order 1e-2 or more).
    CHECK(tangent_error(contact, nodal, block.node_count()) < 1e-6);
  }
}

TEST_CASE("Body-pair contact: the tangent blocks are the derivative of the residual for every formulation, integration "
          "and law",
          "[unit][contact]") {
  // A finer block on a coarser one, 0.01 mm into it, sliding and pressing.
  mesh::TetMesh mesh;
  const mesh::MeshRange lower = mesh::append(mesh, mesh::make_box({0, 0, 0}, {1, 1, 1}, std::array<int, 3>{2, 2, 1}));
  const mesh::MeshRange upper =
      mesh::append(mesh, mesh::make_box({0.1, 0.1, 0.99}, {0.8, 0.8, 1}, std::array<int, 3>{3, 3, 1}));
  Eigen::VectorXd nodal = sliding_velocities(mesh, -0.2);
  for (int i = lower.first_node; i < lower.first_node + lower.node_count; ++i)
    nodal.segment<3>(kDofs * i).setZero();
  using contact::PairFormulation;
  for (const PairFormulation formulation :
       {PairFormulation::master_slave, PairFormulation::symmetric, PairFormulation::quasi_symmetric})
    for (const auto& [integration, quadrature] :
         {std::pair{contact::PairIntegration::nodal, contact::FacetQuadrature::intersection},
          std::pair{contact::PairIntegration::facet, contact::FacetQuadrature::intersection},
          std::pair{contact::PairIntegration::facet, contact::FacetQuadrature::subdivision}})
      for (const contact::FrictionLaw& law : every_law()) {
        const contact::PairMethod method{formulation, integration, quadrature, 1};
        INFO(contact::describe(method) << ", friction " << contact::describe(law));
        contact::BodyContact contact({{"lower/upper", lower, upper, method, law}});
        contact.search(mesh, 0.5);
        REQUIRE(!contact.points().empty());
        contact.set_increment(increment(mesh.node_count()));
        contact.start(nodal);
        REQUIRE(contact.active_count() > 0);
        CHECK(tangent_error(contact, nodal, mesh.node_count()) < 1e-6); // bound as for die contact
      }
}
