#include "mesh.hpp"

#include <cmath>

namespace cosmems::viewer {

void Mesh::AddBox(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  auto corner = [&](int i) {
    return Eigen::Vector3d((i & 1) ? high.x() : low.x(), (i & 2) ? high.y() : low.y(),
                           (i & 4) ? high.z() : low.z());
  };
  // Each face by its four corners (bit 0: x, bit 1: y, bit 2: z).
  AddQuad(corner(0), corner(4), corner(6), corner(2), -Eigen::Vector3d::UnitX());
  AddQuad(corner(1), corner(3), corner(7), corner(5), Eigen::Vector3d::UnitX());
  AddQuad(corner(0), corner(1), corner(5), corner(4), -Eigen::Vector3d::UnitY());
  AddQuad(corner(2), corner(6), corner(7), corner(3), Eigen::Vector3d::UnitY());
  AddQuad(corner(0), corner(2), corner(3), corner(1), -Eigen::Vector3d::UnitZ());
  AddQuad(corner(4), corner(5), corner(7), corner(6), Eigen::Vector3d::UnitZ());
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
