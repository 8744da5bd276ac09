// Node-to-surface contact of one deformable body with rigid dies (docs/design.md §3):
// the die is the master, each boundary node a slave. Per candidate node the
// velocity gap of the increment is
//   h = −(v − v_die)·n − δ₀/t   (≤ 0 allowed, paper eq. 19 with a rigid master;
//   t = Δt, or for a penetration the nominal step or longer: ContactIncrement::closing_time),
// enforced by a penalty on the active nodes (contact/ActiveSet.h): contact
// pressure σn = ρ h. Friction acts on active nodes.
// The term is nodal (one 3×3 block per node), so the sparsity pattern of the
// global system does not change with the active set.
#pragma once
#include "anvil/contact/ActiveSet.h"
#include "anvil/contact/ContactIncrement.h"
#include "anvil/contact/Friction.h"
#include "anvil/contact/FrictionDual.h"
#include "anvil/die/DieSurface.h"
#include "anvil/solver/NodalTerm.h"

#include <span>
#include <vector>

namespace anvil::contact {

/// A die as contact sees it during one increment.
struct DieView {
  const die::DieSurface* surface;
  Eigen::Vector3d displacement; ///< of the die frame at the start of the increment (mm)
  Eigen::Vector3d velocity;     ///< over the increment (mm/s)
  FrictionLaw friction;
};

/// A boundary node near a die at the start of the increment.
struct ContactCandidate {
  int node;
  int die;
  Eigen::Vector3d normal; ///< die outward normal at the projection
  double gap;             ///< δ₀, signed distance (mm)
  double area;            ///< tributary boundary area (mm²)
};

class RigidContact final : public solver::NodalTerm {
public:
  /// Boundary nodes of `mesh` within `search_distance` (mm) of a die, each
  /// paired with its nearest die; `node_area` is the tributary boundary area.
  void search(const mesh::TetMesh& mesh, const std::vector<DieView>& dies, double search_distance);
  void set_increment(const ContactIncrement& increment) { increment_ = increment; }
  void set_tangent_sensitivity_floor(double floor) override { tangent_sensitivity_floor_ = floor; }
  void set_line_search_step(double step) override { dual_.set_step(step); }

  void add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual, std::vector<solver::NodeBlock>* blocks,
           const std::vector<char>* rows = nullptr) const override;
  void start(const Eigen::VectorXd& nodal) override;
  std::string accept(const Eigen::VectorXd& nodal) override;
  bool consistent(const Eigen::VectorXd& nodal, bool converged) override;
  bool set_changed() const override { return active_.last_changes() > 0; }
  bool set_follows_iterates() const override { return active_.following(); }
  bool linear() const override;

  /// Force each die receives from the body (N), at `nodal`.
  std::vector<Eigen::Vector3d> die_forces(const Eigen::VectorXd& nodal) const;
  /// Contact pressure σn (MPa) of candidate `i` at `nodal` (0 when released).
  double pressure(int i, const Eigen::VectorXd& nodal) const;
  /// |w| (mm/s): how fast candidate `i` slides on its die at `nodal`.
  double sliding_speed(int i, const Eigen::VectorXd& nodal) const { return sliding(candidates_[i], nodal).norm(); }
  /// Friction power τ·w A (mW) at candidate `i` at `nodal`, the heat its
  /// sliding makes; 0 when released or frictionless.
  double friction_power(int i, const Eigen::VectorXd& nodal) const;
  /// Earliest time (s) at which a candidate that is not touching (gap above
  /// `touching`, mm) reaches its die when moving with `nodal`; infinity if none.
  double first_contact_time(const Eigen::VectorXd& nodal, double touching) const;

  const std::vector<ContactCandidate>& candidates() const { return candidates_; }
  int active_count() const { return active_.count(); }

private:
  double gap_velocity(const ContactCandidate& c, const Eigen::VectorXd& nodal) const;
  /// w: the tangential velocity of the node relative to its die.
  Eigen::Vector3d sliding(const ContactCandidate& c, const Eigen::VectorXd& nodal) const;
  /// τ of the die's friction law at candidate `i`, under contact pressure `sigma_n`.
  FrictionStress friction(int i, const Eigen::VectorXd& nodal, double sigma_n) const;
  /// h of every candidate at `nodal`, into gap_.
  const std::vector<double>& gaps(const Eigen::VectorXd& nodal);

  std::vector<DieView> dies_;
  std::vector<ContactCandidate> candidates_;
  ContactIncrement increment_{};
  double tangent_sensitivity_floor_ = 0.0;
  ActiveSet active_;        ///< per candidate
  std::vector<double> gap_; ///< per candidate, h at the last iterate asked
  FrictionDual dual_;       ///< per candidate
};

/// Tributary boundary area of each node (mm²): a third of each adjacent
/// boundary face, leaving out the faces `skip` marks (empty: none).
std::vector<double> boundary_node_areas(const mesh::TetMesh& mesh, std::span<const char> skip = {});

} // namespace anvil::contact
