// A new contact set at the same unknowns needs only the contact blocks
// again: the tangent the elements left, kept and put back, takes another
// set's blocks to the same bits as assembling the elements anew.
#include "box_assembly.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace anvil;

TEST_CASE("The elements' tangent kept and put back takes another contact set as a fresh assembly does", "[unit][fem]") {
  std::vector<char> prescribed(fem::kDofsPerNode * 64, 0); // 4³ nodes
  prescribed[2] = 1;                                       // a prescribed row and column for finish_tangent() to clear
  BoxAssembly block(3, prescribed);
  fem::Assembler& assembler = block.assembler;
  const Eigen::Matrix3d first_set = 7.0 * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d second_set = Eigen::Vector3d(0.0, 0.0, 3.0).asDiagonal();

  // Elements, one contact set, then the other set on the elements kept.
  block.assemble();
  assembler.keep_element_tangent();
  assembler.add_velocity_block(0, 0, first_set);
  assembler.finish_tangent();
  assembler.restore_element_tangent();
  assembler.add_velocity_block(1, 1, second_set);
  assembler.finish_tangent();
  const std::vector<double> reused(assembler.tangent().valuePtr(),
                                   assembler.tangent().valuePtr() + assembler.tangent().nonZeros());

  // The other set on a fresh assembly.
  block.assemble();
  assembler.add_velocity_block(1, 1, second_set);
  assembler.finish_tangent();
  const std::vector<double> fresh(assembler.tangent().valuePtr(),
                                  assembler.tangent().valuePtr() + assembler.tangent().nonZeros());
  CHECK(reused == fresh);
}
