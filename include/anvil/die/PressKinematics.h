// How a die moves: the press. Each law gives the die displacement as a
// function of press time; a load limit (hydraulic press) slows press time
// down (see Die in the time loop), so every law can be load-limited.
#pragma once
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace anvil::die {

class PressKinematics {
public:
  virtual ~PressKinematics() = default;
  /// Die displacement from its initial position at press time t (mm, s).
  virtual Eigen::Vector3d displacement(double t) const = 0;
  /// Press time (s) from which the die stays where it is; infinite when it
  /// never comes to rest for good.
  virtual double rest_time() const { return std::numeric_limits<double>::infinity(); }
  virtual std::string describe() const = 0;
};

/// Constant velocity (mm/s).
class ConstantVelocity final : public PressKinematics {
public:
  explicit ConstantVelocity(const Eigen::Vector3d& velocity) : velocity_(velocity) {}
  Eigen::Vector3d displacement(double t) const override { return t * velocity_; }
  double rest_time() const override { return velocity_.norm() == 0.0 ? 0.0 : std::numeric_limits<double>::infinity(); }
  std::string describe() const override;

private:
  Eigen::Vector3d velocity_;
};

/// A table against time along a fixed direction, linear between points:
/// either the speed (mm/s, integrated exactly) or the displacement (mm).
/// Before the first time the first value holds, after the last the last one
/// (a speed keeps the die moving, a displacement holds it still).
class TableMotion final : public PressKinematics {
public:
  enum class Quantity { speed, displacement };
  TableMotion(const Eigen::Vector3d& direction, std::vector<double> times, std::vector<double> values, Quantity q);
  Eigen::Vector3d displacement(double t) const override;
  /// A displacement table's last time; a speed table's when its last speed is 0.
  double rest_time() const override {
    return quantity_ == Quantity::displacement || values_.back() == 0.0 ? times_.back()
                                                                        : std::numeric_limits<double>::infinity();
  }
  std::string describe() const override;

private:
  Eigen::Vector3d direction_;
  std::vector<double> times_, values_;
  Quantity quantity_;
};

/// Mechanical crank press: crank radius r, connecting rod L, crank speed in
/// rpm, starting crank angle θ0 from top dead centre. Ram travel from top dead
/// centre s(θ) = r(1 − cos θ) + L − sqrt(L² − r² sin² θ), along `direction`.
class CrankPress final : public PressKinematics {
public:
  CrankPress(const Eigen::Vector3d& direction, double crank_radius, double rod_length, double rpm,
             double start_angle_deg);
  Eigen::Vector3d displacement(double t) const override;
  std::string describe() const override;
  /// Ram travel from top dead centre at crank angle θ (rad), mm.
  double travel(double angle) const;

private:
  Eigen::Vector3d direction_;
  double crank_radius_, rod_length_, angular_speed_, start_angle_;
};

} // namespace anvil::die
