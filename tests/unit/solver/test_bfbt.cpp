// Stabilised BFBT (src/solver/bfbt_schur.h) with D the block diagonal of K:
// exact, like the Schur complement it approximates, wherever K is block
// diagonal, as at nodes held by a contact penalty alone.
#include "test_common.h"

#include "anvil/core/Timers.h"
#include "anvil/fem/Partition.h"
#include "anvil/mesh/generators.h"
#include "anvil/solver/LinearSolver.h"
#include "anvil/solver/PetscSession.h"

#include <cmath>
#include <vector>

using namespace anvil;

TEST_CASE("BFBT is exact where K is block diagonal: with exact inner solves FGMRES takes two iterations", "[unit]") {
  // [K Bᵀ; B −C] with each node's 3×3 block of K a penalty 1000 n nᵀ along
  // a normal n off every axis plus the identity, and no coupling between
  // nodes: with D = K, Ŝ = −(B K⁻¹ Bᵀ + C), the Schur complement itself.
  // With the velocity block and BFBT's L solved exactly, the upper
  // block-triangular preconditioner then leaves FGMRES two iterations (the
  // preconditioned operator's minimal polynomial is (λ − 1)²). With
  // D = diag(K), Ŝ is not S there, and FGMRES took 64 iterations.
  const mesh::TetMesh box = mesh::make_box(mesh::Point::Zero(), mesh::Point(3, 3, 3), {3, 3, 3});
  const int nodes = box.node_count(), n = 4 * nodes;
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < nodes; ++k) {
    const Eigen::Vector3d normal = Eigen::Vector3d(1.0 + std::sin(k), 2.0 + std::cos(k), 3.0).normalized();
    const Eigen::Matrix3d block = Eigen::Matrix3d::Identity() + 1000.0 * normal * normal.transpose();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        entries.emplace_back(4 * k + i, 4 * k + j, block(i, j));
    // B: pressure k on the velocities of nodes k and k + 1; −C on its diagonal.
    for (int neighbour : {k, (k + 1) % nodes})
      for (int i = 0; i < 3; ++i) {
        const double b = std::cos(0.7 * k + 1.3 * i + neighbour);
        entries.emplace_back(4 * k + 3, 4 * neighbour + i, b);
        entries.emplace_back(4 * neighbour + i, 4 * k + 3, b);
      }
    entries.emplace_back(4 * k + 3, 4 * k + 3, -0.01);
  }
  fem::SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(n), x;
  for (int d = 0; d < n; ++d)
    rhs[d] = std::sin(0.37 * d);
  const Eigen::VectorXd pressure_mass = Eigen::VectorXd::Ones(nodes);
  const fem::Partition partition = fem::partition_mesh(box, 1, 0);

  int iterations = -1;
  {
    const solver::ScopedPetscOptions exact("-fieldsplit_0_pc_type lu -fieldsplit_1_bfbt_pc_type lu", "test");
    Timers timers;
    solver::LinearSolver solver({solver::LinearSolverKind::fgmres}, n, partition, timers);
    REQUIRE(solver.factorize(a, {box.nodes, pressure_mass, {}}));
    REQUIRE(solver.solve(rhs, x, 1e-10));
    REQUIRE(solver.kind() == solver::LinearSolverKind::fgmres);
    iterations = solver.iterations();
  }
  INFO("FGMRES iterations " << iterations << ", residual " << (rhs - a * x).norm() / rhs.norm());
  CHECK(iterations <= 2);
  CHECK((rhs - a * x).norm() <= 1e-9 * rhs.norm()); // the tolerance asked, with room for round-off
}
