#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/haptics/probe_faces.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// The probe pressing on a structure's faces (ProbeFaces pushes): the box of every mesh element
/// (its length, its thickness along its local y, its width along its local z) and of every
/// rigid body. The sphere's centre is in the structure's global axes [m].
///
/// MoveTo() takes the box nearest the centre (the least distance from the centre to the box;
/// the first of those containing it) among those within the radius across their thickness (a
/// box's faces are taken unbounded along its thickness, so the clearance above a face is known at
/// any height), and places the faces of its member at the point of each under the sphere: the
/// box's thickness and width faces, and the member's two ends (a member is one straight box from
/// its first node to its second, so no face stands between two of its elements). A face of an
/// element moves along its axis with the element's interpolation at that point: linear u_x for
/// the ends, the Hermite cubics of u_y and u_z for the thickness and width faces, plus the
/// section's rotation (linear in xi) times the point's arm from the axis, so a push off the axis
/// twists the member. A face of a body moves as the body, u + theta x (P - c). A face's weights
/// keep only the degrees of freedom coupled to the direction it mostly moves in
/// (FrameModel::Coupled): the band has no room for the rest, which are the small arm terms across
/// a planar device's in-plane and out-of-plane groups and, in a straight chain without
/// FrameCouplings::kTwist, the twist. Placing the faces costs a scan of the boxes and allocates
/// nothing.
class ProbeContact final : public ProbeFaces {
 public:
  ProbeContact(const FrameModel& model, const ProbeOptions& options)
      : ProbeFaces(model.units(), options), model_(model) {
    const FrameMesh& mesh = model.mesh();
    for (int e = 0; e < model.ElementCount(); ++e) {
      const FrameMesh::Element& element = mesh.elements[e];
      const RectangularSection& s = model.description().members[element.member].section;
      Box box;
      box.centre = 0.5 * (mesh.nodes[element.from].position + mesh.nodes[element.to].position) /
                   units_.length;
      box.axes = element.axes;
      box.half = 0.5 * Eigen::Vector3d(element.length, s.thickness, s.width) / units_.length;
      box.element = e;
      // Elements come member by member, each member's from its first node to its second.
      const bool starts = e == 0 || mesh.elements[e - 1].member != element.member;
      box.first = starts ? e : boxes_.back().first;
      boxes_.push_back(box);
    }
    for (std::size_t b = 0; b < model.description().bodies.size(); ++b) {
      const StructureBody& body = model.description().bodies[b];
      Box box;
      box.centre = body.center / units_.length;
      box.axes = Eigen::Matrix3d::Identity();
      box.half = 0.5 * body.size / units_.length;
      box.body = static_cast<int>(b);
      box.first = box.last = static_cast<int>(boxes_.size());
      boxes_.push_back(box);
    }
    for (int e = model.ElementCount() - 1; e >= 0; --e) {
      const bool ends =
          e + 1 == model.ElementCount() || mesh.elements[e + 1].member != mesh.elements[e].member;
      boxes_[e].last = ends ? e : boxes_[e + 1].last;
    }
  }

  /// Places the sphere's centre at `centre_m` [m, global axes].
  void MoveTo(const Eigen::Vector3d& centre_m) {
    const Eigen::Vector3d p = centre_m / units_.length;
    const double r2 = radius_ * radius_;
    const Box* nearest = nullptr;
    double least = std::numeric_limits<double>::infinity();
    for (const Box& box : boxes_) {
      const Eigen::Vector3d out = Outside(box, p);
      // Beyond the radius across the thickness (or NaN): out of reach.
      if (!(out.x() * out.x() + out.z() * out.z() < r2)) continue;
      if (out.squaredNorm() < least) {
        least = out.squaredNorm();
        nearest = &box;
      }
    }
    reach_ = nearest != nullptr;
    if (!reach_) return;
    const Box& box = *nearest;
    const Eigen::Vector3d q = box.axes * (p - box.centre);
    const Eigen::Vector3d out = Outside(box, p);
    const Eigen::Vector3d clamped = q - out;
    // Faces in ProbeFace order: +-y, +-z, -x, +x of the box.
    constexpr int kAxis[kProbeFaceCount] = {1, 1, 2, 2, 0, 0};
    constexpr double kSign[kProbeFaceCount] = {1.0, -1.0, 1.0, -1.0, -1.0, 1.0};
    for (int f = 0; f < kProbeFaceCount; ++f) {
      const int a = kAxis[f];
      const double s = kSign[f];
      // The ends are the member's: the face of its first or last box, at the same section.
      const Box& face_box =
          a != 0 ? box : boxes_[static_cast<std::size_t>(s < 0 ? box.first : box.last)];
      const double q_a = a != 0 ? q[a] : (box.axes * (p - face_box.centre))[a];
      // Across the face in its plane; every face unbounded along the thickness.
      const double across =
          out.squaredNorm() - out[a] * out[a] - (a == 1 ? 0.0 : out.y() * out.y());
      Eigen::Vector3d point = clamped;  // the face's point under the sphere, its box's axes
      point[a] = s * face_box.half[a];
      const Eigen::Vector3d normal = s * box.axes.row(a).transpose();
      std::array<int, 12> dofs;
      const Weights w = face_box.element >= 0 ? ElementWeights(face_box, a, point, dofs)
                                              : BodyWeights(face_box, a, point, dofs);
      Place(static_cast<ProbeFace>(f), s, face_box.half[a] - s * q_a + std::sqrt(r2 - across),
            normal, dofs, Coupled(w));
    }
  }

