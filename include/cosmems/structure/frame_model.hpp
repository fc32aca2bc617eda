#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "cosmems/beam/element_interpolation.hpp"
#include "cosmems/beam/frame_element.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/structure/frame_mesh.hpp"
#include "cosmems/structure/reverse_cuthill_mckee.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The assembled, constant data of a linear frame: a device's members meshed into power-series
/// elements, each rotated from its own axes into the global ones, rigid bodies and anchors.
///
/// A node attached to a body is eliminated: its motion is the body's, u = u_c + theta_c x r, so
/// a body adds six degrees of freedom and no stiff springs. Anchored degrees of freedom are
/// removed. The carriers of motion (free nodes and bodies) are numbered in reverse
/// Cuthill-McKee order, so K and the mass terms M_2j keep a narrow band (SymmetricBandMatrix)
/// whatever the netlist's order. The six directions of motion fall into groups that no member
/// or body couples (a planar device's in-plane ux, uz, ry and out-of-plane uy, rx, rz; a chain
/// along x's four fields), and each group is numbered on its own, carrier by carrier: the band
/// is that of the widest group, as a beam's field-by-field numbering makes it (a netlist that
/// is a straight chain has the chain's band). A planar description numbers u_x, u_y and r_z
/// alone: a chain along x then has a planar beam's unknowns and band.
/// A member's residual axial force N (StructureMember::axial_load) adds N G_0 to its elements'
/// stiffness and -N G_(j+1) to their mass terms M_2j, the power series of the prestressed
/// element's dynamic stiffness (the highest term keeps M_2j alone).
/// The couplings between a member's fields that the forces on a frame may add to its linear
/// elements, as a set: axial stretching ties each member's axial field to its two bendings
/// (FrameStretchingForce); a probe pressing a thickness face off the axis ties the bending
/// across the thickness (u_y, r_z) to the twist r_x (ProbeContact). The numbering keeps
/// apart only what never couples: the twist widens a straight chain's band from its bending's
/// two unknowns a node to three, and leaves a planar device's (whose out-of-plane group holds
/// both) as it is.
enum class FrameCouplings : unsigned { kLinear = 0, kStretching = 1, kTwist = 2 };

constexpr FrameCouplings operator|(FrameCouplings a, FrameCouplings b) {
  return static_cast<FrameCouplings>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}

/// Whether the set `couplings` holds `c`.
constexpr bool Holds(FrameCouplings couplings, FrameCouplings c) {
  return (static_cast<unsigned>(couplings) & static_cast<unsigned>(c)) != 0;
}

class FrameModel {
 public:
  using Element = FrameElement<3>;
  using Transform = Eigen::Matrix<double, 12, 12>;
  using Motion = Eigen::Matrix<double, 6, 1>;
  using ElementVector = Eigen::Matrix<double, 12, 1>;

  explicit FrameModel(const StructureDescription& description,
                      FrameCouplings couplings = FrameCouplings::kLinear)
      : couplings_(couplings),
        description_((description.Validate(), description)),
        units_(InternalUnits(description)),
        bases_(description.series_order),
        mesh_(description) {
    int first = 0;
    for (const StructureMember& member : description.members) {
      first_element_.push_back(first);
      first += member.elements;
    }
    for (const FrameMesh::Element& e : mesh_.elements) {
      const StructureMember& member = description.members[e.member];
      elements_.emplace_back(
          ElementProperties::From(ElementSpec{e.length, member.material, member.section}, units_));
    }
    Number();
    Assemble();
  }

  const StructureDescription& description() const { return description_; }
  FrameCouplings couplings() const { return couplings_; }
  const UnitSystem& units() const { return units_; }
  const FrameBases& bases() const { return bases_; }
  const FrameMesh& mesh() const { return mesh_; }
  const std::vector<Element>& elements() const { return elements_; }

  int ElementCount() const { return static_cast<int>(elements_.size()); }
  int FreeDofCount() const { return free_; }
  int SeriesOrder() const { return bases_.order(); }

