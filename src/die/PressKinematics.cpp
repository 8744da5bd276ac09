#include "anvil/die/PressKinematics.h"

#include "anvil/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace anvil::die {

std::string ConstantVelocity::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "constant velocity (%g, %g, %g) mm/s", velocity_.x(), velocity_.y(), velocity_.z());
  return text;
}

TableMotion::TableMotion(const Eigen::Vector3d& direction, std::vector<double> times, std::vector<double> values,
                         Quantity q)
    : direction_(direction.normalized()), times_(std::move(times)), values_(std::move(values)), quantity_(q) {
  ANVIL_ASSERT(times_.size() == values_.size() && !times_.empty());
  for (std::size_t i = 1; i < times_.size(); ++i)
    ANVIL_ASSERT(times_[i] > times_[i - 1]);
}

Eigen::Vector3d TableMotion::displacement(double t) const {
  const std::size_t n = times_.size();
  auto value_at = [&](double s) {
    if (s <= times_.front()) return values_.front();
    if (s >= times_.back()) return values_.back();
    const std::size_t i = std::upper_bound(times_.begin(), times_.end(), s) - times_.begin();
    const double w = (s - times_[i - 1]) / (times_[i] - times_[i - 1]);
    return (1.0 - w) * values_[i - 1] + w * values_[i];
  };
  if (quantity_ == Quantity::displacement) return value_at(t) * direction_;
  // ∫₀ᵗ speed: exact for a piecewise linear speed (trapezoids between breakpoints).
  double travel = 0.0, s = 0.0;
  for (std::size_t i = 0; i <= n && s < t; ++i) {
    const double next = i < n ? std::min(std::max(times_[i], s), t) : t;
    travel += 0.5 * (value_at(s) + value_at(next)) * (next - s);
    s = next;
  }
  return travel * direction_;
}

std::string TableMotion::describe() const {
  char text[200];
  std::snprintf(text, sizeof text, "table of %s against time, %zu points from %g to %g s, along (%g, %g, %g)",
                quantity_ == Quantity::speed ? "speed (mm/s)" : "displacement (mm)", times_.size(), times_.front(),
                times_.back(), direction_.x(), direction_.y(), direction_.z());
  return text;
}

CrankPress::CrankPress(const Eigen::Vector3d& direction, double crank_radius, double rod_length, double rpm,
                       double start_angle_deg)
    : direction_(direction.normalized()), crank_radius_(crank_radius), rod_length_(rod_length),
      angular_speed_(2.0 * std::numbers::pi * rpm / 60.0), start_angle_(start_angle_deg * std::numbers::pi / 180.0) {
  ANVIL_ASSERT(rod_length > crank_radius && crank_radius > 0.0 && rpm > 0.0);
}

double CrankPress::travel(double angle) const {
  const double s = std::sin(angle);
  return crank_radius_ * (1.0 - std::cos(angle)) + rod_length_ -
         std::sqrt(rod_length_ * rod_length_ - crank_radius_ * crank_radius_ * s * s);
}

Eigen::Vector3d CrankPress::displacement(double t) const {
  return (travel(start_angle_ + angular_speed_ * t) - travel(start_angle_)) * direction_;
}

std::string CrankPress::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "crank press, crank radius %g mm, rod %g mm, %g rpm, from %g deg after top dead centre", crank_radius_,
                rod_length_, angular_speed_ * 60.0 / (2.0 * std::numbers::pi), start_angle_ * 180.0 / std::numbers::pi);
  return text;
}

} // namespace anvil::die
