#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace cosmems::viewer {

/// Triangles with a normal per vertex, ready for one vertex buffer: x y z nx ny nz per vertex,
/// three vertices a triangle, world coordinates.
struct Mesh {
  std::vector<float> vertices;

  int VertexCount() const { return static_cast<int>(vertices.size() / 6); }
  void Clear() { vertices.clear(); }

  void AddVertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    vertices.insert(vertices.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                     static_cast<float>(p.z()), static_cast<float>(n.x()),
                                     static_cast<float>(n.y()), static_cast<float>(n.z())});
  }
  /// The quad a, b, c, d (in order round its edge), flat-shaded with the normal `n`. Faces are
  /// drawn from both sides, so the winding does not matter.
  void AddQuad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
               const Eigen::Vector3d& d, const Eigen::Vector3d& n) {
    for (const Eigen::Vector3d* p : {&a, &b, &c, &a, &c, &d}) AddVertex(*p, n);
  }
  /// A hexahedron by its eight corners, corner i at the x end (i & 1), the y end (i & 2) and the
  /// z end (i & 4) of its own edges; each face flat-shaded with its normal turned outward.
  void AddHexahedron(const std::array<Eigen::Vector3d, 8>& corner);
  /// An axis-aligned box from `low` to `high`.
  void AddBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high);
  /// An ellipsoid with semi-axes `radii` about `centre`, smooth-shaded.
  void AddEllipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii);
};

}  // namespace cosmems::viewer
