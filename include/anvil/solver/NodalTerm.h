// A node-based term of the residual (contact and friction, docs/design.md §3): a
// 3-vector per node and 3×3 velocity blocks, on a node's own velocity (rigid
// dies) or coupling it with the nodes of a facet it projects onto (body
// pairs). The Newton solver adds it to the assembled system. The couplings a
// term may use are declared once per increment, so the sparsity pattern does
// not change with the active set.
#pragma once
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace anvil::solver {

struct NodeBlock {
  int row_node, col_node;
  Eigen::Matrix3d tangent; ///< ∂r(row node)/∂v(col node) (N·s/mm); may be unsymmetric (Coulomb)
};

class NodalTerm {
public:
  virtual ~NodalTerm() = default;
  /// Adds the term's residual (R = internal − external convention, so minus
  /// the force on the body) to the velocity rows of `residual` (4 × nodes)
  /// at `nodal` (4 × nodes), and, when `blocks` is given, appends its tangent
  /// blocks to it (the caller clears it). With `rows` (per node, 1 = this
  /// process owns the node's rows), only those rows are computed: each
  /// process of a run adds the contact of its own nodes.
  virtual void add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual, std::vector<NodeBlock>* blocks,
                   const std::vector<char>* rows = nullptr) const = 0;
  /// Called when Newton starts, at the starting iterate.
  virtual void start(const Eigen::VectorXd& nodal) = 0;
  /// Called once per accepted Newton iterate: a short note for the log (e.g.
  /// active-set changes); may update the term's own bookkeeping.
  virtual std::string accept(const Eigen::VectorXd& nodal) = 0;
  /// Called when Newton has converged with the term as it stands
  /// (`converged`), or is near convergence: true if its internal choices (an
  /// active set) agree with `nodal`; false if it changed them, and Newton must
  /// go on. Near convergence a term may keep choices it would change at
  /// convergence (contact/ActiveSet.h).
  virtual bool consistent(const Eigen::VectorXd& nodal, bool converged) = 0;
  /// True when the last accept() changed the term's active set.
  virtual bool set_changed() const = 0;
  /// True while the next accept() may change the active set (the set follows
  /// the iterates, before it is frozen).
  virtual bool set_follows_iterates() const = 0;
  /// True when the term is linear in the velocities while its active set
  /// holds (frictionless or sticking contact): with a linear law, one full
  /// Newton step then solves the increment.
  virtual bool linear() const = 0;
  /// Pairs of distinct nodes (a < b) whose blocks the term may fill in this
  /// increment, sorted; none for a term on each node's own velocity.
  virtual std::vector<std::pair<int, int>> couplings() const { return {}; }
  /// Rate-dependent friction builds its tangent with a sliding-rate
  /// sensitivity of at least `floor` (0: the consistent tangent) until told
  /// otherwise: Newton's far phase (IncrementSolver).
  virtual void set_tangent_sensitivity_floor(double floor) = 0;
  /// The next add() is at the last accepted iterate plus `step` times the
  /// Newton direction (the line search's trial; 0 after accept()): a term
  /// with unknowns of its own (contact/FrictionDual.h) moves them with it.
  virtual void set_line_search_step(double step) = 0;
};

} // namespace anvil::solver
