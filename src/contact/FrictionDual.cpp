#include "anvil/contact/FrictionDual.h"

#include <cmath>

namespace anvil::contact {

void FrictionDual::start(const std::vector<Eigen::Vector3d>& sliding, double regularisation) {
  regularisation_ = regularisation;
  sliding_ = sliding;
  direction_.resize(sliding.size());
  for (std::size_t i = 0; i < sliding.size(); ++i) {
    const double s = std::sqrt(sliding[i].squaredNorm() + regularisation * regularisation);
    direction_[i] = s > 0.0 ? Eigen::Vector3d(sliding[i] / s) : Eigen::Vector3d::Zero();
  }
  step_ = 0.0;
}

Eigen::Vector3d FrictionDual::direction(int i, const Eigen::Vector3d& w) const {
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

void FrictionDual::accept(const std::vector<Eigen::Vector3d>& sliding) {
  for (std::size_t i = 0; i < sliding.size(); ++i)
    direction_[i] = direction(static_cast<int>(i), sliding[i]);
  sliding_ = sliding;
  step_ = 0.0;
}

} // namespace anvil::contact
