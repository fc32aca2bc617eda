#pragma once

#include <Eigen/Core>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <vector>

#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// A connected part of a device (its nodes joined by members and bodies) that its anchors do not
/// hold, so that its stiffness matrix is singular: no node of it is anchored, or the dofs its
/// anchors fix leave it a rigid motion (a pinned beam turning about its pin).
struct FloatingPart {
  std::vector<int> nodes;    ///< the description's nodes in the part, ascending
  std::vector<int> members;  ///< its members, ascending
  std::vector<int> bodies;   ///< its bodies, ascending
  std::vector<int> anchors;  ///< its anchored nodes (empty: nothing holds it)
  /// A rigid motion the anchors leave free, u = translation + rotation x (x - centre) with the
  /// centre the mean of the part's nodes (any scale; components below 1e-9 of it are zero): a
  /// pure translation when `rotation` is zero. Without anchors, the translation along x.
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
};

namespace internal {

// The root of `n` in a union-find forest, halving the path as it goes.
inline int PartRoot(std::vector<int>& parent, int n) {
  while (parent[n] != n) n = parent[n] = parent[parent[n]];
  return n;
}

}  // namespace internal

/// The first part of a valid description (Validate) that floats, in the order of its lowest node,
/// or none when every part is held.
///
/// Members join their nodes rigidly and bodies hold theirs, so a part's stiffness vanishes for
/// its rigid motions alone (u = t + w x r, rotation w, at every node): the part is held exactly
/// when no rigid motion but zero keeps every anchored dof at zero, that is when the anchors'
/// constraints on (t, w) have rank 6. Rank is judged on positions scaled by the part's size, so
/// that translations and rotations weigh alike, to 1e-10 of the largest singular value: far
/// below any anchors a design spreads apart, far above round-off.
inline std::optional<FloatingPart> FindFloatingPart(const StructureDescription& s) {
  const int count = static_cast<int>(s.nodes.size());
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  auto join = [&](int a, int b) {
    parent[internal::PartRoot(parent, a)] = internal::PartRoot(parent, b);
  };
  for (const StructureMember& m : s.members) join(m.from, m.to);
  for (const StructureBody& b : s.bodies) {
    for (int n : b.nodes) join(n, b.nodes.front());
  }
  // The parts, each its nodes ascending, in the order of their lowest node.
  std::vector<int> part_of(count, -1);
  std::vector<std::vector<int>> parts;
  for (int n = 0; n < count; ++n) {
    int& part = part_of[internal::PartRoot(parent, n)];
    if (part < 0) {
      part = static_cast<int>(parts.size());
      parts.emplace_back();
    }
    parts[part].push_back(n);
  }
  for (const std::vector<int>& nodes : parts) {
    FloatingPart part;
    part.nodes = nodes;
    for (int n : nodes) {
      if (std::any_of(s.nodes[n].anchor.begin(), s.nodes[n].anchor.end(), [](bool f) { return f; }))
        part.anchors.push_back(n);
    }
    if (part.anchors.empty()) {
      part.translation = Eigen::Vector3d::UnitX();
    } else {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int n : nodes) centre += s.nodes[n].position;
      centre /= static_cast<double>(nodes.size());
      double size = 0.0;
      for (int n : nodes) size = std::max(size, (s.nodes[n].position - centre).norm());
      if (size == 0.0) size = 1.0;  // one node: its own rotations are the rigid ones
      // One row per anchored dof, on (t, w size) with r in units of the part's size:
      // u_d = t_d + (w size) . (r x e_d), and theta_d = w_d.
      std::vector<Eigen::Matrix<double, 1, 6>> rows;
      for (int n : part.anchors) {
        const Eigen::Vector3d r = (s.nodes[n].position - centre) / size;
        for (int d = 0; d < 6; ++d) {
          if (!s.nodes[n].anchor[d]) continue;
          Eigen::Matrix<double, 1, 6> row = Eigen::Matrix<double, 1, 6>::Unit(d);
          if (d < 3) row.tail<3>() = r.cross(Eigen::Vector3d::Unit(d)).transpose();
          rows.push_back(row);
        }
      }
      Eigen::MatrixXd constraints(rows.size(), 6);
      for (std::size_t i = 0; i < rows.size(); ++i) constraints.row(i) = rows[i];
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(constraints, Eigen::ComputeFullV);
      const Eigen::VectorXd& sigma = svd.singularValues();
      if (sigma.size() == 6 && sigma(5) > 1e-10 * sigma(0)) continue;
      // The free motions span V's last columns; of them, the one nearest a translation along or
      // a rotation about an axis (the first such in x, y, z order), which names itself plainly.
      Eigen::Index free = 0;
      while (free < 6 && (6 - free > sigma.size() || sigma(5 - free) <= 1e-10 * sigma(0))) ++free;
      const Eigen::MatrixXd basis = svd.matrixV().rightCols(free);
      const Eigen::Matrix<double, 6, 6> projection = basis * basis.transpose();
      const Eigen::Matrix<double, 1, 6> reach = projection.colwise().norm();
      Eigen::Index axis = 0;
      while (reach(axis) < reach.maxCoeff() - 1e-9) ++axis;
      Eigen::Matrix<double, 6, 1> motion = projection.col(axis).normalized();
      motion = motion.unaryExpr([](double c) { return std::abs(c) < 1e-9 ? 0.0 : c; });
      part.translation = motion.head<3>();
      part.rotation = motion.tail<3>() / size;
    }
    const int root = internal::PartRoot(parent, nodes.front());
    for (std::size_t m = 0; m < s.members.size(); ++m) {
      if (internal::PartRoot(parent, s.members[m].from) == root)
        part.members.push_back(static_cast<int>(m));
    }
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
      if (internal::PartRoot(parent, s.bodies[b].nodes.front()) == root)
        part.bodies.push_back(static_cast<int>(b));
    }
    return part;
  }
  return std::nullopt;
}

}  // namespace cosmems
