#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

namespace cosmems {

/// One mode of a modal model: q'' + 2 zeta w q' + w^2 q = phi^T f, with phi normalised to unit
/// modal mass.
struct ModalCoordinate {
  double omega = 0.0;  ///< rad per internal time unit
  double damping_ratio = 0.0;
};

/// The exact map of one step h of a modal oscillator under a load g(t) linear over the step:
/// [q, q']_(n+1) = a [q, q']_n + b0 g_n + b1 g_(n+1), taken from the exponential of the augmented
/// 4x4 system [q, q', g, g'] (Van Loan). A load held at g over the whole step moves it by
/// (b0 + b1) g.
struct ModeStep {
  Eigen::Matrix2d a;
  Eigen::Vector2d b0, b1;

  static ModeStep Make(const ModalCoordinate& mode, double h) {
    const double w = mode.omega;
    Eigen::Matrix4d f = Eigen::Matrix4d::Zero();
    f(0, 1) = 1.0;
    f(1, 0) = -w * w;
    f(1, 1) = -2.0 * mode.damping_ratio * w;
    f(1, 2) = 1.0;
    f(2, 3) = 1.0;
    const Eigen::Matrix4d e = (f * h).exp();
    ModeStep out;
    out.a = e.topLeftCorner<2, 2>();
    // g(t) = g_n + (g_(n+1) - g_n) t / h: the block E12 acts on [g_n, (g_(n+1) - g_n) / h].
    out.b0 = e.block<2, 1>(0, 2) - e.block<2, 1>(0, 3) / h;
    out.b1 = e.block<2, 1>(0, 3) / h;
    return out;
  }
};

}  // namespace cosmems