  /// K_L (with the members' prestress N G_0), and the mass terms M_2j (bodies in M_0 only; with
  /// the prestress's -N G_(j+1)), D(w) = K - sum_j w^(2j+2) M_2j.
  const SymmetricBandMatrix& Stiffness() const { return stiffness_; }
  const SymmetricBandMatrix& Mass(int j) const { return mass_.at(j); }

  /// Reduced index of a carrier's degree of freedom d (NodalDof order), or -1 when anchored.
  int CarrierDof(int carrier, int d) const { return dof_[6 * carrier + d]; }

  /// The element's K_L + N G_0 in its own axes (internal units), kept from the assembly for the
  /// recovery of end forces.
  const Element::Matrix& LocalStiffness(int e) const { return local_stiffness_[e]; }

  /// The element's local displacements from its carriers' (a's six, then b's): u = T q.
  const Transform& ElementTransform(int e) const { return transform_[e]; }
  /// The residual axial force of the element's member (internal units, tension > 0).
  double ElementAxialLoad(int e) const {
    return description_.members[mesh_.elements[e].member].axial_load / units_.force;
  }
  /// Reduced indices of the element's carriers' degrees of freedom, -1 where anchored.
  const std::array<int, 12>& ElementDofs(int e) const { return element_dofs_[e]; }

  /// The element's displacements in its own axes (internal units) in the reduced state d.
  ElementVector LocalDisplacement(const Eigen::VectorXd& d, int e) const {
    ElementVector q;
    for (int a = 0; a < 12; ++a) q[a] = element_dofs_[e][a] >= 0 ? d[element_dofs_[e][a]] : 0.0;
    return transform_[e] * q;
  }

  /// A carrier's motion (u, theta; global axes, internal units) in the reduced state d.
  Motion CarrierMotion(const Eigen::VectorXd& d, int carrier) const {
    Motion q;
    for (int k = 0; k < 6; ++k)
      q[k] = CarrierDof(carrier, k) >= 0 ? d[CarrierDof(carrier, k)] : 0.0;
    return q;
  }

  /// The element of `member` holding the point a fraction s (0 at its first node, 1 at its
  /// second) along it, and the point's local coordinate xi in [0, 1] there.
  std::pair<int, double> Locate(int member, double s) const {
    const int count = description_.members.at(member).elements;
    const double at = std::clamp(s, 0.0, 1.0) * count;
    const int k = std::min(static_cast<int>(at), count - 1);
    return {first_element_[member] + k, at - k};
  }

  /// The motion (u, theta; global axes, internal units) of the point a fraction s along
  /// `member` in the reduced state d: u_x and the twist linear along its element, each bending
  /// the Hermite cubic of its end values and slopes (the static shape, as BeamField recovers a
  /// beam's).
  Motion MemberMotion(const Eigen::VectorXd& d, int member, double s) const {
    const auto [e, xi] = Locate(member, s);
    const ElementVector q = LocalDisplacement(d, e);
    const double l = elements_[e].properties().length;
    const ShapeValues v = ShapeValues::At(bases_, xi);
    Eigen::Vector3d u, theta;
    u.x() = v.bar[0] * q[0] + v.bar[1] * q[6];
    theta.x() = v.bar[0] * q[3] + v.bar[1] * q[9];
    // x-y plane: (u_y, r_z) with r_z = du_y/dx; x-z plane: (u_z, r_y) with r_y = -du_z/dx.
    const double y[4] = {q[1], l * q[5], q[7], l * q[11]};
    const double z[4] = {q[2], -l * q[4], q[8], -l * q[10]};
    u.y() = u.z() = theta.y() = theta.z() = 0.0;
    for (int a = 0; a < 4; ++a) {
      u.y() += v.bending[a] * y[a];
      u.z() += v.bending[a] * z[a];
      theta.z() += v.bending_slope[a] * y[a] / l;
      theta.y() -= v.bending_slope[a] * z[a] / l;
    }
    const Eigen::Matrix3d& axes = mesh_.elements[e].axes;
    Motion out;
    out << axes.transpose() * u, axes.transpose() * theta;
    return out;
  }

