#include "anvil/thermal/HeatStep.h"

#include "anvil/core/error.h"
#include "anvil/mesh/tet_geometry.h"

#include <Eigen/IterativeLinearSolvers>
#include <cmath>
#include <string>

namespace anvil::thermal {
namespace {
/// What a failed heat step asks the user to look at.
constexpr const char* kThermalKeys =
    "check thermal.environment.convection, dies[].heat_transfer, contact_pairs[].heat_transfer, the time step "
    "(time.stroke_increment) and the material cards' conductivity, specific_heat and density";
} // namespace
// The capacity term keeps the matrix well conditioned at forging time steps
// (C/Δt is of the order of the conduction of an element): conjugate
// gradients with a diagonal preconditioner need a few tens of iterations,
// where a sparse Cholesky factorisation of the same 3D mesh costs ten times more.
struct HeatStep::Solver {
  Eigen::SparseMatrix<double> exchange; ///< conduction and exchanges (lower triangle): the linear part
  Eigen::SparseMatrix<double> matrix;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower> cg;
};

HeatStep::HeatStep() : solver_(std::make_unique<Solver>()) {}
HeatStep::~HeatStep() = default;
HeatStep::HeatStep(HeatStep&&) noexcept = default;
HeatStep& HeatStep::operator=(HeatStep&&) noexcept = default;

NodalMass nodal_mass(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials) {
  NodalMass m{std::vector<double>(mesh.nodes.size(), 0.0), std::vector<const ThermalMaterial*>(mesh.nodes.size())};
  for (int e = 0; e < mesh.tet_count(); ++e) {
    if (!materials[e]) continue;
    const double quarter = 0.25e-6 * materials[e]->density * mesh::signed_volume(mesh, e);
    for (int node : mesh.tets[e]) {
      m.mass[node] += quarter;
      m.material[node] = materials[e];
    }
  }
  return m;
}

HeatFlows HeatStep::advance(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials,
                            const HeatStepInput& in, std::vector<double>& temperature) {
  const int n = mesh.node_count();
  const double dt = in.time_step;
  const NodalMass m = nodal_mass(mesh, materials);
  auto solved = [&](int node) { return m.material[node] != nullptr; };

  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  entries_.clear();
  // Entry (row, col) of the matrix; a column of a fixed node goes to the
  // right-hand side with its known temperature. Lower triangle only.
  auto add = [&](int row, int col, double value) {
    if (!solved(row)) return;
    if (!solved(col)) {
      rhs[row] -= value * temperature[col];
      return;
    }
    if (row >= col) entries_.emplace_back(row, col, value);
  };
  for (int i = 0; i < n; ++i)
    if (!solved(i)) {
      entries_.emplace_back(i, i, 1.0);
      rhs[i] = temperature[i];
    }
  for (int e = 0; e < mesh.tet_count(); ++e) {
    if (!materials[e]) continue;
    const mesh::Tet& t = mesh.tets[e];
    const mesh::P1Gradients g =
        mesh::p1_gradients(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    const double k = materials[e]->conductivity.at(element_mean(t, temperature));
    const Eigen::Matrix4d ke = k * g.volume * g.grad * g.grad.transpose();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        add(t[a], t[b], ke(a, b));
  }
  double sources = 0.0;
  for (int e = 0; e < static_cast<int>(in.element_power.size()); ++e) {
    if (!materials[e] || in.element_power[e] == 0.0) continue;
    for (int node : mesh.tets[e])
      rhs[node] += 0.25 * in.element_power[e];
    sources += in.element_power[e] * dt;
  }
  for (int i = 0; i < static_cast<int>(in.node_power.size()); ++i)
    if (solved(i)) {
      rhs[i] += in.node_power[i];
      sources += in.node_power[i] * dt;
    }
  for (const NodeExchange& x : in.exchanges) {
    const double ha = x.coefficient * x.area;
    add(x.node, x.node, ha);
    if (solved(x.node)) rhs[x.node] += ha * x.far_temperature;
  }
  // q = hA cᵀT with c = (1, −N): the matrix takes hA c cᵀ.
  for (const FacetExchange& x : in.facet_contacts) {
    const double ha = x.coefficient * x.area;
    const std::array<int, 4> nodes{x.node, x.facet[0], x.facet[1], x.facet[2]};
    const std::array<double, 4> weight{1.0, -x.shape[0], -x.shape[1], -x.shape[2]};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        add(nodes[a], nodes[b], ha * weight[a] * weight[b]);
  }

  // Newton on the enthalpy form, r(T) = m (H(T) − H(T_n))/Δt + (K + H) T − b
  // = 0 with tangent m c(T)/Δt + K + H: at its root the stored change is the
  // change of enthalpy exactly. One solve when c is constant (r is linear).
  Solver& s = *solver_;
  for (int i = 0; i < n; ++i) // every solved node's diagonal in the pattern: the capacity goes there
    if (solved(i)) entries_.emplace_back(i, i, 0.0);
  s.exchange.resize(n, n);
  s.exchange.setFromTriplets(entries_.begin(), entries_.end());
  bool linear = true;
  for (int i = 0; i < n; ++i)
    if (solved(i)) linear = linear && m.material[i]->specific_heat.constant();
  const Eigen::Map<const Eigen::VectorXd> start(temperature.data(), n);
  Eigen::VectorXd next = start, residual(n), change(n);
  HeatFlows flows;
  constexpr int kMostSolves = 20;
  s.cg.setTolerance(1e-13);
  s.cg.setMaxIterations(5 * n);
  for (;;) {
    residual.noalias() = s.exchange.selfadjointView<Eigen::Lower>() * next;
    residual -= rhs;
    s.matrix = s.exchange;
    for (int i = 0; i < n; ++i)
      if (solved(i)) {
        const auto& c = m.material[i]->specific_heat;
        residual[i] += m.mass[i] * c.mean(start[i], next[i]) * (next[i] - start[i]) / dt;
        s.matrix.coeffRef(i, i) += m.mass[i] * c.at(next[i]) / dt;
      }
    s.cg.compute(s.matrix);
    change = s.cg.solve(residual);
    if (s.cg.info() != Eigen::Success)
      throw RunError("heat step (thermal effect): conjugate gradients did not converge (" +
                     std::to_string(s.cg.iterations()) + " iterations): " + kThermalKeys);
    next -= change;
    ++flows.solves;
    if (linear || change.lpNorm<Eigen::Infinity>() <= 1e-9 * (1.0 + next.lpNorm<Eigen::Infinity>())) break;
    if (flows.solves == kMostSolves)
      throw RunError("heat step (thermal effect): Newton on the enthalpy did not converge in " +
                     std::to_string(kMostSolves) + " solves (a specific-heat table with a jump?): " + kThermalKeys);
  }
  flows.sources = sources;
  for (int i = 0; i < n; ++i) // the secant capacity times ΔT: m ΔH
    if (solved(i))
      flows.stored += m.mass[i] * m.material[i]->specific_heat.mean(start[i], next[i]) * (next[i] - start[i]);
  for (const NodeExchange& x : in.exchanges) {
    if (!solved(x.node)) continue;
    const double heat = x.coefficient * x.area * (next[x.node] - x.far_temperature) * dt;
    (x.sink == Sink::environment ? flows.to_environment : flows.to_dies) += heat;
  }
  // Between a solved body and one that is not, the heat leaves the budget: to the dies.
  for (const FacetExchange& x : in.facet_contacts) {
    const double q =
        x.coefficient * x.area * dt *
        (next[x.node] - x.shape[0] * next[x.facet[0]] - x.shape[1] * next[x.facet[1]] - x.shape[2] * next[x.facet[2]]);
    if (solved(x.node)) {
      for (int j = 0; j < 3; ++j)
        if (!solved(x.facet[j])) flows.to_dies += q * x.shape[j];
    } else {
      for (int j = 0; j < 3; ++j)
        if (solved(x.facet[j])) flows.to_dies -= q * x.shape[j];
    }
  }
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(next[i]) || next[i] <= -273.15)
      throw RunError("heat step (thermal effect): the temperature of node " + std::to_string(i + 1) + " became " +
                     std::to_string(next[i]) + " C: " + kThermalKeys);
  for (int i = 0; i < n; ++i)
    temperature[i] = next[i];
  return flows;
}

double stored_heat(const mesh::TetMesh& mesh, const mesh::MeshRange& range,
                   std::span<const ThermalMaterial* const> materials, std::span<const double> temperature) {
  return enthalpy(nodal_mass(mesh, materials), range, temperature);
}

double enthalpy(const NodalMass& m, const mesh::MeshRange& range, std::span<const double> temperature) {
  double heat = 0.0;
  for (int i = range.first_node; i < range.first_node + range.node_count; ++i)
    if (m.material[i]) heat += m.mass[i] * m.material[i]->specific_heat.integral(temperature[i]);
  return heat;
}

} // namespace anvil::thermal
