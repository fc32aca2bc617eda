#pragma once

// An independent oracle for small-displacement 3-D Euler-Bernoulli frames, written from textbook
// formulas: plain 12x12 element matrices rotated into global axes, assembled densely, with supports
// and rigid-body links imposed through a null-space basis of the constraint matrix. It is naive
// (dense, O(n^3)) on purpose, so that it shares no code or shortcut with the frame model it checks.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

namespace cosmems::test::oracle {

/// One straight prismatic member between nodes a and b, meshed into `elements` equal elements.
struct Member {
  int a = 0, b = 0;
  double young = 0, shear = 0;   // E, G [Pa]
  double area = 0;               // A
  double iy = 0, iz = 0, j = 0;  // second moments about local y and local z, torsion constant
  double density = 0;            // rho [kg/m^3]
  // Polar second moment of area I_p = iy + iz (rotary inertia of torsion: rho I_p per length).
  double polar = 0;
  // Local y direction (orthogonalised against the axis).
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  int elements = 1;
};

/// A rigid body: mass and inertia tensor about its centre, nodes attached rigidly.
struct Body {
  Eigen::Vector3d center;
  double mass = 0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre, global axes
  std::vector<int> nodes;
};

struct Frame {
  std::vector<Eigen::Vector3d> nodes;  // positions [m]
  // Per node: ux uy uz rx ry rz fixed (size = nodes.size()).
  std::vector<std::array<bool, 6>> fixed;
  std::vector<Member> members;
  std::vector<Body> bodies;
};

namespace detail {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

/// Bending stiffness over (w_a, theta_a, w_b, theta_b) with theta = +dw/dx.
inline Eigen::Matrix4d BendingStiffness(double ei, double l) {
  Eigen::Matrix4d k;
  k << 12, 6 * l, -12, 6 * l,               //
      6 * l, 4 * l * l, -6 * l, 2 * l * l,  //
      -12, -6 * l, 12, -6 * l,              //
      6 * l, 2 * l * l, -6 * l, 4 * l * l;
  return ei / (l * l * l) * k;
}

/// Consistent (cubic Hermite) bending mass over the same dofs, translational inertia only.
inline Eigen::Matrix4d BendingMass(double rho_a, double l) {
  Eigen::Matrix4d m;
  m << 156, 22 * l, 54, -13 * l,              //
      22 * l, 4 * l * l, 13 * l, -3 * l * l,  //
      54, 13 * l, 156, -22 * l,               //
      -13 * l, -3 * l * l, -22 * l, 4 * l * l;
  return rho_a * l / 420 * m;
}

/// Adds `block` at local dofs (w, r) of both ends. In the x-z plane theta_y = -dw/dx, so there
/// `sign` = -1 flips every displacement-rotation coupling.
inline void AddBending(Matrix12d& m, const Eigen::Matrix4d& block, int w, int r, double sign) {
  const std::array<int, 4> dof = {w, r, w + 6, r + 6};
  const std::array<double, 4> s = {1, sign, 1, sign};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) m(dof[i], dof[k]) += s[i] * s[k] * block(i, k);
}

/// Adds the two-node pattern [diag off; off diag] at local dof i of both ends (axial, torsion).
inline void AddPair(Matrix12d& m, int i, double diag, double off) {
  m(i, i) += diag;
  m(i + 6, i + 6) += diag;
  m(i, i + 6) += off;
  m(i + 6, i) += off;
}

/// Direction cosines: rows are the local x, y, z axes in global coordinates.
inline Eigen::Matrix3d Axes(const Eigen::Vector3d& pa, const Eigen::Vector3d& pb,
                            const Eigen::Vector3d& up) {
  const Eigen::Vector3d x = (pb - pa).normalized();
  const Eigen::Vector3d y_raw = up - up.dot(x) * x;
  if (!(y_raw.norm() > 1e-9 * up.norm()))
    throw std::invalid_argument("oracle: up parallel to axis");
  const Eigen::Vector3d y = y_raw.normalized();
  Eigen::Matrix3d r;
  r.row(0) = x.transpose();
  r.row(1) = y.transpose();
  r.row(2) = x.cross(y).transpose();
  return r;
}

/// [v]x, so that [v]x w = v x w.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

/// Full-dof model. Node order: original nodes, body centres, then interior mesh nodes, so the
/// reported dofs are the leading `reported` ones.
struct Model {
  Eigen::MatrixXd k, m;  // assembled, unconstrained
  Eigen::MatrixXd z;     // null-space basis of all constraints: u = z q
  int reported = 0;
};

inline void AddElement(Model& model, const Member& mb, const Eigen::Vector3d& pa,
                       const Eigen::Vector3d& pb, int na, int nb) {
  const double l = (pb - pa).norm();
  if (!(l > 0)) throw std::invalid_argument("oracle: zero-length element");
  Matrix12d k = Matrix12d::Zero(), m = Matrix12d::Zero();
  AddPair(k, 0, mb.young * mb.area / l, -mb.young * mb.area / l);
  AddPair(k, 3, mb.shear * mb.j / l, -mb.shear * mb.j / l);
  AddBending(k, BendingStiffness(mb.young * mb.iz, l), 1, 5, 1);   // x-y plane: v, theta_z
  AddBending(k, BendingStiffness(mb.young * mb.iy, l), 2, 4, -1);  // x-z plane: w, theta_y
  const double rho_a = mb.density * mb.area;
  AddPair(m, 0, rho_a * l / 3, rho_a * l / 6);
  AddPair(m, 3, mb.density * mb.polar * l / 3, mb.density * mb.polar * l / 6);
  AddBending(m, BendingMass(rho_a, l), 1, 5, 1);
  AddBending(m, BendingMass(rho_a, l), 2, 4, -1);
  Matrix12d t = Matrix12d::Zero();  // u_local = t u_global
  const Eigen::Matrix3d r = Axes(pa, pb, mb.up);
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r;
  const Matrix12d kg = t.transpose() * k * t, mg = t.transpose() * m * t;
  const std::array<int, 2> node = {na, nb};
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 2; ++c) {
      model.k.block<6, 6>(6 * node[i], 6 * node[c]) += kg.block<6, 6>(6 * i, 6 * c);
      model.m.block<6, 6>(6 * node[i], 6 * node[c]) += mg.block<6, 6>(6 * i, 6 * c);
    }
}