  /// A mesh node's motion (u, theta; global axes, internal units) in the reduced state d.
  Motion NodeMotion(const Eigen::VectorXd& d, int node) const {
    return NodeTransform(node) * CarrierMotion(d, mesh_.nodes[node].carrier);
  }

  /// Adds a load (force, moment about the node; global axes, internal units) at a mesh node to
  /// the reduced load vector f: its work on the node's motion, T^T (F, C), falls on the carrier.
  void AddNodeLoad(int node, const Motion& load, Eigen::VectorXd& f) const {
    const Motion generalised = NodeTransform(node).transpose() * load;
    const int carrier = mesh_.nodes[node].carrier;
    for (int k = 0; k < 6; ++k) {
      if (CarrierDof(carrier, k) >= 0) f[CarrierDof(carrier, k)] += generalised[k];
    }
  }

  /// Adds a load at a carrier's reference point (a body's centre) to f.
  void AddCarrierLoad(int carrier, const Motion& load, Eigen::VectorXd& f) const {
    for (int k = 0; k < 6; ++k) {
      if (CarrierDof(carrier, k) >= 0) f[CarrierDof(carrier, k)] += load[k];
    }
  }

  /// A body's rigid mass about its centre (internal units): m I and the block's inertia tensor.
  Eigen::Matrix<double, 6, 6> BodyMass(int body) const {
    const StructureBody& b = description_.bodies[body];
    const double m = b.Mass() / units_.Mass();
    const Eigen::Vector3d s = b.size / units_.length;
    Eigen::Matrix<double, 6, 6> out = Eigen::Matrix<double, 6, 6>::Zero();
    out.topLeftCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
    out(3, 3) = m * (s.y() * s.y() + s.z() * s.z()) / 12.0;
    out(4, 4) = m * (s.x() * s.x() + s.z() * s.z()) / 12.0;
    out(5, 5) = m * (s.x() * s.x() + s.y() * s.y()) / 12.0;
    return out;
  }

