// A Krylov preconditioner kept across increments, as a checkpoint written
// at a stop carries it (Ctrl-C, the stop criterion). A kept set-up was made
// from the tangent of an earlier Newton iteration, whose entries the
// assembly has since overwritten: a run resumed with a new set-up would
// solve its next increments on another preconditioner, to the same
// tolerance but not to the same bits, and after its next remesh it would
// part from the uninterrupted run by up to a remesh's load jump. With this
// record it sets the preconditioner up from the same entries and goes on
// exactly. A periodic checkpoint needs none: the run sets its
// preconditioner up anew after each one (LinearSolver::restart).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::solver {

struct KeptSetUp {
  /// Per process of the run that wrote it, its tangent entries at the
  /// set-up, in the order of its own assembly (the pattern it had then).
  std::vector<std::vector<double>> entries;
  /// Per process, a 52-bit hash of that pattern (exact in a double): a
  /// resumed run whose assembly has another pattern (another number of
  /// processes, other contact couplings) would have set up anew, and does.
  std::vector<double> patterns;
  std::vector<mesh::Point> nodes;    ///< coordinates at the set-up (ML's rigid-body modes, its geometry), mm
  std::vector<double> pressure_mass; ///< M_p/η per node at the set-up (the same on every process)
  double setup_rate = 0.0;           ///< LinearSolver's measure of the set-up (iterations per decade)
  double extra_iterations = 0.0;     ///< and the iterations its later solves took beyond that
  /// FGMRES had stagnated on this mesh and MUMPS took over: the resumed run
  /// takes MUMPS too (no entries then).
  bool direct_fallback = false;

  bool empty() const { return entries.empty() && !direct_fallback; }
};

/// Every process calls it together with its own record (one entry list):
/// rank 0 gets every process's entries and patterns, in rank order, the
/// others an empty record.
KeptSetUp gather_kept(KeptSetUp own);

} // namespace anvil::solver
