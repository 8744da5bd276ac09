#include "anvil/contact/FrictionDual.h"

namespace anvil::contact {

std::optional<Eigen::Vector3d> FrictionDual::direction(std::size_t i, const Eigen::Vector3d& w) const {
  if (i >= direction_.size()) return std::nullopt;
  const Eigen::Vector3d& lambda = direction_[i];
  const Eigen::Vector3d& w0 = sliding_[i];
  const double s = std::sqrt(w0.squaredNorm() + regularisation_ * regularisation_);
  if (!(s > 0.0)) return Eigen::Vector3d::Zero(); // at rest, unregularised: no direction, as w wᵀ = 0
  const Eigen::Vector3d dw = w - w0;
  Eigen::Vector3d next = lambda + (dw - lambda * (w0.dot(dw) / s) + step_ * (w0 - lambda * s)) / s;
  const double length = next.norm();
  if (length > 1.0) next /= length;
  return next;
}

} // namespace anvil::contact
