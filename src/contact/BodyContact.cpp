#include "anvil/contact/BodyContact.h"

#include "anvil/contact/ContactSurface.h"
#include "anvil/core/error.h"
#include "anvil/fem/DofMap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>

namespace anvil::contact {

using fem::kDofsPerNode;

PairFormulation pair_formulation(const std::string& name) {
  if (name == "master_slave") return PairFormulation::master_slave;
  if (name == "symmetric") return PairFormulation::symmetric;
  if (name == "quasi_symmetric") return PairFormulation::quasi_symmetric;
  throw InputError("unknown contact formulation '" + name + "' (expected master_slave, symmetric or quasi_symmetric)");
}

PairIntegration pair_integration(const std::string& name) {
  if (name == "nodal") return PairIntegration::nodal;
  if (name == "facet") return PairIntegration::facet;
  throw InputError("unknown contact integration '" + name + "' (expected nodal or facet)");
}

std::string to_string(PairIntegration integration) {
  return integration == PairIntegration::nodal ? "nodal" : "facet";
}

FacetQuadrature facet_quadrature(const std::string& name) {
  if (name == "intersection") return FacetQuadrature::intersection;
  if (name == "subdivision") return FacetQuadrature::subdivision;
  throw InputError("unknown facet quadrature '" + name + "' (expected intersection or subdivision)");
}

std::string to_string(FacetQuadrature quadrature) {
  return quadrature == FacetQuadrature::intersection ? "intersection" : "subdivision";
}

std::string describe(const PairMethod& method) {
  std::string text = to_string(method.formulation) + ", " + to_string(method.integration);
  if (method.integration == PairIntegration::facet)
    text += method.quadrature == FacetQuadrature::intersection
                ? " (over the facets' intersections)"
                : " (facets split up to " + std::to_string(method.facet_subdivision) + " levels)";
  return text;
}

std::string to_string(PairFormulation formulation) {
  switch (formulation) {
  case PairFormulation::master_slave:
    return "master_slave";
  case PairFormulation::symmetric:
    return "symmetric";
  case PairFormulation::quasi_symmetric:
    return "quasi_symmetric";
  }
  return "?";
}

namespace {

/// Σ_j w_j value[node_j] over the nodes of positive weight.
double interpolate(const std::vector<double>& nodal_value, const std::array<int, 3>& nodes, const Eigen::Vector3d& w) {
  double value = 0.0;
  for (int j = 0; j < 3; ++j)
    if (w[j] > 0.0) value += w[j] * nodal_value[nodes[j]];
  return value;
}

/// The smaller of a nodal value at the point and at its projection:
/// friction is bounded by the weaker body (an elastic die's value is infinite).
double weaker_side(const std::vector<double>& nodal_value, const ContactPoint& p) {
  return std::min(interpolate(nodal_value, p.own, p.own_shape), interpolate(nodal_value, p.facet, p.shape));
}

/// The six nodes of a point's relative velocity and their coefficients in
/// w = sense (Σ M_i v_i − Σ N_j v_j); an own node of −1 is absent.
struct RelativeStencil {
  std::array<int, 6> nodes;
  std::array<double, 6> coefficient;
};
RelativeStencil stencil(const ContactPoint& p, double sense) {
  RelativeStencil s;
  for (int k = 0; k < 3; ++k) {
    s.nodes[k] = p.own[k], s.coefficient[k] = sense * p.own_shape[k];
    s.nodes[3 + k] = p.facet[k], s.coefficient[3 + k] = -sense * p.shape[k];
  }
  return s;
}

} // namespace

Eigen::Vector3d relative_velocity(const ContactPoint& p, const Eigen::VectorXd& nodal) {
  Eigen::Vector3d relative = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (p.own[k] >= 0) relative += p.own_shape[k] * nodal.segment<3>(kDofsPerNode * p.own[k]);
  for (int j = 0; j < 3; ++j)
    relative -= p.shape[j] * nodal.segment<3>(kDofsPerNode * p.facet[j]);
  return relative;
}

void BodyContact::search(const mesh::TetMesh& mesh, double search_distance) {
  nodes_.clear();
  points_.clear();
  dual_ = FrictionDual{}; // set again when Newton starts
  const ContactBoundary boundary(mesh, symmetry_faces_);
  std::vector<FacetPoint> facet_points;
  for (std::size_t q = 0; q < pairs_.size(); ++q) {
    const BodyPair& pair = pairs_[q];
    const bool one_sided = pair.method.formulation == PairFormulation::master_slave;
    const double share = one_sided ? 1.0 : 0.5; // f_p: eqs. 10, 19 against the ½ of eqs. 12, 14, 20, 21
    // The surfaces projected onto: the master's, and the slave's unless
    // master/slave or the body's own (self-contact).
    const ContactSurface master(boundary, pair.master);
    const std::optional<ContactSurface> slave =
        one_sided || pair.self() ? std::nullopt : std::optional<ContactSurface>(std::in_place, boundary, pair.slave);
    // A point of `from` (own nodes and shape functions, area A_p) projected as `hit`.
    auto point = [&](const std::array<int, 3>& own, const Eigen::Vector3d& own_shape, const SurfaceProjection& hit,
                     double area, double gap_weight, bool on_slave) {
      return ContactPoint{.pair = static_cast<int>(q),
                          .own = own,
                          .own_shape = own_shape,
                          .facet = mesh.boundary_faces[hit.facet],
                          .shape = hit.shape,
                          .normal = hit.normal,
                          .gap = hit.gap,
                          .area = area,
                          .share = share,
                          .gap_weight = gap_weight,
                          .on_slave = on_slave};
    };
    // The boundary nodes of `from`, each projected by `project(node, its outward normal)`.
    auto project_nodes = [&](const mesh::MeshRange& from, auto&& project, bool on_slave) {
      for (int node = from.first_node; node < from.first_node + from.node_count; ++node) {
        const Eigen::Vector3d own = boundary.own_normal(node);
        if (own.isZero()) continue; // an interior node, or one on symmetry planes only
        const std::optional<SurfaceProjection> hit = project(node, own);
        if (!hit) continue;
        const double area = boundary.tributary_area(node, hit->normal);
        if (area == 0.0) continue; // no face looks at the other body: not on its contact surface
        nodes_.push_back(point({node, -1, -1}, Eigen::Vector3d::UnitX(), *hit, area, share, on_slave));
      }
    };
    auto onto = [&](const ContactSurface& surface) {
      return
          [&](int node, const Eigen::Vector3d& own) { return surface.project(mesh.nodes[node], own, search_distance); };
    };
    // The quadrature points of the facets of `from`, grouped by the facet
    // of the other body they fall on, so that add() sums their friction
    // blocks once per pair of facets.
    auto project_facets = [&](const mesh::MeshRange& from, const ContactSurface& target, bool on_slave) {
      for (int f = from.first_face; f < from.first_face + from.face_count; ++f) {
        if (boundary.on_symmetry_plane(f)) continue;
        const double facet_area = mesh::area_vector(mesh, mesh.boundary_faces[f]).norm();
        target.facet_points(f, pair.method, search_distance, facet_points);
        for (const FacetPoint& g : facet_points) {
          const double area = g.area_fraction * facet_area;
          points_.push_back(point(mesh.boundary_faces[f], g.barycentric, g.hit, area, share * area, on_slave));
        }
      }
    };
    const std::size_t first_node = nodes_.size();
    if (pair.self())
      project_nodes(
          pair.slave, [&](int node, const Eigen::Vector3d&) { return master.project_self(node, search_distance); },
          true);
    else
      project_nodes(pair.slave, onto(master), true);
    if (slave) project_nodes(pair.master, onto(*slave), false);
    if (pair.method.integration == PairIntegration::nodal) {
      points_.insert(points_.end(), nodes_.begin() + static_cast<std::ptrdiff_t>(first_node), nodes_.end());
      continue;
    }
    project_facets(pair.slave, master, true);
    if (slave) project_facets(pair.master, *slave, false);
  }
  build_multipliers(mesh.node_count());
}

void BodyContact::build_multipliers(int node_count) {
  multipliers_.clear();
  support_.clear();
  // The λ of each (pair, node), and the projection of each quasi-symmetric
  // master node onto the slave surface (eq. 16), by (pair, node).
  const std::size_t nodes = static_cast<std::size_t>(node_count);
  std::vector<int> own_multiplier(nodes * pairs_.size(), -1), master_projection(nodes * pairs_.size(), -1);
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (!nodes_[i].on_slave) master_projection[nodes * nodes_[i].pair + nodes_[i].node()] = static_cast<int>(i);
  // λ of `node` in `pair`; created when `create` (never an empty one), else −1 when absent.
  auto multiplier_of = [&](int pair, int node, bool create) {
    int& index = own_multiplier[nodes * pair + node];
    if (index < 0 && create) {
      multipliers_.push_back({pair});
      index = static_cast<int>(multipliers_.size()) - 1;
    }
    return index;
  };
  auto add_weight = [](std::vector<MultiplierWeight>& list, int m, double w) {
    if (m < 0 || w <= 0.0) return;
    for (MultiplierWeight& e : list)
      if (e.multiplier == m) return void(e.weight += w);
    list.push_back({m, w});
  };
  // W_pm of a point (see the header); `create` for the points that make the
  // constraints, not for the projected nodes that only report them.
  auto weigh = [&](ContactPoint& p, bool create) {
    p.multipliers.clear();
    const BodyPair& pair = pairs_[p.pair];
    const bool interpolated = pair.method.formulation == PairFormulation::quasi_symmetric && !p.on_slave;
    if (!interpolated) { // its own nodes' λ (eqs. 10-13, 19-20)
      for (int k = 0; k < 3; ++k)
        if (p.own[k] >= 0) add_weight(p.multipliers, multiplier_of(p.pair, p.own[k], create), p.own_shape[k]);
      return;
    }
    for (int l = 0; l < 3; ++l) { // λ̃ at its own nodes, from their projections on the slave (eqs. 17, 22)
      if (p.own[l] < 0 || p.own_shape[l] <= 0.0) continue;
      const int projection = master_projection[nodes * p.pair + p.own[l]];
      if (projection < 0) continue; // out of the slave surface's reach
      const ContactPoint& n = nodes_[projection];
      for (int k = 0; k < 3; ++k)
        add_weight(p.multipliers, multiplier_of(p.pair, n.facet[k], create), p.own_shape[l] * n.shape[k]);
    }
  };
  for (ContactPoint& p : points_)
    weigh(p, true);
  for (ContactPoint& n : nodes_)
    weigh(n, false);
  // Per multiplier, the points feeding it, then its support nodes with merged coefficients.
  std::vector<std::vector<std::pair<int, double>>> feeds(multipliers_.size());
  for (std::size_t i = 0; i < points_.size(); ++i)
    for (const MultiplierWeight& w : points_[i].multipliers)
      feeds[w.multiplier].push_back({static_cast<int>(i), w.weight});
  for (std::size_t m = 0; m < multipliers_.size(); ++m) {
    Multiplier& mult = multipliers_[m];
    mult.first = static_cast<int>(support_.size());
    auto add_support = [&](int node, const Eigen::Vector3d& normal, const Eigen::Matrix3d& tangential) {
      for (int s = mult.first; s < static_cast<int>(support_.size()); ++s)
        if (support_[s].node == node) {
          support_[s].normal += normal;
          support_[s].tangential += tangential;
          return;
        }
      support_.push_back({node, normal, tangential});
    };
    for (const auto& [i, w] : feeds[m]) {
      const ContactPoint& p = points_[i];
      const double scale = w * p.gap_weight;
      // h_p = −n·(Σ M_i v_i − Σ N_j v_j) − δ₀/Δt; tangential velocity in the
      // slave's sense (slave − master): sign +1 on the slave, −1 on the master.
      const double sense = p.on_slave ? 1.0 : -1.0;
      const RelativeStencil st = stencil(p, sense);
      const Eigen::Matrix3d tangent_projector = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
      for (int a = 0; a < 6; ++a)
        if (st.nodes[a] >= 0 && st.coefficient[a] != 0.0)
          add_support(st.nodes[a], -scale * sense * st.coefficient[a] * p.normal,
                      scale * st.coefficient[a] * tangent_projector);
      mult.node_weight += scale;
      mult.area += w * p.share * p.area;
      mult.gap_sum += scale * p.gap;
    }
    mult.count = static_cast<int>(support_.size()) - mult.first;
  }
  active_.resize(multipliers_.size());
  gap_.assign(multipliers_.size(), 0.0);
  stress_.assign(multipliers_.size(), 0.0);
}

void BodyContact::set_increment(const ContactIncrement& increment) {
  increment_ = increment;
  active_.set_tolerance(increment.gap_tolerance);
}

double BodyContact::mean_gap_velocity(std::size_t index, const Eigen::VectorXd& nodal) const {
  const Multiplier& m = multipliers_[index];
  double c = -m.gap_sum / increment_.closing_time(m.gap_sum);
  for (int s = m.first; s < m.first + m.count; ++s)
    c += support_[s].normal.dot(nodal.segment<3>(kDofsPerNode * support_[s].node));
  return c / m.node_weight;
}

const std::vector<double>& BodyContact::gaps(const Eigen::VectorXd& nodal) {
  for (std::size_t m = 0; m < multipliers_.size(); ++m)
    gap_[m] = mean_gap_velocity(m, nodal);
  return gap_;
}

void BodyContact::start(const Eigen::VectorXd& nodal) {
  active_.start(gaps(nodal));
  dual_.start(
      points_.size(), [&](std::size_t i) { return sliding(points_[i], nodal); }, increment_.regularisation);
}
bool BodyContact::consistent(const Eigen::VectorXd& nodal, bool converged) {
  return active_.consistent(gaps(nodal), converged);
}
bool BodyContact::linear() const {
  return std::all_of(pairs_.begin(), pairs_.end(), [](const BodyPair& p) { return is_linear(p.friction); });
}
std::string BodyContact::accept(const Eigen::VectorXd& nodal) {
  dual_.accept([&](std::size_t i) { return sliding(points_[i], nodal); });
  return active_.accept(gaps(nodal), "pair constraints");
}

double BodyContact::pressure(const ContactPoint& p, const Eigen::VectorXd& nodal) const {
  double pressure = 0.0;
  for (const MultiplierWeight& w : p.multipliers)
    if (active_[w.multiplier])
      pressure += w.weight * increment_.penalty * std::max(mean_gap_velocity(w.multiplier, nodal), 0.0);
  return pressure;
}

Eigen::Vector3d BodyContact::sliding(const ContactPoint& p, const Eigen::VectorXd& nodal) const {
  const double sense = p.on_slave ? 1.0 : -1.0;
  return sense * (Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose()) * relative_velocity(p, nodal);
}

bool BodyContact::point_friction(int i, const Eigen::VectorXd& nodal, FrictionStress& f) const {
  const ContactPoint& p = points_[i];
  const FrictionLaw& law = pairs_[p.pair].friction;
  if (law.kind == FrictionKind::frictionless || law.kind == FrictionKind::sticking) return false;
  double sigma_n = 0.0;
  bool touching = false;
  for (const MultiplierWeight& w : p.multipliers)
    if (active_[w.multiplier]) {
      touching = true;
      sigma_n += w.weight * stress_[w.multiplier];
    }
  if (!touching) return false;
  const Eigen::Vector3d w = sliding(p, nodal);
  f = friction_stress(law, {w, sigma_n, weaker_side(increment_.flow_stress, p), weaker_side(increment_.consistency, p),
                            increment_.regularisation, increment_.penalty, tangent_sensitivity_floor_,
                            dual_.direction(static_cast<std::size_t>(i), w)});
  return true;
}

void BodyContact::friction_power(const Eigen::VectorXd& nodal, std::vector<double>& power) const {
  power.assign(points_.size(), 0.0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    FrictionStress f;
    if (point_friction(static_cast<int>(i), nodal, f))
      power[i] = points_[i].share * points_[i].area * f.stress.dot(sliding(points_[i], nodal));
  }
}

double BodyContact::node_pressure(int i, const Eigen::VectorXd& nodal) const {
  return pressure(nodes_[i], nodal);
}

void BodyContact::add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual, std::vector<solver::NodeBlock>* blocks,
                      const std::vector<char>* rows) const {
  const double rho = increment_.penalty;
  auto computed = [rows](int node) { return !rows || (*rows)[node]; };
  for (std::size_t index = 0; index < multipliers_.size(); ++index) {
    // Normal: ∂Π/∂v_i = λ (Ã/G) c_i with λ = ρ C/G (may be tensile while the set is frozen).
    stress_[index] = active_[index] ? rho * mean_gap_velocity(index, nodal) : 0.0;
    if (!active_[index]) continue;
    const Multiplier& m = multipliers_[index];
    const double area_per_weight = m.area / m.node_weight;
    const double stiffness = rho * area_per_weight / m.node_weight;
    const double lambda = stress_[index];
    const bool sticking = pairs_[m.pair].friction.kind == FrictionKind::sticking;
    Eigen::Vector3d tangential = Eigen::Vector3d::Zero(); // T = Σ D_i v_i
    if (sticking)
      for (int s = m.first; s < m.first + m.count; ++s)
        tangential += support_[s].tangential * nodal.segment<3>(kDofsPerNode * support_[s].node);
    for (int s = m.first; s < m.first + m.count; ++s) {
      const Support& a = support_[s];
      if (!computed(a.node)) continue;
      Eigen::Vector3d r = lambda * area_per_weight * a.normal;
      if (sticking) r += stiffness * a.tangential.transpose() * tangential;
      residual.segment<3>(kDofsPerNode * a.node) += r;
      if (!blocks) continue;
      for (int t = m.first; t < m.first + m.count; ++t) {
        const Support& b = support_[t];
        Eigen::Matrix3d k = stiffness * a.normal * b.normal.transpose();
        if (sticking) k += stiffness * a.tangential.transpose() * b.tangential;
        blocks->push_back({a.node, b.node, k});
      }
    }
  }
  // Friction laws with a stress of their own, at each point, under the
  // pressure Σ W λ of its multipliers (λ as just computed). The sliding
  // blocks of consecutive points on the same six nodes (a facet's points
  // over one facet of the other body: search() orders them so) are summed
  // before they are handed over, not sent 36 per quadrature point.
  std::array<Eigen::Matrix3d, 36> sliding_sum;
  std::array<int, 6> summed_nodes{-1, -1, -1, -1, -1, -1};
  bool summing = false;
  auto hand_over_sliding = [&] {
    if (!summing) return;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (summed_nodes[a] >= 0 && summed_nodes[b] >= 0 && computed(summed_nodes[a]))
          blocks->push_back({summed_nodes[a], summed_nodes[b], sliding_sum[6 * a + b]});
    summing = false;
  };
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& p = points_[i];
    FrictionStress f;
    if (!point_friction(static_cast<int>(i), nodal, f)) continue;
    const double sense = p.on_slave ? 1.0 : -1.0;
    const Eigen::Matrix3d tangent_projector = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
    // w = sense P (Σ M_i v_i − Σ N_j v_j): coefficient of node a in w is c_a P.
    const RelativeStencil st = stencil(p, sense);
    const double area = p.share * p.area;
    if (blocks && st.nodes != summed_nodes) {
      hand_over_sliding();
      summed_nodes = st.nodes;
    }
    if (blocks && !summing) {
      for (Eigen::Matrix3d& k : sliding_sum)
        k.setZero();
      summing = true;
    }
    const Eigen::Matrix3d sliding = area * f.d_sliding * tangent_projector;
    for (int a = 0; a < 6; ++a) {
      if (st.nodes[a] < 0 || !computed(st.nodes[a])) continue;
      residual.segment<3>(kDofsPerNode * st.nodes[a]) += st.coefficient[a] * area * f.stress;
      if (!blocks) continue;
      for (int b = 0; b < 6; ++b)
        sliding_sum[6 * a + b] += (st.coefficient[a] * st.coefficient[b]) * sliding;
      if (f.d_normal_pressure.isZero()) continue;
      // Coulomb: τ depends on σn = Σ_m W λ_m, λ_m = ρ C_m/G_m.
      for (const MultiplierWeight& w : p.multipliers)
        if (active_[w.multiplier]) {
          const Multiplier& mult = multipliers_[w.multiplier];
          const double gain = st.coefficient[a] * area * w.weight * rho / mult.node_weight;
          for (int s = mult.first; s < mult.first + mult.count; ++s)
            blocks->push_back(
                {st.nodes[a], support_[s].node, gain * f.d_normal_pressure * support_[s].normal.transpose()});
        }
    }
  }
  if (blocks) hand_over_sliding();
}