inline Model Assemble(const Frame& frame) {
  const int n_orig = static_cast<int>(frame.nodes.size());
  const int n_body = static_cast<int>(frame.bodies.size());
  if (frame.fixed.size() != frame.nodes.size())
    throw std::invalid_argument("oracle: fixed.size() != nodes.size()");
  std::vector<Eigen::Vector3d> pos = frame.nodes;
  for (const Body& body : frame.bodies) pos.push_back(body.center);
  // Chains of node indices per member; interior nodes are created as they are met.
  std::vector<std::vector<int>> chains;
  for (const Member& mb : frame.members) {
    if (mb.a < 0 || mb.a >= n_orig || mb.b < 0 || mb.b >= n_orig || mb.elements < 1)
      throw std::invalid_argument("oracle: bad member");
    std::vector<int> chain = {mb.a};
    for (int e = 1; e < mb.elements; ++e) {
      chain.push_back(static_cast<int>(pos.size()));
      pos.push_back(pos[mb.a] + (pos[mb.b] - pos[mb.a]) * (double(e) / mb.elements));
    }
    chain.push_back(mb.b);
    chains.push_back(chain);
  }
  const int n = 6 * static_cast<int>(pos.size());
  Model model;
  model.reported = 6 * (n_orig + n_body);
  model.k = Eigen::MatrixXd::Zero(n, n);
  model.m = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 0; i < chains.size(); ++i)
    for (std::size_t e = 0; e + 1 < chains[i].size(); ++e) {
      const int na = chains[i][e], nb = chains[i][e + 1];
      AddElement(model, frame.members[i], pos[na], pos[nb], na, nb);
    }
  for (int b = 0; b < n_body; ++b) {
    const int c = 6 * (n_orig + b);
    model.m.block<3, 3>(c, c) += frame.bodies[b].mass * Eigen::Matrix3d::Identity();
    model.m.block<3, 3>(c + 3, c + 3) += frame.bodies[b].inertia;
  }
  // Constraint rows C u = 0: one per fixed dof, six per rigid link
  // (u_node - u_c - theta_c x r = u_node - u_c + [r]x theta_c = 0 and theta_node - theta_c = 0).
  std::vector<Eigen::RowVectorXd> rows;
  for (int i = 0; i < n_orig; ++i)
    for (int d = 0; d < 6; ++d)
      if (frame.fixed[i][d]) rows.push_back(Eigen::RowVectorXd::Unit(n, 6 * i + d));
  for (int b = 0; b < n_body; ++b) {
    const int c = 6 * (n_orig + b);
    for (int node : frame.bodies[b].nodes) {
      if (node < 0 || node >= n_orig) throw std::invalid_argument("oracle: bad body node");
      Eigen::MatrixXd link = Eigen::MatrixXd::Zero(6, n);
      link.block<6, 6>(0, 6 * node).setIdentity();
      link.block<6, 6>(0, c) = -Eigen::Matrix<double, 6, 6>::Identity();
      link.block<3, 3>(0, c + 3) = Skew(pos[node] - pos[n_orig + b]);
      for (int r = 0; r < 6; ++r) rows.push_back(link.row(r));
    }
  }
  if (rows.empty()) {
    model.z = Eigen::MatrixXd::Identity(n, n);
    return model;
  }
  Eigen::MatrixXd cmat(rows.size(), n);
  for (std::size_t r = 0; r < rows.size(); ++r) cmat.row(r) = rows[r];
  // Rank-revealing, so redundant constraints (a fixed node also on a body) are harmless.
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(cmat);
  if (lu.rank() == n) throw std::invalid_argument("oracle: no free dofs");
  model.z = lu.kernel();
  return model;
}

