#pragma once

// A rigid square plate, 100 um wide and centred at the origin, on four 2 x 2 um beams leaving its
// corners along x to clamped anchors: the device the surface forces on structures are checked
// on. The plate translates without turning, so each beam is clamped-guided and the four together
// are the spring k = 4 x 12 E I / L^3 (the frame is exact for it to 1e-10, frame_model_test.cpp).

#include <cmath>
#include <string>
#include <vector>

#include "structure/test_frames.hpp"

namespace cosmems::test {

struct PlateOnFourBeams {
  StructureDescription structure;
  double k = 0.0;                                     ///< N/m
  double side = 100e-6;                               ///< m
  double area = side * side;                          ///< m^2
  Electrode plate{{-50e-6, 50e-6}, {-50e-6, 50e-6}};  ///< the plate's footprint

  /// Beams `beam_length` long, the plate `plate_thickness` thick (its lower face lies
  /// (plate_thickness - 2 um) / 2 below the beams'), the beams' density that of polysilicon
  /// times `beam_density` (a light suspension leaves the plate's mass alone in the oscillator).
  explicit PlateOnFourBeams(double beam_length = 100e-6, double plate_thickness = 2e-6,
                            double beam_density = 1.0) {
    Material beam = Poly();
    beam.density *= beam_density;
    std::vector<int> corners;
    for (int side_index = 0; side_index < 4; ++side_index) {
      const double x = side_index % 2 ? 50e-6 : -50e-6, z = side_index / 2 ? 50e-6 : -50e-6;
      const std::string name = std::to_string(side_index);
      const int corner = AddNode(structure, "corner" + name, {x, 0.0, z});
      const int anchor = AddNode(structure, "anchor" + name,
                                 {x + (x > 0 ? 1 : -1) * beam_length, 0.0, z}, Support::kClamped);
      structure.members.push_back(
          {anchor, corner, beam, SquareSection(), 4, Eigen::Vector3d::UnitY()});
      corners.push_back(corner);
    }
    AddBody(structure, "plate", Eigen::Vector3d::Zero(), {side, plate_thickness, side}, corners);
    const double i = 2e-6 * std::pow(2e-6, 3) / 12.0;
    k = 4.0 * 12.0 * Poly().young_modulus * i / std::pow(beam_length, 3);
  }

  /// The plate's mass [kg].
  double Mass() const { return Poly().density * area * structure.bodies[0].size.y(); }
};

}  // namespace cosmems::test
