#include "anvil/contact/contact_scales.h"

#include "anvil/fem/element_fields.h"

#include <cmath>
#include <limits>

namespace anvil::contact {

ContactScales contact_scales(const mesh::TetMesh& mesh, std::span<const ScaledBody> bodies,
                             const fem::ElementLaws& laws, std::span<const material::PointState> states,
                             const fem::BodyUnknowns& u, double reference_rate, double body_size,
                             double penalty_factor) {
  const fem::ElementFields fields = fem::element_fields(mesh, laws, states, u);
  ContactScales out;
  out.flow_stress.assign(mesh.nodes.size(), 0.0);
  out.consistency.assign(mesh.nodes.size(), 0.0);
  std::vector<double> weight(mesh.nodes.size(), 0.0);
  for (const ScaledBody& body : bodies) {
    const int first = body.range.first_node, end = first + body.range.node_count;
    if (body.law->is_elastic()) {
      // An elastic body does not flow: friction against it is bounded by the
      // other body's shear strength (BodyContact takes the weaker side).
      std::fill(out.flow_stress.begin() + first, out.flow_stress.begin() + end,
                std::numeric_limits<double>::infinity());
      std::fill(out.consistency.begin() + first, out.consistency.begin() + end,
                std::numeric_limits<double>::infinity());
      continue;
    }
    for (int e = body.range.first_tet; e < body.range.first_tet + body.range.tet_count; ++e) {
      // A body left at rest by the dies has almost no strain rate: its
      // elements take the process rate instead.
      const double rate = fields.rate[e] > 0.0 ? fields.rate[e] : reference_rate;
      const double flow = laws[e]->flow_stress(rate, states[e]), k = laws[e]->consistency(states[e]);
      for (int node : mesh.tets[e])
        out.flow_stress[node] += flow, out.consistency[node] += k, weight[node] += 1.0;
    }
    for (int i = first; i < end; ++i)
      out.flow_stress[i] /= weight[i], out.consistency[i] /= weight[i];
  }
  // The softest body sets ρ: a stiff die's modulus (an elastic body's secant
  // viscosity is its shear modulus) would make the system needlessly
  // ill-conditioned.
  double softest = std::numeric_limits<double>::infinity();
  for (const ScaledBody& body : bodies) {
    double viscosity = 0.0;
    for (int e = body.range.first_tet; e < body.range.first_tet + body.range.tet_count; ++e)
      viscosity += body.law->secant_viscosity(reference_rate, states[e]) / body.range.tet_count;
    softest = std::min(softest, viscosity);
  }
  out.penalty = penalty_factor * 3.0 * softest / body_size;
  out.reference_force = 3.0 * softest * reference_rate * std::pow(mesh::volume(mesh), 2.0 / 3.0);
  return out;
}

} // namespace anvil::contact
