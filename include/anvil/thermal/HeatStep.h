// One backward-Euler step of the heat equation (docs/design.md §2, heat) on linear
// tetrahedra, the same mesh the flow is solved on:
//   (C/Δt + K + H) T_{n+1} = C/Δt T_n + Q + H T_far
// C the lumped (row-sum) capacity: no undershoot at small Δt (docs/heat.md
// "Numerics"); K the conduction, k(T_n) V ∇N∇Nᵀ per element; H the
// exchanges of boundary nodes, with a far temperature (air, rigid die, a
// body not solved for heat) or with the facet of another body they touch;
// Q the heat sources (plastic work per element, friction per node). The
// capacity of node i is its lumped mass m_i = Σ_e ρ V_e/4 times the secant
// specific heat (H(T_{n+1}) − H(T_n))/(T_{n+1} − T_n), H = ∫c dT: the step
// solves the enthalpy form m (H(T) − H(T_n))/Δt + (K + H) T = b by Newton
// (tangent m c(T)/Δt + K + H), so that C ΔT is the node's change of
// enthalpy exactly and a step across the steel's transformation peak of c
// neither misses nor invents its latent heat; one solve when c is constant.
// The matrix is symmetric positive definite: conjugate gradients (Eigen).
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/thermal/ThermalMaterial.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <span>
#include <vector>

namespace anvil::thermal {

/// Where the heat a boundary node exchanges goes: the budget line it feeds.
enum class Sink { environment, dies };

/// A boundary node exchanging q = h (T − T_far) (mW/mm²) over its area with
/// something at a known temperature.
struct NodeExchange {
  int node;
  double area;            ///< mm²
  double coefficient;     ///< h, mW/(mm²·K) = kW/(m²·K)
  double far_temperature; ///< °C
  Sink sink;
};

/// A boundary node exchanging q = h (T − Σ_j N_j T_j) over its area with the
/// facet of another body it touches; the facet's nodes receive it in
/// proportion N_j, so the exchange creates no heat.
struct FacetExchange {
  int node;
  std::array<int, 3> facet;
  Eigen::Vector3d shape; ///< N_j at the node's projection
  double area;           ///< mm²
  double coefficient;    ///< h, mW/(mm²·K)
};

/// What one step exchanged (mJ): the budget's lines (summary.json "heat").
struct HeatFlows {
  double sources = 0.0;        ///< Q Δt: plastic and friction heat put into the bodies
  double to_environment = 0.0; ///< Σ h A (T_{n+1} − T_far) Δt to the air
  double to_dies = 0.0;        ///< the same to rigid dies and bodies not solved for heat
  double stored = 0.0;         ///< Σ m (H(T_{n+1}) − H(T_n)): the change of the bodies' enthalpy
  int solves = 0;              ///< linear solves (Newton iterations on the enthalpy)
};

/// What a step needs besides the mesh and the temperatures.
struct HeatStepInput {
  double time_step;                              ///< Δt, s
  std::span<const double> element_power;         ///< mW per element (empty: none)
  std::span<const double> node_power;            ///< mW per node (empty: none)
  std::span<const NodeExchange> exchanges;       ///< with known temperatures
  std::span<const FacetExchange> facet_contacts; ///< between bodies
};

/// The step's solver: keeps its storage from one step to the next.
class HeatStep {
public:
  HeatStep();
  ~HeatStep();
  HeatStep(HeatStep&&) noexcept;
  HeatStep& operator=(HeatStep&&) noexcept;

  /// Advances `temperature` (°C, per node of `mesh`) over the step;
  /// `materials[e]` is element e's thermal material, or null where its body
  /// is not solved for heat (its nodes keep their temperature). Throws
  /// RunError when the system cannot be factorised.
  HeatFlows advance(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials,
                    const HeatStepInput& input, std::vector<double>& temperature);

private:
  struct Solver;
  std::unique_ptr<Solver> solver_;
  std::vector<Eigen::Triplet<double>> entries_;
};

/// The lumped thermal mass of each node: Σ_e ρ_e V_e/4 (1e-6 kg per mm³ of
/// kg/m³), and the material of a body solved for heat it belongs to (null:
/// not solved). A node's enthalpy is mass × ∫₀ᵀ c dT (mJ).
struct NodalMass {
  std::vector<double> mass;
  std::vector<const ThermalMaterial*> material;
};
NodalMass nodal_mass(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials);

/// Σ m_i H(T_i) (mJ) over the nodes of `range` with a material: their enthalpy above 0 °C.
double enthalpy(const NodalMass& m, const mesh::MeshRange& range, std::span<const double> temperature);

/// The mean of a tetrahedron's nodal values: its element's temperature.
inline double element_mean(const mesh::Tet& t, std::span<const double> nodal) {
  return 0.25 * (nodal[t[0]] + nodal[t[1]] + nodal[t[2]] + nodal[t[3]]);
}

/// Σ m_i H(T_i) (mJ) of the nodes of `range`: the enthalpy it stores above 0 °C.
double stored_heat(const mesh::TetMesh& mesh, const mesh::MeshRange& range,
                   std::span<const ThermalMaterial* const> materials, std::span<const double> temperature);

} // namespace anvil::thermal
