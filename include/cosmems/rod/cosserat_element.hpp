#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "cosmems/beam/element_spec.hpp"
#include "cosmems/rod/so3.hpp"

namespace cosmems {
namespace internal {

/// m += a b^T for 3-vectors as a coefficient-wise (lazy) product: Eigen's general outer-product
/// kernel is an out-of-line call at -O2.
inline void AddOuterProduct(Eigen::Matrix3d& m, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b) {
  m += a.lazyProduct(b.transpose());
}

}  // namespace internal

/// One two-node element of a straight, geometrically exact (Simo-Reissner) rod: its constant data
/// in a model's internal units and its energy, gradient and Hessian.
///
/// Directors: d1 = R e1 is the axis (tangent to the undeformed rod along x), d2 = R e2 the
/// thickness direction (y, toward the substrate), d3 = R e3 = d1 x d2 the width (z). (The paper
/// names the axis d3; the frame here is that one relabelled cyclically, so that the undeformed
/// rod has R = I and the rotation components are the frame code's rx, ry, rz.)
///
/// Strains (material components): Gamma = R^T r' - e1 (extension, shear along d2, d3) and kappa
/// from [kappa]x = R^T R' (twist, bending about d2, about d3). Energy per length
/// (Gamma . C_f Gamma + kappa . C_m kappa) / 2 with C_f = diag(EA, kGA, kGA) and
/// C_m = diag(GJ, EI_y, EI_z).
///
/// Discretisation: positions interpolate linearly; rotations along the geodesic
/// R(s) = R_a exp(s psi^ / h) with psi = log(R_a^T R_b), so kappa = psi / h exactly and the
/// interpolation is objective (a rigid rotation of both nodes leaves the strains unchanged) and
/// path independent (Crisfield & Jelenic 1999). Gamma is taken at the single midpoint, where
/// R_m = R_a exp(psi^ / 2): one-point (reduced) integration, exact for the constant kappa and
/// free of shear locking, since a linear displacement field then never has to carry a spurious
/// shear strain in bending (the two-point rule would lock as h^2 / t^2). Nodal rotations can be
/// anything; within an element the relative rotation |psi| must stay below pi, which any mesh
/// that resolves the deformation satisfies.
///
/// Variations are spatial: u_i moves node i, R_i -> exp(theta_i^) R_i rotates it. The gradient is
/// dW/d(u_a, theta_a, u_b, theta_b); the Hessian is the second derivative of W in the exponential
/// chart (u, theta) -> (x + u, exp(theta^) R) about the current state, which is symmetric (the
/// spatial linearisation of Simo & Vu-Quoc differs from it by (1/2)[g_theta]x blocks, a skew
/// term that vanishes at equilibrium).
struct CosseratElement {
  using Vector12 = Eigen::Matrix<double, 12, 1>;
  using Matrix12 = Eigen::Matrix<double, 12, 12>;

  /// The chart Hessian by its distinct 3 x 3 blocks (rows, columns in u_a, theta_a, u_b,
  /// theta_b); the others follow from symmetry and from u_a and u_b entering only through
  /// u_b - u_a: K(u_a, u_a) = K(u_b, u_b) = -K(u_b, u_a) = stiffness / h,
  /// K(theta_a, u_b) = -K(theta_a, u_a), K(theta_b, u_b) = -K(theta_b, u_a).
  struct Tangent {
    Eigen::Matrix3d force;             ///< C_f / h in spatial components: K(u_a, u_a)
    Eigen::Matrix3d rotation_a_force;  ///< K(theta_a, u_a)
    Eigen::Matrix3d rotation_b_force;  ///< K(theta_b, u_a)
    Eigen::Matrix3d rotation_aa;       ///< K(theta_a, theta_a)
    Eigen::Matrix3d rotation_bb;       ///< K(theta_b, theta_b)
    Eigen::Matrix3d rotation_ba;       ///< K(theta_b, theta_a)

