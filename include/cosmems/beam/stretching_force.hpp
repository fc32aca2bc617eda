#pragma once

#include <Eigen/Core>
#include <stdexcept>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"

namespace cosmems {

/// Mid-plane stretching of a beam whose ends cannot approach each other (a microbridge): the
/// transverse deflection lengthens the axis, raising the axial force to
///   N(d) = N0 + s(d) / C,   s = 1/2 int (v'^2 + w'^2) dx = 1/2 d^T G_0 d,   C = int dx / EA
/// (uniform N: the elements act as springs in series, so a stepped beam is covered too). The
/// extra energy s^2 / (2C) gives r(d) = (N - N0) G_0 d, N0 G_0 already being in the model's
/// stiffness, with the consistent tangent (N - N0) G_0 + (1/C) g g^T, g = G_0 d: a band part and
/// a rank-one part, since N couples every element.
template <int Dim>
class StretchingForce final : public NonlinearForce {
 public:
  /// Throws std::invalid_argument unless both ends are held axially: a free end lets the axis
  /// slide and no tension builds up.
  explicit StretchingForce(const BeamModel<Dim>& model)
      : model_(model), slope_(Eigen::VectorXd::Zero(model.FreeDofCount())) {
    const int last = model.NodeCount() - 1;
    if (model.dofs().Reduced(0, NodalDof::kUx) >= 0 ||
        model.dofs().Reduced(last, NodalDof::kUx) >= 0) {
      throw std::invalid_argument(
          "model.theory = \"stretching\": needs both ends held axially (a bridge); a free end "
          "lets the beam slide and no tension builds up");
    }
    for (const auto& element : model.elements()) {
      const ElementProperties& p = element.properties();
      compliance_ += p.length / (p.young_modulus * p.area);
    }
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    model_.Geometric(0).Multiply(d, slope_);
    const double extra = 0.5 * d.dot(slope_) / compliance_;  // N - N0
    if (!std::isfinite(extra)) return false;
    force += extra * slope_;
    if (tangent.band_wanted()) tangent.band().mutable_data() += extra * model_.Geometric(0).data();
    tangent.SetRankOne(1.0 / compliance_, slope_);
    return true;
  }

  /// N(d) in internal units (tension > 0), the residual N0 included.
  double AxialForce(const Eigen::VectorXd& d) const {
    return model_.AxialLoad() + 0.5 * d.dot(model_.Geometric(0) * d) / compliance_;
  }

  /// C = int dx / EA (internal units).
  double Compliance() const { return compliance_; }

 private:
  const BeamModel<Dim>& model_;
  Eigen::VectorXd slope_;  ///< g = G_0 d, reused by every evaluation
  double compliance_ = 0.0;
};

}  // namespace cosmems
