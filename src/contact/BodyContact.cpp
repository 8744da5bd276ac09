#include "anvil/contact/BodyContact.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/error.h"
#include "anvil/fem/DofMap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace anvil::contact {

using fem::kDofsPerNode;

PairFormulation pair_formulation(const std::string& name) {
  if (name == "master_slave") return PairFormulation::master_slave;
  if (name == "symmetric") return PairFormulation::symmetric;
  if (name == "quasi_symmetric") return PairFormulation::quasi_symmetric;
  throw InputError("unknown contact formulation '" + name + "' (expected master_slave, symmetric or quasi_symmetric)");
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

/// Barycentric coordinates of `q` (on or near the plane of triangle abc), clamped to the triangle.
Eigen::Vector3d barycentric(const mesh::Point& q, const mesh::Point& a, const mesh::Point& b, const mesh::Point& c) {
  const Eigen::Vector3d e0 = b - a, e1 = c - a, r = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = r.dot(e0), d21 = r.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  Eigen::Vector3d l;
  l[1] = (d11 * d20 - d01 * d21) / det;
  l[2] = (d00 * d21 - d01 * d20) / det;
  l[0] = 1.0 - l[1] - l[2];
  l = l.cwiseMax(0.0);
  return l / l.sum();
}

/// The point of triangle f with barycentric coordinates `shape`.
mesh::Point point_on(const mesh::TetMesh& mesh, const mesh::Triangle& f, const Eigen::Vector3d& shape) {
  return shape[0] * mesh.nodes[f[0]] + shape[1] * mesh.nodes[f[1]] + shape[2] * mesh.nodes[f[2]];
}

/// Outward unit normal of a body at a boundary node: the area-weighted mean of its boundary faces.
Eigen::Vector3d own_normal(const mesh::TetMesh& mesh, const std::vector<int>& faces) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int f : faces)
    n += mesh::area_vector(mesh, mesh.boundary_faces[f]);
  return n.normalized();
}

/// The smaller of a nodal value at the point's node and at its projection:
/// friction is bounded by the weaker body (an elastic die's value is infinite).
double weaker_side(const std::vector<double>& nodal_value, const ContactPoint& p) {
  double facet = 0.0;
  for (int j = 0; j < 3; ++j)
    if (p.shape[j] > 0.0) facet += p.shape[j] * nodal_value[p.facet[j]];
  return std::min(nodal_value[p.node], facet);
}

} // namespace

Eigen::Vector3d relative_velocity(const ContactPoint& p, const Eigen::VectorXd& nodal) {
  Eigen::Vector3d relative = nodal.segment<3>(kDofsPerNode * p.node);
  for (int j = 0; j < 3; ++j)
    relative -= p.shape[j] * nodal.segment<3>(kDofsPerNode * p.facet[j]);
  return relative;
}