    /// The whole 12 x 12 matrix.
    Matrix12 ToMatrix() const {
      Matrix12 k;
      k.block<3, 3>(0, 0) = force;
      k.block<3, 3>(6, 0) = -force;
      k.block<3, 3>(6, 6) = force;
      k.block<3, 3>(0, 6) = -force;
      k.block<3, 3>(3, 0) = rotation_a_force;
      k.block<3, 3>(0, 3) = rotation_a_force.transpose();
      k.block<3, 3>(3, 6) = -rotation_a_force;
      k.block<3, 3>(6, 3) = -rotation_a_force.transpose();
      k.block<3, 3>(9, 0) = rotation_b_force;
      k.block<3, 3>(0, 9) = rotation_b_force.transpose();
      k.block<3, 3>(9, 6) = -rotation_b_force;
      k.block<3, 3>(6, 9) = -rotation_b_force.transpose();
      k.block<3, 3>(3, 3) = rotation_aa;
      k.block<3, 3>(9, 9) = rotation_bb;
      k.block<3, 3>(9, 3) = rotation_ba;
      k.block<3, 3>(3, 9) = rotation_ba.transpose();
      return k;
    }
  };

  double length = 0.0;                                         ///< h
  Eigen::Vector3d force_stiffness = Eigen::Vector3d::Zero();   ///< (EA, kGA, kGA)
  Eigen::Vector3d moment_stiffness = Eigen::Vector3d::Zero();  ///< (GJ, EI_y, EI_z)
  /// N0, the axial force the straight rod carries at its undeformed length (a residual stress,
  /// tension > 0): the stress-free state is shorter by N0 / EA, and extension is measured from
  /// it, so Gamma_1 in the energy is R^T r' . e1 - 1 + N0 / EA.
  double axial_prestress = 0.0;
  double mass = 0.0;                                         ///< rho A h
  Eigen::Vector3d rotary_inertia = Eigen::Vector3d::Zero();  ///< rho h (I_y + I_z, I_y, I_z)

  /// From an element's properties (internal units). `shear_factor` k scales GA (5/6 for a solid
  /// rectangle); `constraint_factor` multiplies EA and kGA (1 for the physical rod, large for
  /// the Kirchhoff limit); `axial_prestress` is N0 (internal units).
  static CosseratElement From(const ElementProperties& p, double shear_factor,
                              double constraint_factor, double axial_prestress) {
    CosseratElement e;
    e.length = p.length;
    e.axial_prestress = axial_prestress;
    const double ga = shear_factor * p.shear_modulus * p.area;
    e.force_stiffness = constraint_factor * Eigen::Vector3d(p.young_modulus * p.area, ga, ga);
    e.moment_stiffness =
        Eigen::Vector3d(p.shear_modulus * p.torsion_constant, p.young_modulus * p.second_moment_y,
                        p.young_modulus * p.second_moment_z);
    e.mass = p.density * p.area * p.length;
    e.rotary_inertia = p.density * p.length *
                       Eigen::Vector3d(p.polar_moment, p.second_moment_y, p.second_moment_z);
    return e;
  }

  /// Strain energy W for the relative displacement du = u_b - u_a and the nodal rotations.
  double Energy(const Eigen::Vector3d& du, const Eigen::Quaterniond& qa,
                const Eigen::Quaterniond& qb) const {
    const Strains s = StrainsAt(du, qa, qb);
    const Eigen::Vector3d force = force_stiffness.cwiseProduct(s.gamma);
    const Eigen::Vector3d moment = moment_stiffness.cwiseProduct(s.kappa);
    return 0.5 * length * (s.gamma.dot(force) + s.kappa.dot(moment));
  }

  /// Stress resultants in material components: force C_f Gamma (axial, shear d2, shear d3) and
  /// moment C_m kappa (twist, bending about d2, bending about d3), at the midpoint.
  void Resultants(const Eigen::Vector3d& du, const Eigen::Quaterniond& qa,
                  const Eigen::Quaterniond& qb, Eigen::Vector3d& force,
                  Eigen::Vector3d& moment) const {
    const Strains s = StrainsAt(du, qa, qb);
    force = force_stiffness.cwiseProduct(s.gamma);
    moment = moment_stiffness.cwiseProduct(s.kappa);
  }

