#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/beam/element_spec.hpp"
#include "cosmems/beam/frame_layout.hpp"
#include "cosmems/beam/power_series_basis.hpp"

namespace cosmems {

/// The power-series bases of one series order, shared by every element of a model.
struct FrameBases {
  explicit FrameBases(int order)
      : bar(FieldKind::kBar, order), bending(FieldKind::kBending, order) {}
  PowerSeriesBasis bar;
  PowerSeriesBasis bending;
  int order() const { return bending.order(); }
};

/// A straight Euler-Bernoulli frame element along x with power-series shape functions.
///
/// Degrees of freedom per node follow FrameLayout<Dim>; rotations are right-handed, so in the
/// x-y plane r_z = duy/dx and in the x-z plane r_y = -duz/dx. The four fields (axial, torsion,
/// two bending planes) are uncoupled in a straight element; each has its own frequency
/// parameter c (rho A l^4 / EI for bending, rho A l^2 / EA axially, rho I_p l^2 / GJ in torsion).
template <int Dim>
class FrameElement {
 public:
  static constexpr int kNodeDofs = FrameLayout<Dim>::kNodeDofs;
  static constexpr int kDofs = 2 * kNodeDofs;
  using Matrix = Eigen::Matrix<double, kDofs, kDofs>;

  /// `properties` in internal units.
  explicit FrameElement(const ElementProperties& properties) : p_(properties) {}

  const ElementProperties& properties() const { return p_; }

  /// Linear elastic stiffness K_L.
  Matrix Stiffness(const FrameBases& bases) const { return Assemble(bases, Term::kStiffness, 0); }

  /// Mass term M_{2j}: the coefficient of w^(2j+2) in -D(w); j = 0 is the consistent mass.
  Matrix Mass(const FrameBases& bases, int j) const { return Assemble(bases, Term::kMass, j); }

  /// Geometric stiffness term G_j per unit axial force (tension > 0): the coefficient of
  /// N w^(2j) in D(w). G_0 is K_NL / N; the bar fields take none.
  Matrix Geometric(const FrameBases& bases, int j) const {
    return Assemble(bases, Term::kGeometric, j);
  }

 private:
  enum class Term { kStiffness, kMass, kGeometric };

  Matrix Assemble(const FrameBases& bases, Term term, int j) const {
    Matrix out = Matrix::Zero();
    const double l = p_.length;
    const double ea = p_.young_modulus * p_.area;
    const double rho_a = p_.density * p_.area;
    if (term != Term::kGeometric) {
      AddBar(out, bases.bar, term, j, NodalDof::kUx, ea / l, rho_a * l, rho_a * l * l / ea);
    }
    const double eiz = p_.young_modulus * p_.second_moment_z;
    AddBending(out, bases.bending, term, j, NodalDof::kUy, NodalDof::kRz, 1.0, eiz, rho_a);
    if constexpr (Dim == 3) {
      const double gj = p_.shear_modulus * p_.torsion_constant;
      const double rho_ip = p_.density * p_.polar_moment;
      if (term != Term::kGeometric) {
        AddBar(out, bases.bar, term, j, NodalDof::kRx, gj / l, rho_ip * l, rho_ip * l * l / gj);
      }
      const double eiy = p_.young_modulus * p_.second_moment_y;
      AddBending(out, bases.bending, term, j, NodalDof::kUz, NodalDof::kRy, -1.0, eiy, rho_a);
    }
    return out;
  }

  static int Index(int node, NodalDof dof) {
    return node * kNodeDofs + FrameLayout<Dim>::kIndex[static_cast<int>(dof)];
  }

  static void AddBar(Matrix& out, const PowerSeriesBasis& basis, Term term, int j, NodalDof dof,
                     double stiffness, double mass, double c) {
    const Eigen::MatrixXd& m = term == Term::kStiffness ? basis.Stiffness() : basis.Mass(j);
    const double factor = term == Term::kStiffness ? stiffness : mass * std::pow(c, j);
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) out(Index(a, dof), Index(b, dof)) += factor * m(a, b);
    }
  }

  // Nodal values (w1, l theta1, w2, l theta2) of the basis map to (u, r) with theta = sign * r.
  // c = rho A l^4 / EI carries the frequency powers: M_2j ~ rho A l c^j, G_j ~ c^j / l.
  void AddBending(Matrix& out, const PowerSeriesBasis& basis, Term term, int j, NodalDof u,
                  NodalDof r, double sign, double ei, double rho_a) const {
    const double l = p_.length;
    const double c = rho_a * l * l * l * l / ei;
    const Eigen::MatrixXd* m = &basis.Stiffness();
    double factor = ei / (l * l * l);
    if (term == Term::kMass) {
      m = &basis.Mass(j);
      factor = rho_a * l * std::pow(c, j);
    } else if (term == Term::kGeometric) {
      m = &basis.Geometric(j);
      factor = std::pow(c, j) / l;
    }
    const int index[4] = {Index(0, u), Index(0, r), Index(1, u), Index(1, r)};
    const double scale[4] = {1.0, sign * l, 1.0, sign * l};
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        out(index[a], index[b]) += factor * scale[a] * scale[b] * (*m)(a, b);
      }
    }
  }

  ElementProperties p_;
};

}  // namespace cosmems