void BodyContact::search(const mesh::TetMesh& mesh, double search_distance) {
  points_.clear();
  std::vector<std::vector<int>> node_faces(mesh.nodes.size());
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    for (int node : mesh.boundary_faces[f])
      node_faces[node].push_back(static_cast<int>(f));

  for (std::size_t q = 0; q < pairs_.size(); ++q) {
    const BodyPair& pair = pairs_[q];
    const bool one_sided = pair.formulation == PairFormulation::master_slave;
    const double share = one_sided ? 1.0 : 0.5; // f_p: eq. 19 against the ½ of eqs. 20-21
    auto project = [&](const mesh::MeshRange& from, const mesh::MeshRange& onto, bool on_slave) {
      const auto first = mesh.boundary_faces.begin() + onto.first_face;
      const std::vector<mesh::Triangle> faces(first, first + onto.face_count);
      const SurfaceSearch surface(mesh.nodes, faces);
      for (int node = from.first_node; node < from.first_node + from.node_count; ++node) {
        if (node_faces[node].empty()) continue; // interior node
        const mesh::Point& x = mesh.nodes[node];
        const SurfaceSearch::Closest hit = surface.closest(x);
        // On an edge or a vertex several facets hold the closest point (to a
        // hair: two blocks sharing a symmetry plane meet there to round-off);
        // the one that faces the node's own surface best gives the normal and
        // the side (a node on the rim of a block lying on another must not
        // take the side face of the block below).
        const double hair = std::max(1e-9 * (1.0 + hit.point.norm()), 1e-3 * search_distance);
        const Eigen::Vector3d own = own_normal(mesh, node_faces[node]);
        int best = onto.first_face + hit.face;
        double best_facing = mesh::area_vector(mesh, mesh.boundary_faces[best]).normalized().dot(own);
        for (int vertex : faces[hit.face])
          for (int f : node_faces[vertex]) {
            if (f < onto.first_face || f >= onto.first_face + onto.face_count) continue;
            const mesh::Triangle& t = mesh.boundary_faces[f];
            const double facing = mesh::area_vector(mesh, t).normalized().dot(own);
            const Eigen::Vector3d l = barycentric(hit.point, mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]);
            if (facing < best_facing && (point_on(mesh, t, l) - hit.point).norm() <= hair)
              best = f, best_facing = facing;
          }
        const mesh::Triangle& facet = mesh.boundary_faces[best];
        const Eigen::Vector3d facet_normal = mesh::area_vector(mesh, facet).normalized();
        // Inside a facet (or off its edge by a hair: bodies pressed together
        // widen alike, to round-off) the offset is along its normal; off an
        // edge or a vertex the offset direction is the surface normal there.
        // The side comes from the facet.
        const Eigen::Vector3d shape = barycentric(x, mesh.nodes[facet[0]], mesh.nodes[facet[1]], mesh.nodes[facet[2]]);
        const Eigen::Vector3d offset = x - point_on(mesh, facet, shape);
        const double along_normal = offset.dot(facet_normal);
        const double lateral = (offset - along_normal * facet_normal).norm();
        const bool over_facet = lateral <= hair;
        const double side = along_normal >= 0.0 ? 1.0 : -1.0;
        const Eigen::Vector3d normal = over_facet ? facet_normal : Eigen::Vector3d(side * offset / offset.norm());
        const double gap = over_facet ? along_normal : side * offset.norm();
        // Deeper than the reach is not a penetration of this increment: the
        // node lies behind the other body's edge (a block's top corner over
        // the side of the block below), where the side test is ambiguous.
        if (std::abs(gap) >= search_distance) continue;
        // Tributary area on the faces that look at the other body (not the
        // sides of a block, whose edge nodes would otherwise weigh double).
        double area = 0.0;
        for (int f : node_faces[node]) {
          const Eigen::Vector3d n = mesh::area_vector(mesh, mesh.boundary_faces[f]);
          if (n.dot(normal) < -0.3 * n.norm()) area += n.norm() / 3.0;
        }
        if (area == 0.0) continue; // no face looks at the other body: not on its contact surface
        ContactPoint p;
        p.pair = static_cast<int>(q);
        p.node = node;
        p.facet = facet;
        p.shape = shape;
        p.normal = normal;
        p.gap = gap;
        p.area = area;
        p.share = share;
        p.on_slave = on_slave;
        points_.push_back(p);
      }
    };
    project(pair.slave, pair.master, true);
    if (!one_sided) project(pair.master, pair.slave, false);
  }
  build_multipliers(mesh.node_count());
}