  /// What the Hessian needs from a gradient evaluation: the midpoint frame, the spatial force
  /// and moment, the axis of psi, the chord, and sin, cos of |psi|/2 and sigma.
  struct Kinematics {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R_m
    Eigen::Vector3d force = Eigen::Vector3d::Zero();         ///< n = R_m C_f Gamma
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();        ///< m = R_m C_m kappa
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();         ///< nu, spatial
    Eigen::Vector3d chord = Eigen::Vector3d::Zero();         ///< d = x_b - x_a
    double sine = 0.0;
    double cosine = 1.0;
    double sigma = 1.0;
  };

  /// The gradient dW/d(u_a, theta_a, u_b, theta_b), keeping in `k` what Hessian() needs, so that
  /// a caller who finds the residual small enough never pays for the Hessian.
  void Gradient(const Eigen::Vector3d& du, const Eigen::Quaterniond& qa,
                const Eigen::Quaterniond& qb, Vector12& gradient, Kinematics& k) const;

  /// The chart Hessian at the configuration Gradient() saw.
  void Hessian(const Kinematics& k, Tangent& tangent) const;

 private:
  struct Strains {
    Eigen::Matrix3d midpoint;  // R_m
    Eigen::Vector3d axis;      // nu: unit axis of psi (material = spatial-in-frame-m)
    double sine = 0.0;         // sin(|psi| / 2)
    double cosine = 1.0;       // cos(|psi| / 2) >= 0
    double sigma = 1.0;        // (|psi| / 2) / sin(|psi| / 2)
    Eigen::Vector3d gamma;     // Gamma
    Eigen::Vector3d kappa;     // kappa = psi / h
  };

