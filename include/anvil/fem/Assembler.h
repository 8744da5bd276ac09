// Global assembly of the condensed P1+/P1 system of one body:
//   [ K  Bᵀ ] [Δv]     [r_v]
//   [ B −C  ] [Δp] = − [r_p]      (docs/design.md §2), over every nodal dof.
// The matrix is compressed sparse rows with 32-bit indices, the layout of a
// PETSc AIJ matrix, which wraps it without a copy. Its pattern is 4×4 blocks
// of node adjacency, built once per mesh and contact-coupling set. Elements
// are assembled in chunks of consecutive elements (their rows stay in cache);
// a colouring of the chunks (no two chunks of a colour share a node) lets
// assembly write the values in place, colour by colour with TBB, each chunk
// in element order, so the result does not depend on the thread count.
// Prescribed dofs are decoupled rows and columns with a scaled identity on
// the diagonal (DofMap). With several processes (Partition) each assembles
// the elements of its part: its matrix holds their entries only (the
// distributed matrix sums them), while the residual, the pressure mass and
// the bubble data it returns are the whole system's, summed over processes.
#pragma once
#include "anvil/fem/DofMap.h"
#include "anvil/fem/Partition.h"
#include "anvil/fem/mini_element.h"

#include <Eigen/Sparse>
#include <array>
#include <utility>
#include <vector>

namespace anvil::fem {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

/// The law of each element: bodies of different materials are solved in one
/// system, each element with its own body's law.
using ElementLaws = std::vector<const material::Material*>;

/// Elements first, …, end − 1: assembled in order by one task.
struct ElementChunk {
  int first, end;
};

/// The unknowns of one body.
struct BodyUnknowns {
  Eigen::VectorXd nodal;  ///< 4 × nodes, interleaved [vx vy vz p] (mm/s or mm, MPa)
  Eigen::VectorXd bubble; ///< 3 × elements, bubble coefficients
};

/// What the assembly returns besides the matrix.
struct AssemblyResult {
  Eigen::VectorXd residual; ///< 4 × nodes; includes prescribed dofs (their entries are reactions, N)
  double bubble_residual_sq = 0.0;
  int bad_element = -1; ///< first inverted or flat element (0-based), or −1
};

class Assembler {
public:
  /// The pattern of `mesh`'s elements of this process's part (its nodes may
  /// move, its elements not) over the dofs of `dofs`; `partition` must
  /// outlive the assembler.
  Assembler(const mesh::TetMesh& mesh, DofMap dofs, const Partition& partition);

  /// Residual R = internal − external (external = `nodal_forces`, 4 × nodes,
  /// e.g. tractions) and, when `with_tangent`, the condensed tangent (tangent())
  /// and the viscous pressure mass (pressure_mass()). Stores what the bubble
  /// update needs; call bubble_increment() after the linear solve.
  /// `mesh` has the elements the assembler was built for, at their current nodes.
  AssemblyResult assemble(const mesh::TetMesh& mesh, const ElementLaws& laws,
                          const std::vector<material::PointState>& states, const BodyUnknowns& unknowns,
                          const Eigen::VectorXd& nodal_forces, const BodyForce& body_force, bool with_tangent);

  /// Bubble increments (3 × elements) that go with the nodal increments
  /// `delta` (4 × nodes), from the data of the last assemble() (
  /// static condensation: Δb = −K_bb⁻¹ (r_b + K_bl Δv + G_b Δp)).
  void bubble_increment(const mesh::TetMesh& mesh, const Eigen::VectorXd& delta, Eigen::VectorXd& bubble_delta) const;

  /// The tangent of the last assemble() with a tangent (this process's
  /// elements); its storage stays in place until the pattern changes
  /// (set_couplings() returns true).
  const SparseMatrix& tangent() const { return tangent_; }
  /// Lumped pressure mass over viscosity, Σ_e V_e / (4 η_e) per node
  /// (mm³/(MPa·s)): the viscosity-scaled mass matrix that approximates the
  /// Schur complement B K⁻¹ Bᵀ (Elman, Silvester, Wathen 2014, §9.2); η_e
  /// is the element's mean tangent viscosity (MiniElementSystem::viscosity).
  const Eigen::VectorXd& pressure_mass() const { return pressure_mass_; }