/// s = diag(a)^(-1/2): micrometre frames mix EA/L ~ 1e3 with EI/L ~ 1e-9, and the symmetric
/// scaling s a s keeps the factorisations from losing the small terms.
inline Eigen::VectorXd JacobiScale(const Eigen::MatrixXd& a) {
  const Eigen::VectorXd d = a.diagonal();
  if (!(d.minCoeff() > 0)) throw std::runtime_error("oracle: free dof without stiffness");
  return d.cwiseSqrt().cwiseInverse();
}

/// The frame reduced onto its free motions q (u = z q) and Jacobi-scaled, q = diag(s) y:
/// K_s = S Z^T K Z S.
struct Reduced {
  Model model;
  Eigen::VectorXd s;
  Eigen::MatrixXd ks;

  explicit Reduced(const Frame& frame) : model(Assemble(frame)) {
    const Eigen::MatrixXd kr = model.z.transpose() * model.k * model.z;
    s = JacobiScale(kr);
    ks = s.asDiagonal() * kr * s.asDiagonal();
  }
  Eigen::MatrixXd ScaledMass() const {
    return s.asDiagonal() * (model.z.transpose() * model.m * model.z) * s.asDiagonal();
  }
  /// S Z^T f of loads in SolveStatic's layout.
  Eigen::VectorXd ScaledLoads(const Eigen::VectorXd& loads) const {
    if (loads.size() != model.reported) throw std::invalid_argument("oracle: wrong loads size");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.k.rows());
    f.head(model.reported) = loads;
    return s.asDiagonal() * (model.z.transpose() * f);
  }
  /// The reported dofs of scaled coordinates y.
  Eigen::VectorXd Reported(const Eigen::VectorXd& y) const {
    return (model.z * (s.asDiagonal() * y)).head(model.reported);
  }
};

}  // namespace detail

/// Static solution: 6 values per ORIGINAL node (ux uy uz rx ry rz, global axes), then 6 per body
/// (displacement and rotation of its centre). `loads` has the same layout (forces and moments at
/// nodes and at body centres). Loads on fixed dofs go into the supports.
inline Eigen::VectorXd SolveStatic(const Frame& frame, const Eigen::VectorXd& loads) {
  const detail::Reduced reduced(frame);
  const Eigen::LLT<Eigen::MatrixXd> llt(reduced.ks);
  if (llt.info() != Eigen::Success) throw std::runtime_error("oracle: frame is a mechanism");
  return reduced.Reported(llt.solve(reduced.ScaledLoads(loads)));
}

/// Natural frequencies [Hz], ascending, the lowest `count` (fewer if the frame has fewer dofs).
/// Solves K q = w^2 M q in the inverse form M q = mu K q, mu = 1/w^2: K is positive definite for a
/// supported frame while M may be singular (massless dofs, e.g. polar = 0, give mu = 0 and an
/// infinite frequency), and the lowest modes become the largest, most accurately computed mu.
inline Eigen::VectorXd Frequencies(const Frame& frame, int count) {
  const detail::Reduced reduced(frame);
  if (Eigen::LLT<Eigen::MatrixXd>(reduced.ks).info() != Eigen::Success)
    throw std::runtime_error("oracle: frame is a mechanism");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      reduced.ScaledMass(), reduced.ks, Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
  const Eigen::VectorXd& mu = solver.eigenvalues();  // ascending
  const int n = static_cast<int>(mu.size());
  constexpr double kPi = 3.14159265358979323846;
  const double tiny = n * std::numeric_limits<double>::epsilon() * std::abs(mu[n - 1]);
  Eigen::VectorXd hz(std::clamp(count, 0, n));
  for (int i = 0; i < hz.size(); ++i) {
    const double m = mu[n - 1 - i];
    hz[i] = m > tiny ? 1 / (2 * kPi * std::sqrt(m)) : std::numeric_limits<double>::infinity();
  }
  return hz;
}

