// How many nodes a run can afford on this machine, checked before a mesh is
// built (a mistyped element size must not grow to gigabytes first).
#pragma once
#include <algorithm>
#include <string>

namespace anvil::mesh {

/// Memory a run takes per mesh node with the iterative solver: 17-23 kB
/// measured (tools/bench_increment: 4.5 GB at 269k nodes for a Newtonian
/// block, 6.3 GB for Norton-Hoff m = 0.1); the direct solvers take more.
inline constexpr double kRunBytesPerNode = 20e3;

/// Nodes CGAL's isotropic remeshing makes at edge length h (mm): about
/// kRemeshedNodesPerVolume V/h³ + kRemeshedNodesPerArea A/h² for a body of
/// volume V (mm³) and surface area A (mm²), the surface's nodes over what
/// the bulk gives. Fitted by tools/remesh_nodes on cubes, plates, cylinders
/// and rings at 1-2 mm (docs/remeshing.md); the bulk term alone fell short
/// on every one, most on thin bodies.
inline constexpr double kRemeshedNodesPerVolume = 1.62;
inline constexpr double kRemeshedNodesPerArea = 0.92;
inline double remeshed_nodes(double volume, double area, double h) {
  return kRemeshedNodesPerVolume * volume / (h * h * h) + kRemeshedNodesPerArea * area / (h * h);
}

/// Nodes the border of a finer level of a size field adds (remesh_body's
/// levels: the coarser cells keep their faces there, and the border's
/// edges longer than CGAL keeps at the finer length are bisected first):
/// about k g(r) A / L² for a border of area A (mm²) between a level of
/// length L (mm) and the finer one at r L. g(r), the share of the border's
/// edges that are bisected, is 1 at r = ¾ and falls linearly to 0 at
/// r = r₀. k and r₀ are fitted by tools/remesh_nodes on generated bodies
/// under graded size fields (docs/remeshing.md); without this term the
/// estimate fell 30-33 % short on the adaptive remeshes of the closed-die
/// parts, where a third of the nodes are bisected border edges.
inline constexpr double kNodesPerLevelBorder = 1.68;
inline constexpr double kLevelRatioWithoutSplits = 0.870;
inline double level_border_nodes(double area, double coarser, double ratio, double k = kNodesPerLevelBorder,
                                 double r0 = kLevelRatioWithoutSplits) {
  const double share = std::clamp((r0 - ratio) / (r0 - 0.75), 0.0, 1.0);
  return k * share * area / (coarser * coarser);
}

/// Physical memory of this machine (bytes).
double physical_memory();

/// Nodes a run can afford on this machine: its memory at kRunBytesPerNode,
/// at most what 32-bit row indices of the linear system allow.
double affordable_nodes();

/// Throws InputError "`where`: about N nodes ..." when a mesh of `nodes`
/// nodes would not fit in this machine's memory, or past the 32-bit indices
/// of the linear system.
void check_node_budget(double nodes, const std::string& where);

} // namespace anvil::mesh
