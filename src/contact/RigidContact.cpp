#include "anvil/contact/RigidContact.h"

#include "anvil/core/processes.h"
#include "anvil/fem/DofMap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace anvil::contact {

using fem::kDofsPerNode;

std::vector<double> boundary_node_areas(const mesh::TetMesh& mesh, std::span<const char> skip) {
  std::vector<double> area(mesh.node_count(), 0.0);
  for (std::size_t i = 0; i < mesh.boundary_faces.size(); ++i) {
    if (!skip.empty() && skip[i]) continue;
    const mesh::Triangle& f = mesh.boundary_faces[i];
    const double third = mesh::area_vector(mesh, f).norm() / 3.0;
    for (int k = 0; k < 3; ++k)
      area[f[k]] += third;
  }
  return area;
}

void RigidContact::search(const mesh::TetMesh& mesh, const std::vector<DieView>& dies, double search_distance) {
  dies_ = dies;
  candidates_.clear();
  dual_ = FrictionDual{}; // set again when Newton starts
  const std::vector<double> area = boundary_node_areas(mesh);
  std::vector<int> boundary;
  for (int node = 0; node < mesh.node_count(); ++node)
    if (area[node] != 0.0) boundary.push_back(node);
  // Per boundary node: the nearest die within reach (-1: none), the gap and the die's normal.
  constexpr int kWidth = 5;
  const std::vector<double> nearest =
      processes::share_out(static_cast<int>(boundary.size()), kWidth, [&](int k, double* out) {
        const mesh::Point& x = mesh.nodes[boundary[k]];
        out[0] = -1.0;
        double gap = std::numeric_limits<double>::infinity();
        for (std::size_t d = 0; d < dies.size(); ++d) {
          const die::SurfaceProjection p = dies[d].surface->project(x - dies[d].displacement);
          if (p.distance < search_distance && p.distance < gap) {
            gap = p.distance;
            out[0] = static_cast<double>(d), out[1] = gap;
            Eigen::Map<Eigen::Vector3d>(out + 2) = p.normal;
          }
        }
      });
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const double* at = &nearest[kWidth * k];
    if (at[0] < 0.0) continue;
    candidates_.push_back(
        {boundary[k], static_cast<int>(at[0]), Eigen::Map<const Eigen::Vector3d>(at + 2), at[1], area[boundary[k]]});
  }
  active_.resize(candidates_.size());
  gap_.resize(candidates_.size());
}

double RigidContact::gap_velocity(const ContactCandidate& c, const Eigen::VectorXd& nodal) const {
  const Eigen::Vector3d relative = nodal.segment<3>(kDofsPerNode * c.node) - dies_[c.die].velocity;
  return -relative.dot(c.normal) - c.gap / increment_.closing_time(c.gap);
}

double RigidContact::pressure(int i, const Eigen::VectorXd& nodal) const {
  return increment_.penalty * std::max(gap_velocity(candidates_[i], nodal), 0.0);
}

const std::vector<double>& RigidContact::gaps(const Eigen::VectorXd& nodal) {
  for (std::size_t i = 0; i < candidates_.size(); ++i)
    gap_[i] = gap_velocity(candidates_[i], nodal);
  return gap_;
}

void RigidContact::start(const Eigen::VectorXd& nodal) {
  active_.set_tolerance(increment_.gap_tolerance);
  active_.start(gaps(nodal));
  dual_.start(
      candidates_.size(), [&](std::size_t i) { return sliding(candidates_[i], nodal); }, increment_.regularisation);
}

bool RigidContact::consistent(const Eigen::VectorXd& nodal, bool converged) {
  return active_.consistent(gaps(nodal), converged);
}

bool RigidContact::linear() const {
  return std::all_of(dies_.begin(), dies_.end(), [](const DieView& d) { return is_linear(d.friction); });
}

