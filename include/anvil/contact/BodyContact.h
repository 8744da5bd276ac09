// Contact between deformable bodies (Fourment 2008, docs/design.md §3). One search
// and projection for every formulation (contact/ContactSurface.h): points of
// one body of a pair are projected onto the other body's contact surface. A
// projected point p gives the gap velocity of the increment, linear in v:
//   h_p = −(Σ_i M_i v_i − Σ_j N_j(ξ) v_j)·n − δ₀/Δt   (paper eq. 4, in velocity)
// with M_i the point's own shape functions (1 at a node), N_j(ξ) those of the
// facet it projects onto, n that facet body's outward normal, δ₀ the signed
// distance. The formulations differ only in how points are weighted into
// constraints, one multiplier λ_m each:
//   C_m = Σ_p W_pm c_p h_p,   G_m = Σ_p W_pm c_p,   Ã_m = Σ_p W_pm f_p A_p
// Nodal integration (paper §4): the points are boundary nodes, c_p = f_p (a
// constraint adds the nodes' gap velocities, not their areas), A_p the
// node's tributary area:
//   master/slave    (eq. 19): slave nodes only, f = 1, W = 1 on their own λ;
//   symmetric       (eq. 20): nodes of both bodies, f = ½, each its own λ;
//   quasi-symmetric (eqs. 21-24): nodes of both bodies, f = ½; a master node l
//     has no λ of its own: W = N_a^k(ξ_a^l), the slave facet's shape functions
//     at its projection, on the slave nodes' λ (eq. 22), so C_k is eq. 24.
//     A fine master thus outweighs a coarse slave node (the paper's "dominant"
//     master contribution); weighting by area instead would leave the fine
//     master free to sink between the coarse slave's nodes.
// Facet integration (paper §3): the points are quadrature points of the
// boundary facets (contact/facet_quadrature.h), c_p = f_p A_p with A_p the
// point's quadrature weight, so C_m is the integral of the weighted gap:
//   master/slave    (eqs. 10-11): slave facets, λ interpolated on them,
//     W = M_k(ξ_p) on slave node k's λ;
//   symmetric       (eqs. 12-13): facets of both bodies, f = ½, each side's
//     points on its own nodes' λ;
//   quasi-symmetric (eqs. 14-18): both, f = ½; a master point weighs
//     λ̃ = Σ_l M_l(ξ_p) Σ_k N_a^k(ξ_a^l) λ_k (eq. 17), with ξ_a^l the
//     projection of master node l onto the slave surface, so C_k is eq. 18.
//     A master node out of reach of the slave surface carries no λ̃.
// Penalty: λ_m = ρ C_m⁺/G_m (MPa, ρ times the mean gap velocity) acting on
// the area Ã_m, from the potential Π = Σ_m ρ Ã_m (C_m⁺)²/(2 G_m²): multiplier
// m transmits λ_m Ã_m. On matching meshes the nodal forms give the same Π.
// The active set is per multiplier (contact/ActiveSet.h).
// Friction: sticking is a penalty on the tangential relative velocity
// combined the same way; Tresca, Coulomb and Norton act at each point with
// its own pressure Σ_m W_pm λ_m on its area f_p A_p.
#pragma once
#include "anvil/contact/ActiveSet.h"
#include "anvil/contact/ContactIncrement.h"
#include "anvil/contact/Friction.h"
#include "anvil/contact/FrictionDual.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/solver/NodalTerm.h"

#include <array>
#include <string>
#include <vector>