  // The relative rotation p = q_a* q_b, its sign chosen so that Re p >= 0 (then q_b and -q_b give
  // the same element); the geodesic midpoint is the normalised (q_a + q_b) of that sign.
  Strains StrainsAt(const Eigen::Vector3d& du, const Eigen::Quaterniond& qa,
                    const Eigen::Quaterniond& qb) const {
    Strains s;
    Eigen::Quaterniond p = qa.conjugate() * qb;
    const double sign = p.w() < 0.0 ? -1.0 : 1.0;
    p.coeffs() *= sign;
    s.sine = p.vec().norm();
    s.cosine = p.w();
    s.sigma =
        s.sine < 0.5 ? internal::AsinOverArgument(s.sine) : std::atan2(s.sine, s.cosine) / s.sine;
    s.axis = s.sine > 0.0 ? Eigen::Vector3d(p.vec() / s.sine) : Eigen::Vector3d::UnitX();
    s.kappa = (2.0 * s.sigma / length) * p.vec();
    Eigen::Quaterniond mid;
    mid.coeffs() = qa.coeffs() + sign * qb.coeffs();
    mid.normalize();
    s.midpoint = mid.toRotationMatrix();
    // Gamma = (R_m^T - I) e1 + R_m^T du / h, the first term straight from the quaternion: for
    // small strains it is small, and forming R_m^T e1 - e1 would cancel its digits away.
    const double w = mid.w();
    const Eigen::Vector3d v = mid.vec();
    const Eigen::Vector3d rotated_axis(-2.0 * (v.y() * v.y() + v.z() * v.z()),
                                       2.0 * (v.x() * v.y() - w * v.z()),
                                       2.0 * (v.x() * v.z() + w * v.y()));
    s.gamma = rotated_axis + s.midpoint.transpose() * (du / length);
    s.gamma.x() += axial_prestress / force_stiffness.x();
    return s;
  }
};

inline void CosseratElement::Gradient(const Eigen::Vector3d& du, const Eigen::Quaterniond& qa,
                                      const Eigen::Quaterniond& qb, Vector12& gradient,
                                      Kinematics& k) const {
  const Strains s = StrainsAt(du, qa, qb);
  k.rotation = s.midpoint;
  k.force = s.midpoint * force_stiffness.cwiseProduct(s.gamma);
  k.moment = s.midpoint * moment_stiffness.cwiseProduct(s.kappa);
  k.axis = s.midpoint * s.axis;
  k.chord = length * Eigen::Vector3d::UnitX() + du;
  k.sine = s.sine;
  k.cosine = s.cosine;
  k.sigma = s.sigma;
  // The midpoint frame's spin is (theta_a + theta_b)/2 - [tau]x (theta_b - theta_a)/2 with
  // tau = tan(|psi|/4) nu, and the change of psi is S (theta_b - theta_a) in the midpoint frame,
  // S = sigma (I - nu nu^T) + nu nu^T: the Jacobian of log at the geodesic midpoint, symmetric.
  // So dW = n . d(du) + (n x d) . omega + m . S (theta_b - theta_a).
  const Eigen::Vector3d tau = (s.sine / (1.0 + s.cosine)) * k.axis;
  const Eigen::Vector3d sm = s.sigma * k.moment + (1.0 - s.sigma) * k.axis.dot(k.moment) * k.axis;
  const Eigen::Vector3d c = k.force.cross(k.chord);
  const Eigen::Vector3d c_tau = c.cross(tau);
  gradient.segment<3>(0) = -k.force;
  gradient.segment<3>(3) = 0.5 * (c + c_tau) - sm;
  gradient.segment<3>(6) = k.force;
  gradient.segment<3>(9) = 0.5 * (c - c_tau) + sm;
}

inline void CosseratElement::Hessian(const Kinematics& k, Tangent& tangent) const {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const double h = length;
  const Matrix3d& r = k.rotation;
  const Vector3d& n = k.force;
  const Vector3d& m = k.moment;
  const Vector3d& nu = k.axis;
  const Vector3d& d = k.chord;
  const double t = k.sine / (1.0 + k.cosine);  // tan(|psi| / 4)
  const Vector3d tau = t * nu;
  const double nu_m = nu.dot(m);
  const Vector3d sm = k.sigma * m + (1.0 - k.sigma) * nu_m * nu;  // S m
  const Vector3d c = n.cross(d);

  // Coefficients of the log map's derivatives; their closed forms cancel near psi = 0, where
  // the series (in s = sin(|psi|/2), errors < 1e-17) take over.
  const double sine = k.sine;
  const double phi = 2.0 * k.sigma * sine;  // |psi|
  double sigma_prime = 0.0;                 // d sigma / d|psi|
  double one_minus_sigma_over_phi = 0.0;    // (1 - sigma) / |psi|
  double t_over_phi = 0.25;                 // tan(|psi|/4) / |psi|
  if (sine < 1e-2) {
    const double s2 = sine * sine;
    sigma_prime = sine * (1.0 / 6.0 + s2 * (1.0 / 15.0 + s2 * 4.0 / 105.0));
    // (1 - sigma)/phi = -(s^2/6 + 3 s^4/40 + 5 s^6/112) / (2 s sigma)
    one_minus_sigma_over_phi =
        -sine * (1.0 / 6.0 + s2 * (3.0 / 40.0 + s2 * 5.0 / 112.0)) / (2.0 * k.sigma);
    if (sine > 0.0) t_over_phi = t / phi;
  } else {
    const double half = k.sigma * sine;
    sigma_prime = 0.5 * (sine - half * k.cosine) / (sine * sine);
    one_minus_sigma_over_phi = (1.0 - k.sigma) / phi;
    t_over_phi = t / phi;
  }
  const double t_prime = 0.25 * (1.0 + t * t);  // d tan(|psi|/4) / d|psi|

  // The Hessian is the symmetric part of the spatial linearisation D of the gradient. With the
  // midpoint spin omega = (I + T)/2 theta_a + (I - T)/2 theta_b, T = [tau]x, the change of psi
  // (material) S R_m^T (theta_b - theta_a), and the directors e_k = R_m e_k, every block is a
  // sum of outer products and skew matrices of the element's vectors:
  //   dn/d(du) = C_f / h = sum_k (c_k / h) e_k e_k^T,
  //   dc/d(du) = (dn/d(omega))^T = sum_k (c_k / h) f_k e_k^T + [n]x = Y, f_k = e_k x d,
  //   dc/d(omega) = sum_k (c_k / h) f_k f_k^T + n d^T - (d . n) I = W   (c = n x d),
  //   d(S m)/d(omega) = -[S m]x (a rigid spin of the midpoint frame turns S m with it).
  const Matrix3d i3 = Matrix3d::Identity();
  const Vector3d scaled_force = force_stiffness / h;
  const Vector3d scaled_moment = moment_stiffness / h;
  Matrix3d cf = Matrix3d::Zero();
  Matrix3d y = Skew(n);
  Matrix3d w = n * d.transpose() - d.dot(n) * i3;
  Matrix3d tw = t * (nu.cross(n) * d.transpose() - d.dot(n) * Skew(nu));  // T W
  Matrix3d sms = Matrix3d::Zero();                                        // S C_m S / h
  for (int j = 0; j < 3; ++j) {
    const Vector3d e = r.col(j);
    const Vector3d f = e.cross(d);
    const Vector3d scaled_f = scaled_force[j] * f;
    const Vector3d se = k.sigma * e + (1.0 - k.sigma) * nu.dot(e) * nu;
    internal::AddOuterProduct(cf, scaled_force[j] * e, e);
    internal::AddOuterProduct(y, scaled_f, e);
    internal::AddOuterProduct(w, scaled_f, f);
    internal::AddOuterProduct(tw, t * nu.cross(scaled_f), f);
    internal::AddOuterProduct(sms, scaled_moment[j] * se, se);
  }
  // Rotational rows: with A = c/2 and B = c x tau / 2 - S m the gradient is A + B at node a and
  // A - B at node b, and
  //   d(A + B)/d(omega) = U = (I - T) W / 2 - E,  d(A - B)/d(omega) = W - U,
  //   E = t [c]x [nu]x / 2 - [S m]x = t (nu c^T - (c . nu) I) / 2 - [S m]x,
  //   dB/d(theta_b - theta_a) = B_t = [c]x (d tau/d psi) S / 2 - (d(S m)/d psi) S.
  // Only sym(B_t) enters the Hessian: S C_m S / h, the rank-2 sym(z nu^T) and the projector
  // (I - nu nu^T) part; its skew [c]x term drops out.
  const Matrix3d u = 0.5 * (w - tw) - 0.5 * t * (nu * c.transpose() - c.dot(nu) * i3) + Skew(sm);
  // X T row by row: (x^T [nu]x) = (x x nu)^T.
  Matrix3d ut, wt;
  for (int row = 0; row < 3; ++row) {
    ut.row(row) = t * Vector3d(u.row(row).transpose()).cross(nu).transpose();
    wt.row(row) = t * Vector3d(w.row(row).transpose()).cross(nu).transpose();
  }
  const Vector3d m_perp = m - nu_m * nu;
  const Vector3d z = (0.5 * (t_prime - t_over_phi * k.sigma)) * c.cross(nu) -
                     (sigma_prime + one_minus_sigma_over_phi * k.sigma) * m_perp;
  const Matrix3d b_sym = 0.5 * (z * nu.transpose() + nu * z.transpose()) - sms -
                         (one_minus_sigma_over_phi * k.sigma * nu_m) * (i3 - nu * nu.transpose());
  // D blocks: (theta_a, theta_a) = U (I + T)/2 - B_t, (theta_a, theta_b) = U (I - T)/2 + B_t,
  // (theta_b, theta_a) = V (I + T)/2 + B_t, (theta_b, theta_b) = V (I - T)/2 - B_t, V = W - U.
  const Matrix3d p_aa = 0.5 * (u + ut);
  const Matrix3d p_bb = 0.5 * ((w - u) - (wt - ut));
  const Matrix3d h_ba = 0.25 * ((w - u) + (wt - ut) + u.transpose() - ut.transpose()) + b_sym;
  // (theta_a, u_a) = -(I - T) Y / 2 and (theta_b, u_a) = -(I + T) Y / 2.
  Matrix3d ty;
  for (int col = 0; col < 3; ++col) ty.col(col) = tau.cross(y.col(col));

  tangent.force = cf;
  tangent.rotation_a_force = -0.5 * (y - ty);
  tangent.rotation_b_force = -0.5 * (y + ty);
  tangent.rotation_aa = 0.5 * (p_aa + p_aa.transpose()) - b_sym;
  tangent.rotation_bb = 0.5 * (p_bb + p_bb.transpose()) - b_sym;
  tangent.rotation_ba = h_ba;
}

}  // namespace cosmems