  /// Adds T^T A T, an element's matrix A in its own axes carried onto its carriers, to `global`
  /// (a matrix of this model's pattern; A couples the local fields no more than K does). Two
  /// entries of one carrier (an element whose ends share a body) land on the same global entry
  /// and are both added; entries between uncoupled groups are zero up to the rotation's
  /// round-off, and left out.
  void AddElementMatrix(int e, const Element::Matrix& local, SymmetricBandMatrix& global) const {
    const Transform a = transform_[e].transpose() * local * transform_[e];
    const std::array<int, 12>& dofs = element_dofs_[e];
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        if (dofs[i] >= 0 && dofs[j] >= 0 && dofs[i] >= dofs[j] && Coupled(i, j))
          global.Add(dofs[i], dofs[j], a(i, j));
      }
    }
  }

  /// Whether directions i % 6 and j % 6 of carriers may couple (one group of the band): a force
  /// may tie two degrees of freedom only when they do.
  bool Coupled(int i, int j) const { return group_[i % 6] == group_[j % 6]; }

  /// Whether the model has direction d (0..5: ux, uy, uz, rx, ry, rz) at all: a planar one only
  /// u_x, u_y and r_z. A carrier's direction that the model has but numbers no unknown is held.
  bool Moves(int d) const {
    return !description_.planar || d == static_cast<int>(NodalDof::kUx) ||
           d == static_cast<int>(NodalDof::kUy) || d == static_cast<int>(NodalDof::kRz);
  }

  /// How a mesh node moves with its carrier: identity for a free node, [I -[r]x; 0 I] on a body.
  Eigen::Matrix<double, 6, 6> NodeTransform(int node) const {
    Eigen::Matrix<double, 6, 6> t = Eigen::Matrix<double, 6, 6>::Identity();
    t.topRightCorner<3, 3>() = -Skew(mesh_.nodes[node].offset / units_.length);
    return t;
  }

 private:
  // The longest member and the first member's E I_z and rho A (UnitSystem::ForBeam).
  static UnitSystem InternalUnits(const StructureDescription& s) {
    double length = 0.0;
    for (const StructureMember& m : s.members) {
      length = std::max(length, (s.nodes[m.to].position - s.nodes[m.from].position).norm());
    }
    const StructureMember& first = s.members.front();
    return UnitSystem::ForBeam(length, first.material.young_modulus * first.section.SecondMomentZ(),
                               first.material.density * first.section.Area());
  }

  // Whether an element's local dofs a and b may couple: one field; with stretching, the axial
  // field and the bendings; with the twist, the bending across the thickness and the torsion.
  bool LocalCoupled(int a, int b) const {
    const DofField fa = FieldOf(static_cast<NodalDof>(a % 6));
    const DofField fb = FieldOf(static_cast<NodalDof>(b % 6));
    auto pair = [&](DofField x, DofField y) {
      return (fa == x && fb == y) || (fa == y && fb == x);
    };
    const bool stretching = Holds(couplings_, FrameCouplings::kStretching) &&
                            fa != DofField::kTorsion && fb != DofField::kTorsion;
    const bool twist =
        Holds(couplings_, FrameCouplings::kTwist) && pair(DofField::kBendingY, DofField::kTorsion);
    return fa == fb || stretching || twist;
  }

  // The groups of the six directions that some element couples: its coupled local fields
  // (LocalCoupled) carried through its transform, entries below 1e-12 of the transform's taken
  // as the rotation's round-off. A body's inertia about its centre couples none (its offsets
  // couple through the elements' transforms).
  void Group() {
    Transform coupled;
    for (int a = 0; a < 12; ++a) {
      for (int b = 0; b < 12; ++b) coupled(a, b) = LocalCoupled(a, b);
    }
    for (int d = 0; d < 6; ++d) group_[d] = d;
    auto root = [&](int d) {
      while (group_[d] != d) d = group_[d];
      return d;
    };
    for (const Transform& t : transform_) {
      const Transform magnitude = t.cwiseAbs();
      const Transform present =
          (magnitude.array() > 1e-12 * magnitude.maxCoeff()).cast<double>().matrix();
      const Transform couples = present.transpose() * coupled * present;
      for (int i = 0; i < 12; ++i) {
        for (int j = 0; j < 12; ++j) {
          if (couples(i, j) != 0.0) group_[root(i % 6)] = root(j % 6);
        }
      }
    }
    for (int d = 0; d < 6; ++d) group_[d] = root(d);
  }

  // Carriers in reverse Cuthill-McKee order over the elements' connections, each group of
  // directions on its own (Group).
  void Number() {
    const int carriers = static_cast<int>(mesh_.carriers.size());
    std::vector<std::vector<int>> adjacency(carriers);
    for (const FrameMesh::Element& e : mesh_.elements) {
      const int a = mesh_.nodes[e.from].carrier;
      const int b = mesh_.nodes[e.to].carrier;
      if (a == b) continue;
      adjacency[a].push_back(b);
      adjacency[b].push_back(a);
    }
    for (std::vector<int>& list : adjacency) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    for (const FrameMesh::Element& element : mesh_.elements) {
      Transform t = Transform::Zero();
      const int ends[2] = {element.from, element.to};
      for (int end = 0; end < 2; ++end) {
        const Eigen::Matrix<double, 6, 6> node = NodeTransform(ends[end]);
        t.block<3, 6>(6 * end, 6 * end) = element.axes * node.topRows<3>();
        t.block<3, 6>(6 * end + 3, 6 * end) = element.axes * node.bottomRows<3>();
      }
      transform_.push_back(t);
    }
    Group();
    dof_.assign(6 * carriers, -1);
    const std::vector<int> order = ReverseCuthillMcKee(adjacency);
    for (int g = 0; g < 6; ++g) {
      for (int c : order) {
        for (int d = 0; d < 6; ++d) {
          if (group_[d] == g && Moves(d) && !mesh_.carriers[c].anchor[d]) dof_[6 * c + d] = free_++;
        }
      }
    }
    for (const FrameMesh::Element& element : mesh_.elements) {
      std::array<int, 12> dofs;
      for (int a = 0; a < 12; ++a) {
        dofs[a] = CarrierDof(mesh_.nodes[a < 6 ? element.from : element.to].carrier, a % 6);
      }
      element_dofs_.push_back(dofs);
    }
  }

  int Bandwidth() const {
    int bandwidth = 0;
    for (const std::array<int, 12>& dofs : element_dofs_) {
      for (int a = 0; a < 12; ++a) {
        for (int b = 0; b < a; ++b) {
          if (dofs[a] >= 0 && dofs[b] >= 0 && Coupled(a, b))
            bandwidth = std::max(bandwidth, std::abs(dofs[a] - dofs[b]));
        }
      }
    }
    for (int body : mesh_.body_carrier) {
      for (int d = 0; d < 6; ++d) {
        for (int k = 0; k < d; ++k) {
          if (CarrierDof(body, d) >= 0 && CarrierDof(body, k) >= 0 && Coupled(d, k)) {
            bandwidth = std::max(bandwidth, std::abs(CarrierDof(body, d) - CarrierDof(body, k)));
          }
        }
      }
    }
    return bandwidth;
  }

  void Assemble() {
    const int bandwidth = Bandwidth();
    const int order = bases_.order();
    stiffness_ = SymmetricBandMatrix(free_, bandwidth);
    mass_.assign(order + 1, SymmetricBandMatrix(free_, bandwidth));
    for (int e = 0; e < ElementCount(); ++e) {
      const double n = ElementAxialLoad(e);
      local_stiffness_.push_back(elements_[e].Stiffness(bases_));
      if (n != 0.0) local_stiffness_.back() += n * elements_[e].Geometric(bases_, 0);
      AddElementMatrix(e, local_stiffness_.back(), stiffness_);
      for (int j = 0; j <= order; ++j) {
        Element::Matrix m = elements_[e].Mass(bases_, j);
        if (n != 0.0 && j < order) m -= n * elements_[e].Geometric(bases_, j + 1);
        AddElementMatrix(e, m, mass_[j]);
      }
    }
    for (std::size_t b = 0; b < mesh_.body_carrier.size(); ++b) {
      const int carrier = mesh_.body_carrier[b];
      const Eigen::Matrix<double, 6, 6> m = BodyMass(static_cast<int>(b));
      for (int k = 0; k < 6; ++k) {
        for (int d = 0; d < 6; ++d) {
          const int rk = CarrierDof(carrier, k);
          const int rd = CarrierDof(carrier, d);
          if (rk >= 0 && rd >= 0 && rk >= rd && Coupled(k, d)) mass_[0].Add(rk, rd, m(k, d));
        }
      }
    }
  }

  FrameCouplings couplings_;
  StructureDescription description_;
  UnitSystem units_;
  FrameBases bases_;
  FrameMesh mesh_;
  std::vector<Element> elements_;
  std::vector<int> first_element_;  ///< each member's first element (members mesh in order)
  std::array<int, 6> group_{};      ///< each direction's group: the root direction of its group
  std::vector<int> dof_;
  int free_ = 0;
  std::vector<std::array<int, 12>> element_dofs_;
  std::vector<Transform> transform_;
  std::vector<Element::Matrix> local_stiffness_;
  SymmetricBandMatrix stiffness_;
  std::vector<SymmetricBandMatrix> mass_;
};

}  // namespace cosmems
