#include "comb_mesh.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

namespace cosmems::viewer {

void AddCombFingers(const CombDrive& comb, const StructureBody& body, CombHalf half,
                    const Eigen::Matrix<double, 6, 1>& motion, const DisplaySpace& space,
                    Mesh& mesh) {
  const Eigen::Vector3d along = comb.Axis(), across = comb.Lateral();
  // The body's face toward `along`, from its centre; a finger as wide as the gap; the moving
  // fingers twice the overlap long, so that the fixed ones' tips stand `overlap` from the face.
  const double face =
      0.5 * (std::abs(along.x()) * body.size.x() + std::abs(along.z()) * body.size.z());
  const double width = comb.gap, pitch = 2.0 * (width + comb.gap), reach = 2.0 * comb.overlap;
  const double half_height = 0.5 * body.size.y();
  const double angle = motion.tail<3>().norm();
  const Eigen::Matrix3d turn =
      half == CombHalf::kMoving && angle > 0.0
          ? Eigen::AngleAxisd(angle, motion.tail<3>() / angle).toRotationMatrix()
          : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d shift =
      half == CombHalf::kMoving ? Eigen::Vector3d(motion.head<3>()) : Eigen::Vector3d::Zero();
  // A block from s0 to s1 along the comb and c0 to c1 across it, about the body's centre.
  auto block = [&](double s0, double s1, double c0, double c1) {
    std::array<Eigen::Vector3d, 8> corner;
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d offset =
          ((i & 1) ? s1 : s0) * along +
          ((i & 2) ? half_height : -half_height) * Eigen::Vector3d::UnitY() +
          ((i & 4) ? c1 : c0) * across;
      corner[i] = space.ToWorld(body.center + shift + turn * offset);
    }
    mesh.AddHexahedron(corner);
  };
  if (half == CombHalf::kMoving) {
    for (int i = 0; i < comb.fingers; ++i) {
      const double c = (i - 0.5 * (comb.fingers - 1)) * pitch;
      block(face, face + reach, c - 0.5 * width, c + 0.5 * width);
    }
    return;
  }
  const double tips = face + reach - comb.overlap, root = tips + reach;
  for (int j = 0; j <= comb.fingers; ++j) {
    const double c = (j - 0.5 * comb.fingers) * pitch;
    block(tips, root, c - 0.5 * width, c + 0.5 * width);
  }
  const double span = 0.5 * comb.fingers * pitch + width;
  block(root, root + 2.0 * width, -span, span);  // the spine on its anchor
}

}  // namespace cosmems::viewer
