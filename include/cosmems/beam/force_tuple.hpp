#pragma once

#include <Eigen/Core>
#include <tuple>
#include <utility>

#include "cosmems/beam/nonlinear_force.hpp"

namespace cosmems {

/// The sum of a fixed set of nonlinear forces, composed at compile time: a program that knows its
/// effects (a haptic demo with contact, stiction and the Casimir force, say) holds them by value
/// and each call is resolved statically, where ForceSum, the scene files' runtime list, calls
/// through pointers. Both evaluate the same force objects, so the physics is the same. At most
/// one member may carry a rank-one tangent part.
template <typename... Forces>
class ForceTuple final : public NonlinearForce {
 public:
  explicit ForceTuple(Forces... forces) : forces_(std::move(forces)...) {}

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    return std::apply([&](auto&... f) { return (f.Evaluate(d, force, tangent) && ...); }, forces_);
  }
  bool HasViscousPart() const override {
    return std::apply([](const auto&... f) { return (f.HasViscousPart() || ...); }, forces_);
  }
  bool EvaluateViscous(const Eigen::VectorXd& d, const Eigen::VectorXd& v, double velocity_factor,
                       Eigen::VectorXd& force, ForceTangent& tangent) override {
    return std::apply(
        [&](auto&... f) {
          return (f.EvaluateViscous(d, v, velocity_factor, force, tangent) && ...);
        },
        forces_);
  }
  bool Idle(const Eigen::VectorXd& d) const override {
    return std::apply([&](const auto&... f) { return (f.Idle(d) && ...); }, forces_);
  }
  bool Settle(const Eigen::VectorXd& d) override {
    bool settled = true;  // every member settles, even after one has changed its state
    std::apply([&](auto&... f) { ((settled = f.Settle(d) && settled), ...); }, forces_);
    return settled;
  }
  void Commit(const Eigen::VectorXd& d) override {
    std::apply([&](auto&... f) { (f.Commit(d), ...); }, forces_);
  }
  void Revert() override {
    std::apply([](auto&... f) { (f.Revert(), ...); }, forces_);
  }
  void StartStep() override {
    std::apply([](auto&... f) { (f.StartStep(), ...); }, forces_);
  }
  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    std::apply([&](auto&... f) { (f.ProjectMotion(d, v, a), ...); }, forces_);
  }
  bool LetsGo(const Eigen::VectorXd& start, const Eigen::VectorXd& predicted) const override {
    return std::apply([&](const auto&... f) { return (f.LetsGo(start, predicted) || ...); },
                      forces_);
  }

  template <std::size_t I>
  auto& get() {
    return std::get<I>(forces_);
  }

 private:
  std::tuple<Forces...> forces_;
};

}  // namespace cosmems
