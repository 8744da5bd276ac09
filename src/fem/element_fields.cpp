#include "anvil/fem/element_fields.h"

#include "anvil/fem/mini_element.h"

namespace anvil::fem {

ElementFields element_fields(const mesh::TetMesh& mesh, const ElementLaws& laws,
                             std::span<const material::PointState> states, const BodyUnknowns& u) {
  ElementFields out;
  out.rate.resize(mesh.tets.size());
  out.stress.resize(mesh.tets.size());
  MiniElementInput in;
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const mesh::Tet& t = mesh.tets[e];
    for (int a = 0; a < 4; ++a) {
      in.vertices[a] = mesh.nodes[t[a]];
      in.nodal_velocity[a] = u.nodal.segment<3>(4 * t[a]);
      in.nodal_pressure[a] = u.nodal[4 * t[a] + 3];
    }
    in.state = states[e];
    const MiniElementFields f = mini_element_fields(in, *laws[e]);
    out.rate[e] = f.equivalent_strain_rate;
    out.stress[e] = f.stress;
  }
  return out;
}

} // namespace anvil::fem
