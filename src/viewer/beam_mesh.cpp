#include "beam_mesh.hpp"

namespace cosmems::viewer {
namespace {

// The centreline at one sample, in the world: its point and the normal of the upper face there.
struct Section {
  Eigen::Vector3d centre;
  Eigen::Vector3d normal;  // in the x-y plane, the upper face's outward normal
};

Section MakeSection(double x_m, double w_m, double slope, const DisplaySpace& space) {
  const Eigen::Vector3d centre = space.ToWorld(Eigen::Vector3d(x_m, w_m, 0.0));
  const Eigen::Vector3d tangent =
      Eigen::Vector3d(1.0, space.exaggeration * slope, 0.0).normalized();
  return Section{centre, Eigen::Vector3d(-tangent.y(), tangent.x(), 0.0)};
}

}  // namespace

void BuildBeamMesh(const HapticFrame& frame, double width_m, double thickness_m,
                   const DisplaySpace& space, Mesh& mesh, int samples_per_element) {
  mesh.Clear();
  const int nodes = static_cast<int>(frame.node_x_m.size());
  if (nodes < 2) return;
  // The section's half sizes in the world: the thickness stretched like every length along y.
  const double half_t = 0.5e6 * thickness_m * space.exaggeration, half_b = 0.5e6 * width_m;
  const Eigen::Vector3d across = Eigen::Vector3d::UnitZ();
  auto corner = [&](const Section& s, double up, double side) {
    return Eigen::Vector3d(s.centre + up * half_t * s.normal + side * half_b * across);
  };
  Section previous{};
  for (int e = 0; e + 1 < nodes; ++e) {
    const double x0 = frame.node_x_m[e], h = frame.node_x_m[e + 1] - x0;
    const double w0 = frame.deflection_m[e], w1 = frame.deflection_m[e + 1];
    const double r0 = frame.rotation_rad[e], r1 = frame.rotation_rad[e + 1];
    for (int k = e == 0 ? 0 : 1; k <= samples_per_element; ++k) {
      const double xi = static_cast<double>(k) / samples_per_element;
      // Hermite cubics on [0, 1] and their derivatives.
      const double n1 = 1 - 3 * xi * xi + 2 * xi * xi * xi, n2 = xi - 2 * xi * xi + xi * xi * xi;
      const double n3 = 3 * xi * xi - 2 * xi * xi * xi, n4 = -xi * xi + xi * xi * xi;
      const double d1 = -6 * xi + 6 * xi * xi, d2 = 1 - 4 * xi + 3 * xi * xi;
      const double d3 = 6 * xi - 6 * xi * xi, d4 = -2 * xi + 3 * xi * xi;
      const double w = n1 * w0 + n2 * h * r0 + n3 * w1 + n4 * h * r1;
      const double slope = (d1 * w0 + d3 * w1) / h + d2 * r0 + d4 * r1;
      const Section s = MakeSection(x0 + xi * h, w, slope, space);
      if (e == 0 && k == 0) {  // the end face at the first support
        mesh.AddQuad(corner(s, -1, -1), corner(s, 1, -1), corner(s, 1, 1), corner(s, -1, 1),
                     -Eigen::Vector3d::UnitX());
      } else {
        const Section& p = previous;
        mesh.AddQuad(corner(p, 1, -1), corner(s, 1, -1), corner(s, 1, 1), corner(p, 1, 1),
                     0.5 * (p.normal + s.normal).normalized());
        mesh.AddQuad(corner(p, -1, -1), corner(p, -1, 1), corner(s, -1, 1), corner(s, -1, -1),
                     -0.5 * (p.normal + s.normal).normalized());
        mesh.AddQuad(corner(p, -1, 1), corner(p, 1, 1), corner(s, 1, 1), corner(s, -1, 1), across);
        mesh.AddQuad(corner(p, -1, -1), corner(s, -1, -1), corner(s, 1, -1), corner(p, 1, -1),
                     -across);
      }
      previous = s;
    }
  }
  const Section& end = previous;
  const Eigen::Vector3d end_normal(end.normal.y(), -end.normal.x(), 0.0);  // the tangent
  mesh.AddQuad(corner(end, -1, -1), corner(end, -1, 1), corner(end, 1, 1), corner(end, 1, -1),
               end_normal);
}

}  // namespace cosmems::viewer
