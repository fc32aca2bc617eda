#pragma once

// A stylus script sampled once a servo tick from a table: the table is where a test writes the
// misbehaviour in (jumps, NaN, stalls).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "cosmems/scripted/trajectory.hpp"

namespace cosmems::test {

/// Point n of the table is the stylus at t = n / rate_hz; held at the ends.
class TableTrajectory final : public Trajectory {
 public:
  TableTrajectory(std::vector<Eigen::Vector3d> points, double rate_hz)
      : points_(std::move(points)), rate_hz_(rate_hz) {}
  Eigen::Vector3d Position(double t_s) const override {
    const double index = std::clamp(std::round(t_s * rate_hz_), 0.0, points_.size() - 1.0);
    return points_[static_cast<std::size_t>(index)];
  }
  double Duration() const override { return (points_.size() - 1.0) / rate_hz_; }

 private:
  std::vector<Eigen::Vector3d> points_;
  double rate_hz_;
};

}  // namespace cosmems::test
