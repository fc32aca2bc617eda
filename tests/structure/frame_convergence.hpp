#pragma once

// The frames whose frequencies the mesh-convergence test and the accuracy report follow with
// the element count and the series order: the exact frequencies of each (its members'
// transcendental dynamic stiffness, exact_frame_frequencies.hpp) against the frame model's.

#include <string>
#include <vector>

#include "exact_frame_frequencies.hpp"
#include "test_frames.hpp"

namespace cosmems::test {

/// A frame of the convergence study, `elements` per member at series `order`.
struct ConvergenceFrame {
  std::string name;
  StructureDescription (*build)(int elements, int order);
};

/// An L out of the substrate plane's axes: a clamped member along x, a wider one along z to a
/// free tip, so that bending out of the plane twists the first member at the junction.
inline StructureDescription LJunction(int elements, int order) {
  StructureDescription s;
  s.series_order = order;
  const int anchor = AddNode(s, "anchor", {0, 0, 0}, Support::kClamped);
  const int corner = AddNode(s, "corner", {100e-6, 0, 0});
  const int tip = AddNode(s, "tip", {100e-6, 0, 60e-6});
  AddBeam(s, anchor, corner, elements, RectangularSection{4e-6, 2e-6});
  AddBeam(s, corner, tip, elements, RectangularSection{3e-6, 2e-6});
  return s;
}

/// A plate on two legs of unequal length (100 and 80 um) clamped at their anchors: junctions on
/// a rigid body.
inline StructureDescription PlateOnTwoLegs(int elements, int order) {
  StructureDescription s;
  s.series_order = order;
  const int a = AddNode(s, "anchor_a", {0, 0, 0}, Support::kClamped);
  const int b = AddNode(s, "anchor_b", {20e-6, 0, 80e-6}, Support::kClamped);
  const int ja = AddNode(s, "joint_a", {100e-6, 0, 0});
  const int jb = AddNode(s, "joint_b", {100e-6, 0, 80e-6});
  AddBeam(s, a, ja, elements, RectangularSection{3e-6, 2e-6});
  AddBeam(s, b, jb, elements, RectangularSection{3e-6, 2e-6});
  AddBody(s, "plate", {120e-6, 0, 40e-6}, {40e-6, 2e-6, 100e-6}, {ja, jb});
  return s;
}

inline std::vector<ConvergenceFrame> ConvergenceFrames() {
  return {{"L junction", &LJunction}, {"plate on two legs", &PlateOnTwoLegs}};
}

/// The `count` lowest frequencies of `frame` by the model at `elements` and `order`.
inline std::vector<double> ModelFrequencies(const ConvergenceFrame& frame, int elements, int order,
                                            int count) {
  ModalOptions options;
  options.count = count;
  const FrameModalResult result =
      SolveFrameModal(FrameModel(frame.build(elements, order)), options);
  std::vector<double> hz;
  for (const Mode& mode : result.modal.modes) hz.push_back(mode.frequency_hz);
  return hz;
}

/// The exact frequencies next to the model's at series order 2 on 16 elements per member
/// (within about 1e-12 of them: see frame_convergence_test.cpp).
inline std::vector<double> ExactFrequencies(const ConvergenceFrame& frame, int count) {
  const oracle::Frame exact = ToOracle(frame.build(1, 0));
  std::vector<double> hz;
  for (double guess : ModelFrequencies(frame, 16, 2, count)) {
    hz.push_back(oracle::ExactFrequency(exact, guess));
  }
  return hz;
}

}  // namespace cosmems::test
