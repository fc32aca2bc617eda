#include "mesh.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace cosmems::viewer {

void Mesh::AddHexahedron(const std::array<Eigen::Vector3d, 8>& corner) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& c : corner) centre += c / 8.0;
  // Each face by its four corners in order round its edge.
  constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : kFaces) {
    const Eigen::Vector3d &a = corner[f[0]], &b = corner[f[1]], &c = corner[f[2]],
                          &d = corner[f[3]];
    Eigen::Vector3d normal = (c - a).cross(d - b).normalized();
    if (normal.dot(a + b + c + d - 4.0 * centre) < 0.0) normal = -normal;
    AddQuad(a, b, c, d, normal);
  }
}

void Mesh::AddBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  std::array<Eigen::Vector3d, 8> corner;
  for (int i = 0; i < 8; ++i) {
    corner[i] = Eigen::Vector3d((i & 1) ? high.x() : low.x(), (i & 2) ? high.y() : low.y(),
                                (i & 4) ? high.z() : low.z());
  }
  AddHexahedron(corner);
}

void Mesh::AddEllipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii) {
  constexpr int kRings = 12, kSegments = 20;
  auto unit = [](int ring, int segment) {
    const double polar = M_PI * ring / kRings, azimuth = 2.0 * M_PI * segment / kSegments;
    return Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                           std::sin(polar) * std::sin(azimuth));
  };
  // The normal of an ellipsoid at the point radii * u is u / radii, normalised.
  auto add = [&](const Eigen::Vector3d& u) {
    AddVertex(centre + radii.cwiseProduct(u), u.cwiseQuotient(radii).normalized());
  };
  for (int ring = 0; ring < kRings; ++ring) {
    for (int segment = 0; segment < kSegments; ++segment) {
      const Eigen::Vector3d a = unit(ring, segment), b = unit(ring + 1, segment),
                            c = unit(ring + 1, segment + 1), d = unit(ring, segment + 1);
      for (const Eigen::Vector3d* u : {&a, &d, &c, &a, &c, &b}) add(*u);
    }
  }
}

}  // namespace cosmems::viewer
