// A new contact set at the same unknowns needs only the contact blocks
// again: the tangent the elements left, kept and put back, takes another
// set's blocks to the same bits as assembling the elements anew.
#include "anvil/fem/Assembler.h"
#include "anvil/fem/DofMap.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace anvil;

TEST_CASE("The elements' tangent kept and put back takes another contact set as a fresh assembly does", "[unit][fem]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {1, 1, 1}, std::array<int, 3>{3, 3, 3});
  std::vector<char> prescribed(fem::kDofsPerNode * box.node_count(), 0);
  prescribed[2] = 1; // a prescribed row and column for finish_tangent() to clear
  const fem::DofMap dofs(prescribed);
  const fem::Partition whole = fem::partition_mesh(box, 1, 0);
  fem::Assembler assembler(box, dofs, whole);
  const material::NortonHoff law(50.0, 0.15, 1e-4);
  const fem::ElementLaws laws(box.tets.size(), &law);
  const std::vector<material::PointState> states(box.tets.size());
  fem::BodyUnknowns u{Eigen::VectorXd::Zero(fem::kDofsPerNode * box.node_count()),
                      Eigen::VectorXd::Zero(3 * box.tet_count())};
  for (int i = 0; i < box.node_count(); ++i)
    u.nodal.segment<3>(fem::kDofsPerNode * i) = mesh::Point(-box.nodes[i].x(), 0.3 * box.nodes[i].y(), 0.0);
  const Eigen::VectorXd forces = Eigen::VectorXd::Zero(u.nodal.size());
  const Eigen::Matrix3d first_set = 7.0 * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d second_set = Eigen::Vector3d(0.0, 0.0, 3.0).asDiagonal();

  // Elements, one contact set, then the other set on the elements kept.
  assembler.assemble(box, laws, states, u, forces, {}, true);
  assembler.keep_element_tangent();
  assembler.add_velocity_block(0, 0, first_set);
  assembler.finish_tangent();
  assembler.restore_element_tangent();
  assembler.add_velocity_block(1, 1, second_set);
  assembler.finish_tangent();
  const std::vector<double> reused(assembler.tangent().valuePtr(),
                                   assembler.tangent().valuePtr() + assembler.tangent().nonZeros());

  // The other set on a fresh assembly.
  assembler.assemble(box, laws, states, u, forces, {}, true);
  assembler.add_velocity_block(1, 1, second_set);
  assembler.finish_tangent();
  const std::vector<double> fresh(assembler.tangent().valuePtr(),
                                  assembler.tangent().valuePtr() + assembler.tangent().nonZeros());
  CHECK(reused == fresh);
}
