#include "cosmems/scripted/built_in_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cosmems/core/constants.hpp"

namespace cosmems {
namespace {

/// Progress 0 -> 1 through the phase [begin, end) of a cycle, along a raised cosine: zero
/// velocity at both ends (C1 joins with the neighbouring phases) and a peak acceleration of
/// (pi / (end - begin))^2 / 2 per unit of amplitude and squared cycle.
double Ramp(double u, double begin, double end) {
  const double s = std::clamp((u - begin) / (end - begin), 0.0, 1.0);
  return 0.5 * (1.0 - std::cos(kPi * s));
}

/// `cycles` repetitions of one cycle, at rest at start_m before and after the script.
class CyclicMotion : public Trajectory {
 public:
  explicit CyclicMotion(const MotionShape& shape) : shape_(shape) {}

  Eigen::Vector3d Position(double t_s) const final {
    if (!(t_s > 0.0 && t_s < Duration())) return shape_.start_m;
    const double cycle = t_s / shape_.period_s;
    return shape_.start_m + Offset(cycle - std::floor(cycle));
  }
  double Duration() const final { return shape_.cycles * shape_.period_s; }

 protected:
  /// Displacement from start_m at the fraction `u` in [0, 1) of a cycle; zero at u = 0 and as
  /// u -> 1, so cycles join smoothly.
  virtual Eigen::Vector3d Offset(double u) const = 0;
  const MotionShape& shape() const { return shape_; }

 private:
  MotionShape shape_;
};

class PressMotion final : public CyclicMotion {
 public:
  using CyclicMotion::CyclicMotion;

 private:
  Eigen::Vector3d Offset(double u) const override {
    const double down = Ramp(u, 0.0, 0.4) - Ramp(u, 0.7, 1.0);
    return Eigen::Vector3d(0.0, -shape().depth_m * down, 0.0);
  }
};

class SweepMotion final : public CyclicMotion {
 public:
  using CyclicMotion::CyclicMotion;

 private:
  Eigen::Vector3d Offset(double u) const override {
    const double down = Ramp(u, 0.0, 0.2) - Ramp(u, 0.8, 1.0);
    const double along = Ramp(u, 0.2, 0.5) - Ramp(u, 0.5, 0.8);
    return Eigen::Vector3d(shape().sweep_m * along, -shape().depth_m * down, 0.0);
  }
};

class TapMotion final : public CyclicMotion {
 public:
  using CyclicMotion::CyclicMotion;

 private:
  static constexpr double kTapsPerPeriod = 4.0;

  Eigen::Vector3d Offset(double u) const override {
    const double slot = u * kTapsPerPeriod;
    const double s = slot - std::floor(slot);
    const double down = Ramp(s, 0.0, 0.25) - Ramp(s, 0.25, 0.5);
    return Eigen::Vector3d(0.0, -shape().depth_m * down, 0.0);
  }
};

template <typename Value>
void Require(bool ok, const char* field, const Value& value, const char* condition) {
  if (ok) return;
  std::ostringstream message;
  message << "motion." << field << " = " << value << " must be " << condition;
  throw std::invalid_argument(message.str());
}

}  // namespace

void MotionShape::Validate() const {
  Require(start_m.allFinite(), "start_m", start_m.transpose(), "finite");
  Require(std::isfinite(depth_m) && depth_m >= 0.0, "depth_m", depth_m, "finite and >= 0");
  Require(std::isfinite(sweep_m) && sweep_m >= 0.0, "sweep_m", sweep_m, "finite and >= 0");
  Require(std::isfinite(period_s) && period_s > 0.0, "period_s", period_s, "finite and > 0");
  Require(cycles >= 1, "cycles", cycles, ">= 1");
}

std::vector<std::string> BuiltInTrajectoryNames() { return {"press", "sweep", "tap"}; }

std::unique_ptr<Trajectory> MakeBuiltInTrajectory(const std::string& name,
                                                  const MotionShape& shape) {
  shape.Validate();
  if (name == "press") return std::make_unique<PressMotion>(shape);
  if (name == "sweep") return std::make_unique<SweepMotion>(shape);
  if (name == "tap") return std::make_unique<TapMotion>(shape);
  std::string valid;
  for (const std::string& known : BuiltInTrajectoryNames()) {
    valid += (valid.empty() ? "" : ", ") + known;
  }
  throw std::invalid_argument("unknown trajectory '" + name + "'; built-in trajectories: " + valid);
}

}  // namespace cosmems
