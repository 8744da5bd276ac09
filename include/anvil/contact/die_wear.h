// Die wear (effect die_wear): the generalized Archard law
//   w = ∫ K p^a v^b / H^c dt
// (p contact pressure, v sliding speed of the part on the die, H the die's
// hardness), accumulated at the vertices of a rigid die's surface from the
// part's contact nodes. A qualitative measure, for comparing die designs and
// process variants: K is calibrated on worn dies (docs/method.md, "Die wear").
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <span>
#include <vector>

namespace anvil::contact {

/// w in mm with p in MPa, v in mm/s, H in HRC and t in s: K carries the
/// units that make it so.
struct WearLaw {
  double coefficient = 0.0;
  double pressure_exponent = 1.0; ///< a
  double velocity_exponent = 1.0; ///< b
  double hardness_exponent = 2.0; ///< c
  double hardness = 0.0;          ///< HRC

  /// Wear rate (mm/s) under pressure `pressure` (MPa) and sliding speed `sliding` (mm/s).
  double rate(double pressure, double sliding) const;
};

/// A contact node of the part on a die during one increment, in the die's frame.
struct WearPoint {
  mesh::Point at; ///< mm, where it touches the die
  double rate;    ///< mm/s
  double reach;   ///< mm: the die vertices within it are under this node's contact patch
};

/// Adds Δt × rate (× `scale` of the vertex, when given) to the wear of
/// each die vertex lying under a contact node's patch: the nearest point of
/// `points` within its reach (none: no wear). `wear` holds one value per vertex.
void add_wear(std::span<const mesh::Point> vertices, std::span<const WearPoint> points, double dt,
              std::vector<double>& wear, std::span<const double> scale = {});

} // namespace anvil::contact
