// A term of the residual that couples only the velocity of each node with
// itself (rigid-die contact and friction, DESIGN §3): a 3-vector and a 3×3
// block per node. The Newton solver adds it to the assembled system; the
// node's diagonal block is always in the sparsity pattern, so the pattern
// never changes with the active set.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

namespace anvil::solver {

struct NodeBlock {
  int node;
  Eigen::Matrix3d tangent; ///< ∂r/∂v of this node (N·s/mm); may be unsymmetric (Coulomb)
};

class NodalTerm {
public:
  virtual ~NodalTerm() = default;
  /// Adds the term's residual (R = internal − external convention, so minus
  /// the force on the body) to the velocity rows of `residual` (4 × nodes)
  /// at `nodal` (4 × nodes), and, when `blocks` is given, appends its tangent
  /// blocks to it (the caller clears it).
  virtual void add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual, std::vector<NodeBlock>* blocks) const = 0;
  /// Called when Newton starts, at the starting iterate.
  virtual void start(const Eigen::VectorXd& nodal) = 0;
  /// Called once per accepted Newton iterate: a short note for the log (e.g.
  /// active-set changes); may update the term's own bookkeeping.
  virtual std::string accept(const Eigen::VectorXd& nodal) = 0;
  /// Called when Newton has converged with the term as it stands: true if its
  /// internal choices (an active set) agree with `nodal`; false if it changed
  /// them, and Newton must go on.
  virtual bool consistent(const Eigen::VectorXd& nodal) = 0;
};

} // namespace anvil::solver