void BodyContact::build_multipliers(int node_count) {
  multipliers_.clear();
  support_.clear();
  // Multiplier of each slave node (master/slave, quasi-symmetric). Points come
  // pair by pair, so an entry left by an earlier pair is recognised by its pair.
  std::vector<int> slave_multiplier(static_cast<std::size_t>(node_count), -1);
  auto multiplier_of = [&](int pair, int node) {
    int& index = slave_multiplier[node];
    if (index < 0 || multipliers_[index].pair != pair) {
      multipliers_.push_back({pair});
      index = static_cast<int>(multipliers_.size()) - 1;
    }
    return index;
  };
  for (ContactPoint& p : points_) {
    const PairFormulation formulation = pairs_[p.pair].formulation;
    if (formulation == PairFormulation::symmetric) {
      multipliers_.push_back({p.pair});
      p.multiplier = {static_cast<int>(multipliers_.size()) - 1, -1, -1};
      p.multiplier_weight = Eigen::Vector3d(1.0, 0.0, 0.0);
    } else if (p.on_slave) {
      p.multiplier = {multiplier_of(p.pair, p.node), -1, -1};
      p.multiplier_weight = Eigen::Vector3d(1.0, 0.0, 0.0);
    } else { // quasi-symmetric master node: the slave facet's λ, interpolated (eq. 22)
      for (int k = 0; k < 3; ++k)
        if (p.shape[k] > 0.0) p.multiplier[k] = multiplier_of(p.pair, p.facet[k]); // no empty multiplier
      p.multiplier_weight = p.shape;
    }
  }
  // Per multiplier, the points feeding it, then its support nodes with merged coefficients.
  std::vector<std::vector<std::pair<int, double>>> feeds(multipliers_.size());
  for (std::size_t i = 0; i < points_.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (points_[i].multiplier[k] >= 0)
        feeds[points_[i].multiplier[k]].push_back({static_cast<int>(i), points_[i].multiplier_weight[k]});
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
      const double scale = w * p.share;
      // h_p = −n·(v_node − Σ N_j v_j) − δ₀/Δt; tangential velocity in the
      // slave's sense (slave − master): sign +1 at a slave node, −1 at a master node.
      const double sense = p.on_slave ? 1.0 : -1.0;
      const Eigen::Matrix3d tangent_projector = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
      add_support(p.node, -scale * p.normal, scale * sense * tangent_projector);
      for (int j = 0; j < 3; ++j)
        add_support(p.facet[j], scale * p.shape[j] * p.normal, -scale * sense * p.shape[j] * tangent_projector);
      mult.node_weight += scale;
      mult.area += scale * p.area;
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
}
bool BodyContact::consistent(const Eigen::VectorXd& nodal) {
  return active_.consistent(gaps(nodal));
}
bool BodyContact::linear() const {
  return std::all_of(pairs_.begin(), pairs_.end(), [](const BodyPair& p) { return is_linear(p.friction); });
}
std::string BodyContact::accept(const Eigen::VectorXd& nodal) {
  return active_.accept(gaps(nodal), "pair constraints");
}

double BodyContact::pressure(int i, const Eigen::VectorXd& nodal) const {
  const ContactPoint& p = points_[i];
  double pressure = 0.0;
  for (int k = 0; k < 3; ++k)
    if (const int m = p.multiplier[k]; m >= 0 && active_[m])
      pressure += p.multiplier_weight[k] * increment_.penalty * std::max(mean_gap_velocity(m, nodal), 0.0);
  return pressure;
}

void BodyContact::add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual,
                      std::vector<solver::NodeBlock>* blocks) const {
  const double rho = increment_.penalty;
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
  // pressure Σ W λ of its multipliers (λ as just computed).
  for (const ContactPoint& p : points_) {
    const FrictionLaw& law = pairs_[p.pair].friction;
    if (law.kind == FrictionKind::frictionless || law.kind == FrictionKind::sticking) continue;
    double sigma_n = 0.0;
    bool touching = false;
    for (int k = 0; k < 3; ++k)
      if (const int m = p.multiplier[k]; m >= 0 && active_[m]) {
        touching = true;
        sigma_n += p.multiplier_weight[k] * stress_[m];
      }
    if (!touching) continue;
    const double sense = p.on_slave ? 1.0 : -1.0;
    const Eigen::Matrix3d tangent_projector = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
    const FrictionStress f = friction_stress(
        law, {sense * tangent_projector * relative_velocity(p, nodal), sigma_n, weaker_side(increment_.flow_stress, p),
              weaker_side(increment_.consistency, p), increment_.regularisation, rho});
    // w = sense P (v_node − Σ N_j v_j): coefficient of node a in w is c_a P.
    const std::array<int, 4> nodes{p.node, p.facet[0], p.facet[1], p.facet[2]};
    const std::array<double, 4> coefficient{sense, -sense * p.shape[0], -sense * p.shape[1], -sense * p.shape[2]};
    for (int a = 0; a < 4; ++a) {
      residual.segment<3>(kDofsPerNode * nodes[a]) += coefficient[a] * p.share * p.area * f.stress;
      if (!blocks) continue;
      for (int b = 0; b < 4; ++b)
        blocks->push_back(
            {nodes[a], nodes[b], coefficient[a] * coefficient[b] * p.share * p.area * f.d_sliding * tangent_projector});
      if (f.d_normal_pressure.isZero()) continue;
      // Coulomb: τ depends on σn = Σ_m W λ_m, λ_m = ρ C_m/G_m.
      for (int k = 0; k < 3; ++k)
        if (const int m = p.multiplier[k]; m >= 0 && active_[m]) {
          const Multiplier& mult = multipliers_[m];
          const double gain = coefficient[a] * p.share * p.area * p.multiplier_weight[k] * rho / mult.node_weight;
          for (int s = mult.first; s < mult.first + mult.count; ++s)
            blocks->push_back(
                {nodes[a], support_[s].node, gain * f.d_normal_pressure * support_[s].normal.transpose()});
        }
    }
  }
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
    const std::array<int, 4> nodes{p.node, p.facet[0], p.facet[1], p.facet[2]};
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b)
        couple(nodes[a], nodes[b]);
      if (kind != FrictionKind::coulomb) continue;
      for (int k = 0; k < 3; ++k)
        if (const int m = p.multiplier[k]; m >= 0)
          for (int s = multipliers_[m].first; s < multipliers_[m].first + multipliers_[m].count; ++s)
            couple(nodes[a], support_[s].node);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace anvil::contact
