#include "anvil/thermal/HeatStep.h"

#include "anvil/core/error.h"
#include "anvil/mesh/tet_geometry.h"

#include <Eigen/CholmodSupport>

namespace anvil::thermal {
namespace {

double element_temperature(const mesh::Tet& t, std::span<const double> temperature) {
  return 0.25 * (temperature[t[0]] + temperature[t[1]] + temperature[t[2]] + temperature[t[3]]);
}

} // namespace

struct HeatStep::Solver {
  Eigen::SparseMatrix<double> matrix;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholesky;
};

HeatStep::HeatStep() : solver_(std::make_unique<Solver>()) {}
HeatStep::~HeatStep() = default;
HeatStep::HeatStep(HeatStep&&) noexcept = default;
HeatStep& HeatStep::operator=(HeatStep&&) noexcept = default;

std::vector<double> HeatStep::capacity(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials,
                                       std::span<const double> temperature) {
  std::vector<double> c(mesh.nodes.size(), 0.0);
  for (int e = 0; e < mesh.tet_count(); ++e) {
    if (!materials[e]) continue;
    const mesh::Tet& t = mesh.tets[e];
    const double quarter =
        0.25 * materials[e]->capacity(element_temperature(t, temperature)) * mesh::signed_volume(mesh, e);
    for (int node : t)
      c[node] += quarter;
  }
  return c;
}

HeatFlows HeatStep::advance(const mesh::TetMesh& mesh, std::span<const ThermalMaterial* const> materials,
                            const HeatStepInput& in, std::vector<double>& temperature) {
  const int n = mesh.node_count();
  const double dt = in.time_step;
  const std::vector<double> c = capacity(mesh, materials, temperature);
  solved_.assign(n, 0);
  for (int e = 0; e < mesh.tet_count(); ++e)
    if (materials[e])
      for (int node : mesh.tets[e])
        solved_[node] = 1;

  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  entries_.clear();
  // Entry (row, col) of the matrix; a column of a fixed node goes to the
  // right-hand side with its known temperature. Lower triangle only.
  auto add = [&](int row, int col, double value) {
    if (!solved_[row]) return;
    if (!solved_[col]) {
      rhs[row] -= value * temperature[col];
      return;
    }
    if (row >= col) entries_.emplace_back(row, col, value);
  };
  for (int i = 0; i < n; ++i) {
    if (!solved_[i]) {
      entries_.emplace_back(i, i, 1.0);
      rhs[i] = temperature[i];
      continue;
    }
    entries_.emplace_back(i, i, c[i] / dt);
    rhs[i] += c[i] / dt * temperature[i];
  }
  for (int e = 0; e < mesh.tet_count(); ++e) {
    if (!materials[e]) continue;
    const mesh::Tet& t = mesh.tets[e];
    const mesh::P1Gradients g =
        mesh::p1_gradients(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    const double k = materials[e]->conductivity.at(element_temperature(t, temperature));
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
    if (solved_[i]) {
      rhs[i] += in.node_power[i];
      sources += in.node_power[i] * dt;
    }
  for (const NodeExchange& x : in.exchanges) {
    const double ha = x.coefficient * x.area;
    add(x.node, x.node, ha);
    if (solved_[x.node]) rhs[x.node] += ha * x.far_temperature;
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

  Solver& s = *solver_;
  s.matrix.resize(n, n);
  s.matrix.setFromTriplets(entries_.begin(), entries_.end());
  s.cholesky.compute(s.matrix);
  if (s.cholesky.info() != Eigen::Success)
    throw RunError("heat step: the conduction matrix cannot be factorised (an element with a non-positive "
                   "conductivity or capacity?)");
  const Eigen::VectorXd next = s.cholesky.solve(rhs);

  HeatFlows flows;
  flows.sources = sources;
  for (int i = 0; i < n; ++i)
    if (solved_[i]) flows.stored += c[i] * (next[i] - temperature[i]);
  for (const NodeExchange& x : in.exchanges) {
    if (!solved_[x.node]) continue;
    const double heat = x.coefficient * x.area * (next[x.node] - x.far_temperature) * dt;
    (x.sink == Sink::environment ? flows.to_environment : flows.to_dies) += heat;
  }
  // Between a solved body and one that is not, the heat leaves the budget: to the dies.
  for (const FacetExchange& x : in.facet_contacts) {
    const double q =
        x.coefficient * x.area * dt *
        (next[x.node] - x.shape[0] * next[x.facet[0]] - x.shape[1] * next[x.facet[1]] - x.shape[2] * next[x.facet[2]]);
    if (solved_[x.node]) {
      for (int j = 0; j < 3; ++j)
        if (!solved_[x.facet[j]]) flows.to_dies += q * x.shape[j];
    } else {
      for (int j = 0; j < 3; ++j)
        if (solved_[x.facet[j]]) flows.to_dies -= q * x.shape[j];
    }
  }
  for (int i = 0; i < n; ++i)
    temperature[i] = next[i];
  return flows;
}

double stored_heat(const mesh::TetMesh& mesh, const mesh::MeshRange& range,
                   std::span<const ThermalMaterial* const> materials, std::span<const double> temperature) {
  const std::vector<double> c = HeatStep::capacity(mesh, materials, temperature);
  double heat = 0.0;
  for (int i = range.first_node; i < range.first_node + range.node_count; ++i)
    heat += c[i] * temperature[i];
  return heat;
}

} // namespace anvil::thermal
