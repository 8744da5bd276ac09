// The directions a penalty holds at a node, which the velocity AMG's
// near-null space leaves out (src/solver/held_modes.h).
//
// Smoothed aggregation builds its coarse levels from modes of low energy,
// Kz ≈ 0. A rigid-body mode is one only where nothing holds the body: at a
// node where a die's contact penalty ρA n nᵀ (or sticking friction's on the
// tangential velocity) dominates its rows, moving the node along n costs ρA,
// and a coarse basis function that moves it so is far from the smooth
// error there. As AMG does with Dirichlet conditions, the modes leave those
// directions out: at each node, the component along every eigenvector of
// the symmetric part of its 3×3 velocity block whose eigenvalue exceeds
// kHeldDominance times the node's couplings to other nodes. The smoother
// (point-block Jacobi inverts the node's block) corrects those directions,
// and the coarse levels see the motion the penalty leaves free. A
// prescribed velocity component (a symmetry plane's: its row and column out
// of the system, the mean diagonal on it) is not held by this rule, as the
// node's other rows carry couplings; the modes keep it, as they did before.
#pragma once
#include <Eigen/Core>

namespace anvil::solver {

/// How far above a node's couplings to other nodes (the largest absolute
/// sum over one of its velocity rows outside its own block) the stiffness
/// of a direction must be for a penalty to hold it. In the connecting rod's
/// flash stage the directions part in two: those of the body's own flow lie
/// below 1 times the couplings, those of the contact nodes' normals at 10 to
/// 1000 times, few in between; 10 lies in that gap.
inline constexpr double kHeldDominance = 10.0;

/// The projector onto the directions left free at a node whose velocity
/// block is `block` (may be unsymmetric: Coulomb friction) and whose
/// couplings are `couplings` (above): the identity less eᵢeᵢᵀ for each held
/// eigenvector eᵢ.
Eigen::Matrix3d free_directions(const Eigen::Matrix3d& block, double couplings);

} // namespace anvil::solver
