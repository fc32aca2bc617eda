#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "cosmems/beam/element_spec.hpp"
#include "cosmems/rod/so3.hpp"

namespace cosmems {
namespace internal {

/// a x b and a . b on plain arrays, for CosseratElement::Hessian.
inline void Cross3(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
inline double Dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
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
  // Plain doubles throughout: Eigen's packet code for 3-vectors and 3 x 3 matrices (a packet
  // and a scalar tail, SSE2) costs more in shuffles and store-forwarding stalls than it saves
  // here (doc/speed.md, "Kernel choices").
  using internal::Cross3;
  using internal::Dot3;
  double n[3], m[3], nu[3], d[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = k.force[i];
    m[i] = k.moment[i];
    nu[i] = k.axis[i];
    d[i] = k.chord[i];
  }
  const double sig = k.sigma;
  const double t = k.sine / (1.0 + k.cosine);  // tan(|psi| / 4)
  const double nu_m = Dot3(nu, m);
  double tau[3], sm[3], m_perp[3], c[3], c_nu[3];
  for (int i = 0; i < 3; ++i) {
    tau[i] = t * nu[i];
    m_perp[i] = m[i] - nu_m * nu[i];
    sm[i] = sig * m_perp[i] + nu_m * nu[i];  // S m
  }
  Cross3(n, d, c);
  Cross3(c, nu, c_nu);

  // Coefficients of the log map's derivatives; their closed forms cancel near psi = 0, where
  // the series (in s = sin(|psi|/2), errors < 1e-17) take over.
  const double sine = k.sine;
  const double phi = 2.0 * sig * sine;    // |psi|
  double sigma_prime = 0.0;               // d sigma / d|psi|
  double one_minus_sigma_over_phi = 0.0;  // (1 - sigma) / |psi|
  double t_over_phi = 0.25;               // tan(|psi|/4) / |psi|
  if (sine < 1e-2) {
    const double s2 = sine * sine;
    sigma_prime = sine * (1.0 / 6.0 + s2 * (1.0 / 15.0 + s2 * 4.0 / 105.0));
    // (1 - sigma)/phi = -(s^2/6 + 3 s^4/40 + 5 s^6/112) / (2 s sigma)
    one_minus_sigma_over_phi =
        -sine * (1.0 / 6.0 + s2 * (3.0 / 40.0 + s2 * 5.0 / 112.0)) / (2.0 * sig);
    if (sine > 0.0) t_over_phi = t / phi;
  } else {
    const double half = sig * sine;
    sigma_prime = 0.5 * (sine - half * k.cosine) / (sine * sine);
    one_minus_sigma_over_phi = (1.0 - sig) / phi;
    t_over_phi = t / phi;
  }
  const double t_prime = 0.25 * (1.0 + t * t);  // d tan(|psi|/4) / d|psi|

  // The Hessian is the symmetric part of the spatial linearisation D of the gradient. With the
  // midpoint spin omega = (I + T)/2 theta_a + (I - T)/2 theta_b, T = [tau]x, the change of psi
  // (material) S R_m^T (theta_b - theta_a), and the directors e_k = R_m e_k, every block is a
  // sum of outer products and skew matrices of the element's vectors:
  //   dn/d(du) = F = R_m diag(C_f) R_m^T / h,
  //   dc/d(du) = (dn/d(omega))^T = [n]x - [d]x F = Y   (c = n x d),
  //   dc/d(omega) = [d]x F [d]x^T + n d^T - (d . n) I = W,
  //   d(S m)/d(omega) = -[S m]x (a rigid spin of the midpoint frame turns S m with it).
  // Rotational rows: with A = c/2 and B = c x tau / 2 - S m the gradient is A + B at node a and
  // A - B at node b, and
  //   d(A + B)/d(omega) = U = (I - T) W / 2 + E,  d(A - B)/d(omega) = W - U,
  //   E = -t (nu c^T - (c . nu) I) / 2 + [S m]x,
  //   dB/d(theta_b - theta_a) = B_t = [c]x (d tau/d psi) S / 2 - (d(S m)/d psi) S,
  // and D's rotational blocks are (theta_a, theta_a) = U (I + T)/2 - B_t, (theta_b, theta_b) =
  // (W - U)(I - T)/2 - B_t, (theta_b, theta_a) = (W - U)(I + T)/2 + B_t. Only sym(B_t) enters
  // the Hessian: S C_m S / h (C_m spatial), the rank-2 sym(z nu^T) and the projector
  // (I - nu nu^T) part; its skew [c]x term drops out. Expanded with (I - T)^T = I + T, the
  // blocks see W only through its symmetric part W_s, in (I -+ T) W_s (I +- T) =
  // W_s -+ (A + A^T) - T W_s T and (I + T) W_s (I + T) = W_s + A - A^T + T W_s T (A = T W_s),
  // and E only through rank-2 terms in nu and a skew matrix:
  //   K(theta_a, theta_a) = H - Delta,  K(theta_b, theta_b) = H + Delta,
  //   K(theta_b, theta_a) = (W_s + T W_s T)/4 - R + (A - A^T)/4 + [t (c x nu)/8 - S m/2]x,
  //   H = (W_s - T W_s T)/4 + R,  Delta = (A + A^T)/4 + t (sym(nu c^T) - (c . nu) I)/4,
  // with R = S C_m S / h - sym(B_t) + sym(E T)/2 (symmetric). These closed forms need fewer
  // products than forming U, W - U and their products with (I -+ T) (doc/speed.md).
  double f[3][3], cm[3][3];  // F and C_m / h in spatial components: R_m diag(.) R_m^T / h
  {
    const Eigen::Matrix3d& r = k.rotation;
    const double inv_h = 1.0 / length;
    double rf[3][3], rm[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int l = 0; l < 3; ++l) {
        rf[i][l] = r(i, l) * force_stiffness[l] * inv_h;
        rm[i][l] = r(i, l) * moment_stiffness[l] * inv_h;
      }
    }
    for (int j = 0; j < 3; ++j) {
      for (int i = j; i < 3; ++i) {
        f[i][j] = f[j][i] = rf[i][0] * r(j, 0) + rf[i][1] * r(j, 1) + rf[i][2] * r(j, 2);
        cm[i][j] = cm[j][i] = rm[i][0] * r(j, 0) + rm[i][1] * r(j, 1) + rm[i][2] * r(j, 2);
      }
    }
  }
  // [d]x F by columns (df[j] is column j), and W_s = [d]x ([d]x F)^T + sym(n d^T) - (d . n) I.
  double df[3][3], ws[3][3];
  for (int j = 0; j < 3; ++j) {
    const double column[3] = {f[0][j], f[1][j], f[2][j]};
    Cross3(d, column, df[j]);
  }
  const double dn = Dot3(d, n);
  for (int j = 0; j < 3; ++j) {
    const double row[3] = {df[0][j], df[1][j], df[2][j]};
    double g[3];
    Cross3(d, row, g);
    for (int i = j; i < 3; ++i) ws[i][j] = ws[j][i] = g[i] + 0.5 * (n[i] * d[j] + d[i] * n[j]);
    ws[j][j] -= dn;
  }
  // A = T W_s (a[j] is column j) and T W_s T = -T A^T, symmetric (twt[j] is column j).
  double a[3][3], twt[3][3];
  for (int j = 0; j < 3; ++j) {
    const double column[3] = {ws[0][j], ws[1][j], ws[2][j]};
    Cross3(tau, column, a[j]);
  }
  for (int j = 0; j < 3; ++j) {
    const double row[3] = {a[0][j], a[1][j], a[2][j]};
    Cross3(row, tau, twt[j]);
  }
  // R = sig^2 C_m + nu w^T + w nu^T + alpha I, with S C_m S = sig^2 C_m + sig (1 - sig)
  // (nu g^T + g nu^T) + (1 - sig)^2 (nu . g) nu nu^T, g = C_m nu, folded into w.
  const double projector = one_minus_sigma_over_phi * sig * nu_m;
  const double z_c = 0.5 * (t_prime - t_over_phi * sig);
  const double z_m = sigma_prime + one_minus_sigma_over_phi * sig;
  double g[3];
  for (int i = 0; i < 3; ++i) g[i] = cm[i][0] * nu[0] + cm[i][1] * nu[1] + cm[i][2] * nu[2];
  const double nu_nu = (1.0 - sig) * (1.0 - sig) * Dot3(nu, g) - projector;
  const double alpha = projector - 0.5 * t * nu_m;
  const double c_dot_nu = Dot3(c, nu);
  double w[3], wa[3], wb[3];  // R's w, and w -+ t c / 8 for Delta's sym(nu c^T) term
  for (int i = 0; i < 3; ++i) {
    const double z = z_c * c_nu[i] - z_m * m_perp[i];
    const double x0 = 0.5 * t * sm[i] - 0.25 * t * t * c_nu[i] - z;
    w[i] = sig * (1.0 - sig) * g[i] + 0.5 * x0 + 0.5 * nu_nu * nu[i];
    wa[i] = w[i] - 0.125 * t * c[i];
    wb[i] = w[i] + 0.125 * t * c[i];
  }
  double spin[3];
  for (int i = 0; i < 3; ++i) spin[i] = 0.125 * t * c_nu[i] - 0.5 * sm[i];
  const double sig2 = sig * sig;
  for (int j = 0; j < 3; ++j) {
    for (int i = j; i < 3; ++i) {
      const double base = 0.25 * (ws[i][j] - twt[j][i]) + sig2 * cm[i][j];
      const double a_sym = 0.25 * (a[j][i] + a[i][j]);
      double aa = base - a_sym + nu[i] * wa[j] + wa[i] * nu[j];
      double bb = base + a_sym + nu[i] * wb[j] + wb[i] * nu[j];
      double ba_sym = 0.25 * (ws[i][j] + twt[j][i]) - sig2 * cm[i][j] - nu[i] * w[j] - w[i] * nu[j];
      double ba_skew = 0.25 * (a[j][i] - a[i][j]);
      if (i == j) {
        aa += alpha + 0.25 * t * c_dot_nu;
        bb += alpha - 0.25 * t * c_dot_nu;
        ba_sym -= alpha;
      } else {
        // [spin]x below the diagonal: (1, 0) = spin_z, (2, 0) = -spin_y, (2, 1) = spin_x.
        ba_skew += (i - j == 2 ? -1.0 : 1.0) * spin[3 - i - j];
      }
      tangent.rotation_aa(i, j) = tangent.rotation_aa(j, i) = aa;
      tangent.rotation_bb(i, j) = tangent.rotation_bb(j, i) = bb;
      tangent.rotation_ba(i, j) = ba_sym + ba_skew;
      tangent.rotation_ba(j, i) = ba_sym - ba_skew;
    }
  }
  // Y = [n]x - [d]x F; (theta_a, u_a) = -(I - T) Y / 2 and (theta_b, u_a) = -(I + T) Y / 2.
  for (int j = 0; j < 3; ++j) {
    double y[3] = {-df[j][0], -df[j][1], -df[j][2]};  // column j
    y[(j + 1) % 3] += n[(j + 2) % 3];                 // n x e_j
    y[(j + 2) % 3] -= n[(j + 1) % 3];
    double ty[3];
    Cross3(tau, y, ty);
    for (int i = 0; i < 3; ++i) {
      tangent.rotation_a_force(i, j) = -0.5 * (y[i] - ty[i]);
      tangent.rotation_b_force(i, j) = -0.5 * (y[i] + ty[i]);
      tangent.force(i, j) = f[i][j];
    }
  }
}

}  // namespace cosmems
