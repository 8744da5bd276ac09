// A Norton-Hoff box of cells³ cubes (6 tets each) ready to assemble, moving
// in compression along x: what the assembly tests start from.
#pragma once
#include "anvil/fem/Assembler.h"
#include "anvil/fem/DofMap.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/generators.h"

#include <vector>

struct BoxAssembly {
  explicit BoxAssembly(int cells, std::vector<char> prescribed = {})
      : box(anvil::mesh::make_box({0, 0, 0}, {1, 1, 1}, std::array<int, 3>{cells, cells, cells})),
        whole(anvil::fem::partition_mesh(box, 1, 0)),
        assembler(box,
                  anvil::fem::DofMap(prescribed.empty()
                                         ? std::vector<char>(anvil::fem::kDofsPerNode * box.node_count(), 0)
                                         : std::move(prescribed)),
                  whole),
        laws(box.tets.size(), &law),
        states(box.tets.size()), unknowns{Eigen::VectorXd::Zero(anvil::fem::kDofsPerNode * box.node_count()),
                                          Eigen::VectorXd::Zero(3 * box.tet_count())},
        forces(Eigen::VectorXd::Zero(anvil::fem::kDofsPerNode * box.node_count())) {
    for (int i = 0; i < box.node_count(); ++i)
      unknowns.nodal.segment<3>(anvil::fem::kDofsPerNode * i) =
          anvil::mesh::Point(-box.nodes[i].x(), 0.3 * box.nodes[i].y(), 0.0);
  }
  /// assemble() with the tangent.
  anvil::fem::AssemblyResult assemble() { return assembler.assemble(box, laws, states, unknowns, forces, {}, true); }

  const anvil::mesh::TetMesh box;
  const anvil::fem::Partition whole;
  anvil::fem::Assembler assembler;
  const anvil::material::NortonHoff law{50.0, 0.15, 1e-4};
  const anvil::fem::ElementLaws laws;
  const std::vector<anvil::material::PointState> states;
  anvil::fem::BodyUnknowns unknowns;
  const Eigen::VectorXd forces;
};