std::vector<std::pair<int, int>> BodyContact::couplings() const {
  std::vector<std::pair<int, int>> pairs;
  auto couple = [&](int a, int b) {
    if (a != b) pairs.push_back({std::min(a, b), std::max(a, b)});
  };
  for (const Multiplier& m : multipliers_)
    for (int s = m.first; s < m.first + m.count; ++s)
      for (int t = s + 1; t < m.first + m.count; ++t)
        couple(support_[s].node, support_[t].node);
  for (const ContactPoint& p : points_) {
    const FrictionKind kind = pairs_[p.pair].friction.kind;
    if (kind == FrictionKind::frictionless || kind == FrictionKind::sticking) continue;
    const RelativeStencil st = stencil(p, 1.0);
    for (int a = 0; a < 6; ++a) {
      if (st.nodes[a] < 0) continue;
      for (int b = a + 1; b < 6; ++b)
        if (st.nodes[b] >= 0) couple(st.nodes[a], st.nodes[b]);
      if (kind != FrictionKind::coulomb) continue;
      for (const MultiplierWeight& w : p.multipliers)
        for (int s = multipliers_[w.multiplier].first;
             s < multipliers_[w.multiplier].first + multipliers_[w.multiplier].count; ++s)
          couple(st.nodes[a], support_[s].node);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace anvil::contact
