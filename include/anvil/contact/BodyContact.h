// Node-to-facet contact between deformable bodies (Fourment 2008, DESIGN §3).
// One search and projection for every formulation: the boundary nodes of one
// body of a pair are projected onto the other body's boundary facets. A
// projected node p gives the gap velocity of the increment, linear in v:
//   h_p = −(v_node − Σ_j N_j(ξ) v_j)·n − δ₀/Δt     (paper eq. 4, in velocity)
// with n the facet body's outward normal, δ₀ the signed distance.
// The formulations differ only in how points are weighted into constraints,
// one multiplier λ_m each. In the nodal formulation (paper §4) a constraint
// adds the nodes' gap velocities, not their areas:
//   C_m = Σ_p W_pm f_p h_p,   G_m = Σ_p W_pm f_p,   Ã_m = Σ_p W_pm f_p A_p
//   master/slave    (eq. 19): slave nodes only, f = 1, W = 1 on their own λ;
//   symmetric       (eq. 20): nodes of both bodies, f = ½, each its own λ;
//   quasi-symmetric (eqs. 21-24): nodes of both bodies, f = ½; a master node l
//     has no λ of its own: W = N_a^k(ξ_a^l), the slave facet's shape functions
//     at its projection, on the slave nodes' λ (eq. 22), so C_k is eq. 24.
//     A fine master thus outweighs a coarse slave node (the paper's "dominant"
//     master contribution); weighting by area instead would leave the fine
//     master free to sink between the coarse slave's nodes. Measured on the
//     patch test (case 1, M/S error 3.70 %): area weights gave 18.8 % on the
//     4/15 pair (2.41 % as here), and 4.0 % against 2.7 % on 4/7.
// Penalty: λ_m = ρ C_m⁺/G_m (MPa, ρ times the mean gap velocity) acting on
// the area Ã_m, from the potential Π = Σ_m ρ Ã_m (C_m⁺)²/(2 G_m²): multiplier
// m transmits λ_m Ã_m. On matching meshes the three give the same Π.
// The active set is per multiplier (contact/ActiveSet.h).
// Friction: sticking is a penalty on the tangential relative velocity
// combined the same way; Tresca, Coulomb and Norton act at each point with
// its own pressure Σ_m W_pm λ_m on its area f_p A_p.
#pragma once
#include "anvil/contact/ActiveSet.h"
#include "anvil/contact/ContactIncrement.h"
#include "anvil/contact/Friction.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/solver/NodalTerm.h"

#include <array>
#include <string>
#include <vector>

namespace anvil::contact {

enum class PairFormulation { master_slave, symmetric, quasi_symmetric };
PairFormulation pair_formulation(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(PairFormulation formulation);

/// A contact pair as contact sees it.
struct BodyPair {
  std::string name;
  mesh::MeshRange master, slave;
  PairFormulation formulation = PairFormulation::quasi_symmetric;
  FrictionLaw friction;
};

/// A boundary node projected onto the other body's surface.
struct ContactPoint {
  int pair;
  int node;
  std::array<int, 3> facet; ///< nodes of the facet it projects onto
  Eigen::Vector3d shape;    ///< N_j(ξ) of the facet at the projection
  Eigen::Vector3d normal;   ///< outward normal of the facet's body there (towards the node)
  double gap;               ///< δ₀ (mm), < 0 penetrated
  double area;              ///< tributary area A_p of the node on the faces looking at the other body (mm²)
  double share;             ///< f_p: 1 (eq. 19) or ½ (eqs. 20-21)
  bool on_slave;            ///< a slave node (on a master facet); else a master node
  std::array<int, 3> multiplier{-1, -1, -1};                   ///< multipliers it feeds
  Eigen::Vector3d multiplier_weight = Eigen::Vector3d::Zero(); ///< W_pm
};

/// Velocity of the point's node relative to its projection, v_node − Σ_j N_j(ξ) v_j (mm/s).
Eigen::Vector3d relative_velocity(const ContactPoint& p, const Eigen::VectorXd& nodal);

class BodyContact final : public solver::NodalTerm {
public:
  explicit BodyContact(std::vector<BodyPair> pairs) : pairs_(std::move(pairs)) {}

  /// Projects the boundary nodes of each pair (slave nodes, and master nodes
  /// unless master/slave) that are within `search_distance` (mm) of the other body.
  void search(const mesh::TetMesh& mesh, double search_distance);
  void set_increment(const ContactIncrement& increment);

  void add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual,
           std::vector<solver::NodeBlock>* blocks) const override;
  void start(const Eigen::VectorXd& nodal) override;
  std::string accept(const Eigen::VectorXd& nodal) override;
  bool consistent(const Eigen::VectorXd& nodal) override;
  bool set_changed() const override { return active_.last_changes() > 0; }
  bool linear() const override;
  std::vector<std::pair<int, int>> couplings() const override;

  const std::vector<BodyPair>& pairs() const { return pairs_; }
  const std::vector<ContactPoint>& points() const { return points_; }
  /// Contact pressure (MPa) at point i: Σ_m W λ_m over active multipliers.
  double pressure(int i, const Eigen::VectorXd& nodal) const;
  int active_count() const { return active_.count(); }

private:
  /// One constraint: C = Σ_i c_i·v_i − gap_sum/Δt over its support nodes.
  struct Multiplier {
    int pair;
    double node_weight = 0.0; ///< G = Σ W f
    double area = 0.0;        ///< Ã = Σ W f A (mm²), on which λ acts
    double gap_sum = 0.0;     ///< Σ W f δ₀ (mm)
    int first = 0, count = 0; ///< range in support_
  };
  struct Support {
    int node;
    Eigen::Vector3d normal;     ///< c_i = ∂C/∂v_i
    Eigen::Matrix3d tangential; ///< ∂T/∂v_i, T the combined tangential velocity (sticking)
  };

  /// C/G of multiplier `index` at `nodal`: its weighted mean gap velocity (mm/s).
  double mean_gap_velocity(std::size_t index, const Eigen::VectorXd& nodal) const;
  const std::vector<double>& gaps(const Eigen::VectorXd& nodal);
  void build_multipliers(int node_count);

  std::vector<BodyPair> pairs_;
  std::vector<ContactPoint> points_;
  std::vector<Multiplier> multipliers_;
  std::vector<Support> support_;
  ContactIncrement increment_{};
  ActiveSet active_;                   ///< per multiplier
  std::vector<double> gap_;            ///< per multiplier, C/Ã at the last iterate asked (mm/s)
  mutable std::vector<double> stress_; ///< per multiplier, λ of the last add() (MPa), 0 when inactive
};

} // namespace anvil::contact