namespace anvil::contact {

enum class PairFormulation { master_slave, symmetric, quasi_symmetric };
PairFormulation pair_formulation(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(PairFormulation formulation);

enum class PairIntegration { nodal, facet };
PairIntegration pair_integration(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(PairIntegration integration);

/// Facet integration's quadrature (contact/facet_quadrature.h).
enum class FacetQuadrature { intersection, subdivision };
FacetQuadrature facet_quadrature(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(FacetQuadrature quadrature);

/// How a pair's contact term is discretised.
struct PairMethod {
  PairFormulation formulation = PairFormulation::quasi_symmetric;
  PairIntegration integration = PairIntegration::nodal;
  FacetQuadrature quadrature = FacetQuadrature::intersection;
  int facet_subdivision = 4; ///< subdivision quadrature: most levels
};
std::string describe(const PairMethod& method);

/// A contact pair as contact sees it. A body paired with itself is in
/// self-contact: each of its boundary nodes is projected onto the facets of
/// the body that face it (ContactSurface::project_self), as the symmetric
/// nodal form (eq. 20) would do between two bodies: each node its own λ,
/// f = ½, since the nodes of both sides of a fold take part.
struct BodyPair {
  std::string name;
  mesh::MeshRange master, slave;
  PairMethod method;
  FrictionLaw friction;

  bool self() const { return master.first_node == slave.first_node; }
};

/// λ_m weighted into a point's constraint.
struct MultiplierWeight {
  int multiplier;
  double weight; ///< W_pm
};

/// A point of one body's surface projected onto the other body's surface:
/// a boundary node, or a quadrature point of a boundary facet.
struct ContactPoint {
  int pair;
  std::array<int, 3> own{-1, -1, -1};       ///< the point's own nodes: the node itself (own[0]), or its facet's
  Eigen::Vector3d own_shape{1.0, 0.0, 0.0}; ///< M_i, their shape functions at the point
  std::array<int, 3> facet;                 ///< nodes of the facet it projects onto
  Eigen::Vector3d shape;                    ///< N_j(ξ) of the facet at the projection
  Eigen::Vector3d normal;                   ///< outward normal of the facet's body there (towards the point)
  double gap;                               ///< δ₀ (mm), < 0 penetrated
  double area;  ///< A_p (mm²): a node's tributary area on the faces looking at the other body, or a quadrature weight
  double share; ///< f_p: 1 (eqs. 10, 19) or ½ (eqs. 12, 14, 20, 21)
  double gap_weight; ///< c_p, the weight of h_p in its constraints: f_p (nodal) or f_p A_p (facet)
  bool on_slave;     ///< on the slave (projected onto a master facet); else on the master
  std::vector<MultiplierWeight> multipliers{}; ///< the λ_m it feeds

  int node() const { return own[0]; } ///< the node, for a projected node
};

/// Velocity of the point relative to its projection, Σ M_i v_i − Σ_j N_j(ξ) v_j (mm/s).
Eigen::Vector3d relative_velocity(const ContactPoint& p, const Eigen::VectorXd& nodal);

class BodyContact final : public solver::NodalTerm {
public:
  /// `symmetry_faces`: per boundary face of the mesh, 1 where the face lies
  /// on a symmetry plane of its body (empty: none). Such a face is no
  /// contact surface: beyond it lies the body's mirror image, and a point
  /// pressed a hair into the other body, on the symmetry plane they share,
  /// would otherwise find it closest.
  explicit BodyContact(std::vector<BodyPair> pairs, std::vector<char> symmetry_faces = {})
      : pairs_(std::move(pairs)), symmetry_faces_(std::move(symmetry_faces)) {}

  /// Projects the boundary nodes of each pair (slave nodes, and master nodes
  /// unless master/slave) that are within `search_distance` (mm) of the other
  /// body, and, for facet integration, the quadrature points of their facets.
  void search(const mesh::TetMesh& mesh, double search_distance);
  void set_increment(const ContactIncrement& increment);
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
  std::vector<std::pair<int, int>> couplings() const override;

  const std::vector<BodyPair>& pairs() const { return pairs_; }
  const std::vector<char>& symmetry_faces() const { return symmetry_faces_; }
  /// The points whose gaps make the constraints: the projected nodes of
  /// nodal pairs, the quadrature points of facet pairs.
  const std::vector<ContactPoint>& points() const { return points_; }
  /// The projected boundary nodes of every pair, whatever its integration.
  const std::vector<ContactPoint>& projected_nodes() const { return nodes_; }
  /// Contact pressure (MPa) at projected node i: Σ_m W λ_m over its active
  /// multipliers (its own λ, or for a quasi-symmetric master node λ̃, eq. 22).
  double node_pressure(int i, const Eigen::VectorXd& nodal) const;
  int active_count() const { return active_.count(); }
  /// Friction power τ·w f_p A_p (mW) at each of points() at `nodal`, with
  /// the pressures of the last add(): the heat sliding makes there (0 where
  /// a point does not touch, and for frictionless and sticking pairs).
  void friction_power(const Eigen::VectorXd& nodal, std::vector<double>& power) const;

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
  double pressure(const ContactPoint& p, const Eigen::VectorXd& nodal) const;
  /// w: the point's tangential velocity relative to its projection, from the point's side.
  Eigen::Vector3d sliding(const ContactPoint& p, const Eigen::VectorXd& nodal) const;
  /// τ of the pair's friction law at touching point `i` of points_, under the pressure of
  /// its multipliers; false where it does not touch or the law has no τ of its own.
  bool point_friction(int i, const Eigen::VectorXd& nodal, FrictionStress& f) const;

  std::vector<BodyPair> pairs_;
  std::vector<char> symmetry_faces_;
  std::vector<ContactPoint> nodes_;
  std::vector<ContactPoint> points_;
  std::vector<Multiplier> multipliers_;
  std::vector<Support> support_;
  ContactIncrement increment_{};
  double tangent_sensitivity_floor_ = 0.0;
  ActiveSet active_;                   ///< per multiplier
  std::vector<double> gap_;            ///< per multiplier, C/Ã at the last iterate asked (mm/s)
  mutable std::vector<double> stress_; ///< per multiplier, λ of the last add() (MPa), 0 when inactive
  FrictionDual dual_;                  ///< per point of points_
};

} // namespace anvil::contact
