#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// Axial stretching coupled to bending in every member of a frame: each element's axial strain
/// takes the lengthening of its deflected axis (von Karman),
///   eps = (u_b - u_a) / l + s,   s = 1/(2l) int (v'^2 + w'^2) dx = 1/(2l) q^T G_0 q,
/// in its own axes, and stores EA l eps^2 / 2. The linear elements hold the part EA l e0^2 / 2
/// of e0 = (u_b - u_a) / l; this force adds the rest, EA l (2 e0 s + s^2) / 2, whose gradient is
///   r = N G_0 q + EA s (u_b - u_a) direction,   N = EA (e0 + s),
/// with the consistent tangent N G_0 + EA (g a^T + a g^T) + (EA / l) g g^T (g = G_0 q, a the
/// gradient of e0): element by element, so the tangent keeps the frame's band.
///
/// A member whose ends are held apart (a bridge) builds the tension of mid-plane stretching: in
/// statics its elements' axial nodes settle where N is uniform, N = EA / L (Delta u + 1/2 int
/// w'^2), the beam's StretchingForce; a member free to slide axially (a folded flexure's beams
/// meet a truss that gives way) builds little. The model must be numbered for these couplings
/// (FrameCouplings::kStretching).
class FrameStretchingForce final : public FrameElementForce {
 public:
  /// Throws std::invalid_argument unless `model` was built with FrameCouplings::kStretching; it
  /// must outlive the force.
  explicit FrameStretchingForce(const FrameModel& model) : model_(model) {
    if (!Holds(model.couplings(), FrameCouplings::kStretching)) {
      throw std::invalid_argument(
          "FrameStretchingForce: the frame must be numbered for stretching "
          "(FrameCouplings::kStretching)");
    }
    for (int e = 0; e < model.ElementCount(); ++e) {
      const ElementProperties& p = model.elements()[e].properties();
      geometric_.push_back(model.elements()[e].Geometric(model.bases(), 0));
      stiffness_.push_back(p.young_modulus * p.area);
    }
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (int e = 0; e < model_.ElementCount(); ++e) {
      const Local local = Element(d, e);
      if (!std::isfinite(local.tension)) return false;
      const double ea = stiffness_[e];
      const double l = model_.elements()[e].properties().length;
      const FrameModel::ElementVector carried =
          model_.ElementTransform(e).transpose() * Force(local, ea);
      const std::array<int, 12>& dofs = model_.ElementDofs(e);
      for (int a = 0; a < 12; ++a) {
        if (dofs[a] >= 0) force[dofs[a]] += carried[a];
      }
      if (!tangent.band_wanted()) continue;
      FrameModel::Element::Matrix h = local.tension * geometric_[e];
      h.noalias() += (ea / l) * local.slope * local.slope.transpose();
      for (int a = 0; a < 12; ++a) {  // EA (g a^T + a g^T), a = (-1/l at u_a, +1/l at u_b)
        h(a, 0) -= ea / l * local.slope[a];
        h(0, a) -= ea / l * local.slope[a];
        h(a, 6) += ea / l * local.slope[a];
        h(6, a) += ea / l * local.slope[a];
      }
      model_.AddElementMatrix(e, h, tangent.band());
    }
    return true;
  }

  /// An element's axial force N = EA (e0 + s) in internal units (tension > 0), the linear part
  /// EA e0 included.
  double Tension(const Eigen::VectorXd& d, int e) const { return Element(d, e).tension; }

  /// An element's stretching force in its own axes (internal units), the nonlinear part of its
  /// end forces: what the linear elements' K u leaves out.
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e) const override {
    return Force(Element(d, e), stiffness_[e]);
  }

 private:
  struct Local {
    FrameModel::ElementVector slope;  ///< g = G_0 q
    double stretch = 0.0;             ///< s, the axis's lengthening over its length
    double tension = 0.0;             ///< N = EA (e0 + s)
  };

  Local Element(const Eigen::VectorXd& d, int e) const {
    const FrameModel::ElementVector q = model_.LocalDisplacement(d, e);
    const double l = model_.elements()[e].properties().length;
    Local out;
    out.slope.noalias() = geometric_[e] * q;
    out.stretch = 0.5 * q.dot(out.slope) / l;
    out.tension = stiffness_[e] * ((q[6] - q[0]) / l + out.stretch);
    return out;
  }

  // r = N g + EA s (-1 at u_a, +1 at u_b).
  static FrameModel::ElementVector Force(const Local& local, double ea) {
    FrameModel::ElementVector r = local.tension * local.slope;
    r[0] -= ea * local.stretch;
    r[6] += ea * local.stretch;
    return r;
  }

  const FrameModel& model_;
  std::vector<FrameModel::Element::Matrix> geometric_;  ///< G_0 of each element, its own axes
  std::vector<double> stiffness_;                       ///< EA of each element
};

}  // namespace cosmems