namespace detail {
// Every mode of the scaled frame, M_s x_i = mu_i K_s x_i with x_i^T K_s x_i = 1 (mu ascending:
// the lowest modes last), the loads' share x_i^T g of each, and the mu below which a mode is
// massless (round-off of the largest).
struct Modes {
  Reduced reduced;
  Eigen::VectorXd mu, share;
  Eigen::MatrixXd x;
  double tiny = 0.0;

  Modes(const Frame& frame, const Eigen::VectorXd& loads) : reduced(frame) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        reduced.ScaledMass(), reduced.ks, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
    mu = solver.eigenvalues();
    x = solver.eigenvectors();
    share = x.transpose() * reduced.ScaledLoads(loads);
    tiny = static_cast<double>(mu.size()) * std::numeric_limits<double>::epsilon() *
           std::abs(mu[mu.size() - 1]);
  }

  int count() const { return static_cast<int>(mu.size()); }
  // Whether mode i responds dynamically: it is not a rigid motion, and it is among the lowest
  // `dynamic` (all of them when `dynamic` <= 0; the modes come highest mu, lowest frequency, last).
  bool Dynamic(int i, int dynamic) const {
    return mu[i] > tiny && (dynamic <= 0 || i >= count() - dynamic);
  }
};
}  // namespace detail

/// The undamped response (reported dofs, one row per time) to `loads` (SolveStatic's layout)
/// applied as a step at t = 0 to the frame at rest, by superposing all its modes: in the scaled
/// coordinates y (K_s y + M_s y'' = g), with M_s x_i = mu_i K_s x_i and x_i^T K_s x_i = 1, each
/// a_i(t) = (x_i^T g)(1 - cos(t / sqrt(mu_i))), whose sum at rest is y = K_s^-1 g. With
/// `dynamic` > 0 only the lowest `dynamic` modes oscillate and the others follow statically
/// (a_i = x_i^T g), the static correction of a truncated modal model.
inline Eigen::MatrixXd StepResponse(const Frame& frame, const Eigen::VectorXd& loads,
                                    const std::vector<double>& times, int dynamic = 0) {
  const detail::Modes modes(frame, loads);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(times.size()), modes.reduced.model.reported);
  for (std::size_t t = 0; t < times.size(); ++t) {
    Eigen::VectorXd a = modes.share;
    for (int i = 0; i < modes.count(); ++i) {
      if (modes.Dynamic(i, dynamic)) a[i] *= 1 - std::cos(times[t] / std::sqrt(modes.mu[i]));
    }
    out.row(static_cast<Eigen::Index>(t)) = modes.reduced.Reported(modes.x * a);
  }
  return out;
}

/// The steady response to `loads` (SolveStatic's layout) times sin(omega t), every mode damped
/// at the ratio `zeta`, by superposing all the modes: each modal coordinate (x_i^T K_s x_i = 1,
/// mass mu_i, damping c_i = 2 zeta sqrt(mu_i)) answers a_i = (x_i^T g) / (1 - mu_i omega^2 +
/// i omega c_i). With `dynamic` > 0 only the lowest `dynamic` modes respond dynamically, the
/// others statically (undamped, in phase with the load: a truncated modal model's static
/// correction). `amplitude`: each reported dof's; `dissipated`: the damping's work over a cycle,
/// pi omega sum c_i |a_i|^2 [J], what the load puts in.
struct HarmonicResponse {
  Eigen::VectorXd amplitude;
  double dissipated = 0.0;
};

inline HarmonicResponse SteadyHarmonic(const Frame& frame, const Eigen::VectorXd& loads,
                                       double omega, double zeta, int dynamic = 0) {
  constexpr double kPi = 3.14159265358979323846;
  const detail::Modes modes(frame, loads);
  Eigen::VectorXd re = modes.share, im = Eigen::VectorXd::Zero(modes.count());
  HarmonicResponse out;
  for (int i = 0; i < modes.count(); ++i) {
    if (!modes.Dynamic(i, dynamic)) continue;
    const double mu = modes.mu[i];
    const double c = 2.0 * zeta * std::sqrt(mu);
    const std::complex<double> a =
        modes.share[i] / std::complex<double>(1.0 - mu * omega * omega, omega * c);
    re[i] = a.real();
    im[i] = a.imag();
    out.dissipated += kPi * omega * c * std::norm(a);
  }
  const Eigen::VectorXd u_re = modes.reduced.Reported(modes.x * re);
  const Eigen::VectorXd u_im = modes.reduced.Reported(modes.x * im);
  out.amplitude = (u_re.array().square() + u_im.array().square()).sqrt();
  return out;
}

}  // namespace cosmems::test::oracle