 private:
  using Weights = Eigen::Matrix<double, 12, 1>;

  struct Box {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< rows: its axes in global ones
    Eigen::Vector3d half = Eigen::Vector3d::Zero();      ///< half sizes along its axes
    int element = -1, body = -1;                         ///< what it is
    int first = 0, last = 0;  ///< the boxes of its member's ends (a body's: itself)
  };

  // How far the point p lies outside the box along each of its axes (zero inside).
  static Eigen::Vector3d Outside(const Box& box, const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = box.axes * (p - box.centre);
    return q - q.cwiseMax(-box.half).cwiseMin(box.half);
  }

  // The motion along the element's local axis a of the point (local offsets from its centre)
  // per unit of its carriers' dofs.
  Weights ElementWeights(const Box& box, int a, const Eigen::Vector3d& point,
                         std::array<int, 12>& dofs) const {
    const int e = box.element;
    const double l = model_.elements()[e].properties().length;
    const double xi = std::clamp(0.5 + point.x() / l, 0.0, 1.0);
    const std::array<double, 4> h = HermiteShapes(xi);
    Weights local = Weights::Zero();  // [u, theta] of the first node, then of the second
    if (a == 0) {
      local[0] = 1.0 - xi;
      local[6] = xi;
    } else if (a == 1) {  // thickness: u_y, with the slope r_z
      local[1] = h[0];
      local[5] = l * h[1];
      local[7] = h[2];
      local[11] = l * h[3];
    } else {  // width: u_z, with the slope -r_y
      local[2] = h[0];
      local[4] = -l * h[1];
      local[8] = h[2];
      local[10] = -l * h[3];
    }
    // The section's rotation theta(xi) moves the point off the axis by theta x o: along e_a,
    // theta . (o x e_a), o = (0, y, z): the twist for the thickness and width faces, the
    // bendings' rotations for the ends.
    const Eigen::Vector3d arm(0.0, point.y(), point.z());
    const Eigen::Vector3d lever = arm.cross(Eigen::Vector3d::Unit(a));
    for (int k = 0; k < 3; ++k) {
      local[3 + k] += (1.0 - xi) * lever[k];
      local[9 + k] += xi * lever[k];
    }
    dofs = model_.ElementDofs(e);
    return model_.ElementTransform(e).transpose() * local;
  }

  // The motion along global axis a of a body's point (offsets from its centre), u + theta x o.
  Weights BodyWeights(const Box& box, int a, const Eigen::Vector3d& point,
                      std::array<int, 12>& dofs) const {
    const int carrier = model_.mesh().body_carrier[box.body];
    dofs.fill(-1);
    for (int k = 0; k < 6; ++k) dofs[k] = model_.CarrierDof(carrier, k);
    Weights w = Weights::Zero();
    w[a] = 1.0;
    w.segment<3>(3) = point.cross(Eigen::Vector3d::Unit(a));
    return w;
  }

  // The weights without the directions outside the band of the one the face mostly moves in.
  Weights Coupled(Weights w) const {
    int principal = 0;
    for (int i = 0; i < 12; ++i) {
      if (i % 6 < 3 && std::abs(w[i]) > std::abs(w[principal])) principal = i;
    }
    for (int i = 0; i < 12; ++i) {
      if (!model_.Coupled(i, principal)) w[i] = 0.0;
    }
    return w;
  }

  const FrameModel& model_;
  std::vector<Box> boxes_;
};

}  // namespace cosmems