std::string RigidContact::accept(const Eigen::VectorXd& nodal) {
  dual_.accept([&](std::size_t i) { return sliding(candidates_[i], nodal); });
  return active_.accept(gaps(nodal), "contact nodes");
}

void RigidContact::add(const Eigen::VectorXd& nodal, Eigen::VectorXd& residual, std::vector<solver::NodeBlock>* blocks,
                       const std::vector<char>* rows) const {
  const double rho = increment_.penalty;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const ContactCandidate& c = candidates_[i];
    if (!active_[i] || (rows && !(*rows)[c.node])) continue;
    const double h = gap_velocity(c, nodal);
    const Eigen::Vector3d& n = c.normal;
    const Eigen::Matrix3d tangent_projector = Eigen::Matrix3d::Identity() - n * n.transpose();
    // Normal: potential ½ ρ A h⁺², so r = −A ρ h n and ∂r/∂v = A ρ n nᵀ (∂h/∂v = −n).
    const double sigma_n = rho * h; // may be tensile while the set is frozen; checked at convergence
    Eigen::Vector3d r = -c.area * sigma_n * n;
    Eigen::Matrix3d k = c.area * rho * n * n.transpose();
    if (dies_[c.die].friction.kind != FrictionKind::frictionless) {
      const FrictionStress f = friction(static_cast<int>(i), nodal, sigma_n);
      r += c.area * f.stress;
      k += c.area * (f.d_sliding * tangent_projector - rho * f.d_normal_pressure * n.transpose());
    }
    residual.segment<3>(kDofsPerNode * c.node) += r;
    if (blocks) blocks->push_back({c.node, c.node, k});
  }
}

Eigen::Vector3d RigidContact::sliding(const ContactCandidate& c, const Eigen::VectorXd& nodal) const {
  const Eigen::Vector3d relative = nodal.segment<3>(kDofsPerNode * c.node) - dies_[c.die].velocity;
  return (Eigen::Matrix3d::Identity() - c.normal * c.normal.transpose()) * relative;
}

FrictionStress RigidContact::friction(int i, const Eigen::VectorXd& nodal, double sigma_n) const {
  const ContactCandidate& c = candidates_[i];
  const Eigen::Vector3d w = sliding(c, nodal);
  return friction_stress(dies_[c.die].friction,
                         {w, sigma_n, increment_.flow_stress[c.node], increment_.consistency[c.node],
                          increment_.regularisation, increment_.penalty, tangent_sensitivity_floor_,
                          dual_.direction(i, w)});
}

double RigidContact::friction_power(int i, const Eigen::VectorXd& nodal) const {
  const ContactCandidate& c = candidates_[i];
  if (!active_[i] || dies_[c.die].friction.kind == FrictionKind::frictionless) return 0.0;
  return c.area * friction(i, nodal, increment_.penalty * gap_velocity(c, nodal)).stress.dot(sliding(c, nodal));
}

std::vector<Eigen::Vector3d> RigidContact::die_forces(const Eigen::VectorXd& nodal) const {
  // The die receives minus the force on the body, i.e. the term's residual.
  Eigen::VectorXd residual = Eigen::VectorXd::Zero(nodal.size());
  std::vector<Eigen::Vector3d> force(dies_.size(), Eigen::Vector3d::Zero());
  add(nodal, residual, nullptr);
  for (const ContactCandidate& c : candidates_)
    force[c.die] += residual.segment<3>(kDofsPerNode * c.node);
  return force;
}

double RigidContact::first_contact_time(const Eigen::VectorXd& nodal, double touching) const {
  double first = std::numeric_limits<double>::infinity();
  for (const ContactCandidate& c : candidates_) {
    if (c.gap <= touching) continue;
    const double closing = -(nodal.segment<3>(kDofsPerNode * c.node) - dies_[c.die].velocity).dot(c.normal);
    if (closing > 0.0) first = std::min(first, c.gap / closing);
  }
  return first;
}

} // namespace anvil::contact