  /// Adds node pairs (a, b) that a contact term couples to the pattern of the
  /// elements (both blocks ab and ba). True when the pattern changed (the
  /// tangent is then rebuilt and the linear solver must analyse it again).
  bool set_couplings(const std::vector<std::pair<int, int>>& couplings);
  /// tangent(velocity rows of `row_node`, velocity columns of `col_node`) += block;
  /// the pair must be in the pattern (same node, element neighbours or a coupling).
  void add_velocity_block(int row_node, int col_node, const Eigen::Matrix3d& block);
  /// Keeps the tangent as the elements left it (call before the contact
  /// blocks and finish_tangent()); restore_element_tangent() puts it back, so
  /// that the blocks of another contact set can be added without assembling
  /// the elements again.
  void keep_element_tangent();
  void restore_element_tangent();
  /// Decouples the prescribed dofs (after every contribution is added): their
  /// rows and columns are cleared and their diagonal is the mean free
  /// diagonal of the velocity rows, or of the pressure rows, so the rows are
  /// neither tiny nor huge for a solver (put in by the process owning the row).
  void finish_tangent();
  const DofMap& dofs() const { return dofs_; }
  /// The tangents of the next assemble() calls are built with a rate
  /// sensitivity of at least `floor` (MiniElementInput); 0: consistent.
  void set_tangent_sensitivity_floor(double floor) { tangent_sensitivity_floor_ = floor; }
  /// The elements of the next assemble() calls are integrated by the rule of
  /// this degree (fem::tet_quadrature: 5 or 6).
  void set_quadrature_degree(int degree) { quadrature_degree_ = degree; }
  /// Newton's own direction of the strain rate (fem/strain_rate_dual.h):
  /// start_dual() at Newton's first iterate `at` (n̂ = n there; null: no
  /// dual, the consistent tangent, as for linear laws), then each assemble()
  /// is at the last iterate plus `step` (set_dual_step()) times the
  /// direction, and accept_dual() makes the last assemble()'s trial, at `at`,
  /// the next iterate.
  void start_dual(const BodyUnknowns* at);
  void set_dual_step(double step) { dual_step_ = step; }
  void accept_dual(const BodyUnknowns& at);
  const Partition& partition() const { return partition_; }

private:
  void build_pattern();
  /// Index in the tangent's values of (velocity or pressure row `d` of node
  /// `row_node`, component `c` of node `col_node`).
  int entry(int row_node, int d, int col_node, int c) const;

  DofMap dofs_;
  double tangent_sensitivity_floor_ = 0.0;
  int quadrature_degree_ = 5;
  const Partition& partition_;
  std::vector<mesh::Tet> tets_; ///< the elements the pattern is built on: partition_.elements
  SparseMatrix tangent_;
  std::vector<double> element_tangent_; ///< keep_element_tangent()'s values
  Eigen::VectorXd pressure_mass_;
  std::vector<std::vector<ElementChunk>> colours_; ///< the chunks of each colour (positions in tets_)
  /// Per element of tets_: K_bb⁻¹ [K_bl G_b] (3×16) and K_bb⁻¹ r_b (3).
  std::vector<Eigen::Matrix<double, 3, 17>> bubble_condensation_;
  /// Per element, from the last assemble(): inverted/flat flag and |r_b|²
  /// (kept per element so the sums are in a fixed order, whatever the threads).
  std::vector<char> bad_;
  std::vector<double> bubble_sq_;
  /// The dual: unknowns of the last iterate, n̂ per quadrature point of each
  /// element of tets_ there (empty at Newton's first iterate) and at the trial.
  bool dual_ = false;
  BodyUnknowns dual_at_;
  std::vector<DualDirection> dual_last_, dual_trial_;
  double dual_step_ = 0.0;
  /// Per element, where its 4×4 node blocks start in the tangent's values
  /// (row node b, column node a at 4b + a): assembly needs no search.
  std::vector<std::array<int, 16>> element_blocks_;
  std::vector<std::vector<int>> element_neighbours_; ///< per node, the nodes it shares an element with (sorted)
  std::vector<std::vector<int>> neighbours_;         ///< the same with the contact couplings: the pattern
  std::vector<std::pair<int, int>> couplings_;       ///< the contact couplings in the pattern
  std::vector<int> diagonal_;                        ///< per dof, the index of its diagonal entry (−1: no entry)
  std::vector<int> constrained_entries_;             ///< entries in a prescribed row or column
};

} // namespace anvil::fem
