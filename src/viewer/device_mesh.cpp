#include "device_mesh.hpp"

#include <Eigen/Geometry>
#include <array>

namespace cosmems::viewer {
namespace {

// The rotation by the vector `theta` (its length the angle).
Eigen::Matrix3d Turn(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix();
}

// A section of an element at one sample: its centre and its turned thickness and width
// directions, in metres and global axes.
struct Section {
  Eigen::Vector3d centre;
  Eigen::Vector3d up;      // half the thickness along the turned local y
  Eigen::Vector3d across;  // half the width along the turned local z
};

Section SectionAt(const FrameMesh::Element& element, const Eigen::Matrix<double, 6, 1>& from,
                  const Eigen::Matrix<double, 6, 1>& to, const Eigen::Vector3d& start,
                  const RectangularSection& section, double xi) {
  const Eigen::Matrix3d& a = element.axes;  // rows: local x, y, z
  const double h = element.length;
  const Eigen::Vector3d u0 = a * from.head<3>(), u1 = a * to.head<3>();
  const Eigen::Vector3d t0 = a * from.tail<3>(), t1 = a * to.tail<3>();
  // Hermite cubics on [0, 1] and their derivatives per unit xi.
  const double x2 = xi * xi, x3 = x2 * xi;
  const double n1 = 1 - 3 * x2 + 2 * x3, n2 = xi - 2 * x2 + x3, n3 = 3 * x2 - 2 * x3, n4 = x3 - x2;
  const double d1 = 6 * x2 - 6 * xi, d2 = 1 - 4 * xi + 3 * x2, d3 = -d1, d4 = 3 * x2 - 2 * xi;
  // v along local y turns by theta_z (v' = theta_z), w along local z by theta_y (w' = -theta_y).
  const double v = n1 * u0.y() + n2 * h * t0.z() + n3 * u1.y() + n4 * h * t1.z();
  const double w = n1 * u0.z() - n2 * h * t0.y() + n3 * u1.z() - n4 * h * t1.y();
  const double dv = (d1 * u0.y() + d3 * u1.y()) / h + d2 * t0.z() + d4 * t1.z();
  const double dw = (d1 * u0.z() + d3 * u1.z()) / h - d2 * t0.y() - d4 * t1.y();
  const Eigen::Vector3d local((1 - xi) * u0.x() + xi * u1.x(), v, w);
  const Eigen::Vector3d turn((1 - xi) * t0.x() + xi * t1.x(), -dw, dv);
  const Eigen::Matrix3d r = Turn(a.transpose() * turn);
  return {start + xi * h * a.row(0).transpose() + a.transpose() * local,
          r * (0.5 * section.thickness * a.row(1).transpose()),
          r * (0.5 * section.width * a.row(2).transpose())};
}

// The block between two sections, in the world.
void AddSegment(const Section& p, const Section& s, const DisplaySpace& space, Mesh& mesh) {
  std::array<Eigen::Vector3d, 8> corner;
  for (int i = 0; i < 8; ++i) {
    const Section& at = (i & 1) ? s : p;
    const double up = (i & 2) ? 1.0 : -1.0, side = (i & 4) ? 1.0 : -1.0;
    corner[i] = space.ToWorld(at.centre + up * at.up + side * at.across);
  }
  mesh.AddHexahedron(corner);
}

}  // namespace

Eigen::Matrix<double, 6, 1> NodeMotion(const HapticFrame& frame, const FrameMesh& mesh, int node) {
  const FrameMesh::Node& n = mesh.nodes[node];
  Eigen::Matrix<double, 6, 1> q = frame.carrier_motion_m.col(n.carrier);
  q.head<3>() += q.tail<3>().cross(n.offset);
  return q;
}

Eigen::Vector3d ElementPointMotion(const HapticFrame& frame, const FrameMesh& mesh, int element,
                                   double xi) {
  const FrameMesh::Element& e = mesh.elements[element];
  const Eigen::Vector3d& start = mesh.nodes[e.from].position;
  const Section at = SectionAt(e, NodeMotion(frame, mesh, e.from), NodeMotion(frame, mesh, e.to),
                               start, RectangularSection{}, xi);
  return at.centre - (start + xi * e.length * e.axes.row(0).transpose());
}

void BuildDeviceMesh(const HapticFrame& frame, const FrameMesh& mesh,
                     const StructureDescription& structure, const DisplaySpace& space,
                     Mesh& members, Mesh& bodies, int samples_per_element) {
  members.Clear();
  bodies.Clear();
  if (frame.carrier_motion_m.cols() != static_cast<Eigen::Index>(mesh.carriers.size())) return;
  for (const FrameMesh::Element& element : mesh.elements) {
    const Eigen::Matrix<double, 6, 1> from = NodeMotion(frame, mesh, element.from);
    const Eigen::Matrix<double, 6, 1> to = NodeMotion(frame, mesh, element.to);
    const Eigen::Vector3d& start = mesh.nodes[element.from].position;
    const RectangularSection& section = structure.members[element.member].section;
    Section previous = SectionAt(element, from, to, start, section, 0.0);
    for (int k = 1; k <= samples_per_element; ++k) {
      const Section next = SectionAt(element, from, to, start, section,
                                     static_cast<double>(k) / samples_per_element);
      AddSegment(previous, next, space, members);
      previous = next;
    }
  }
  for (std::size_t b = 0; b < structure.bodies.size(); ++b) {
    const StructureBody& body = structure.bodies[b];
    const Eigen::Matrix<double, 6, 1> q = frame.carrier_motion_m.col(mesh.body_carrier[b]);
    const Eigen::Matrix3d r = Turn(q.tail<3>());
    std::array<Eigen::Vector3d, 8> corner;
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d half(((i & 1) ? 0.5 : -0.5) * body.size.x(),
                                 ((i & 2) ? 0.5 : -0.5) * body.size.y(),
                                 ((i & 4) ? 0.5 : -0.5) * body.size.z());
      corner[i] = space.ToWorld(body.center + q.head<3>() + r * half);
    }
    bodies.AddHexahedron(corner);
  }
}

}  // namespace cosmems::viewer
