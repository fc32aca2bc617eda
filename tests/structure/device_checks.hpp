#pragma once

// Checks shared by the parametric devices' tests: a body's static motion by the frame model and
// by the oracle (frame_oracle.hpp), the modes against the oracle's, and the key a generator's
// error names.

#include <gtest/gtest.h>

#include <string>

#include "test_frames.hpp"

namespace cosmems::test {

using BodyMotion = Eigen::Matrix<double, 6, 1>;

/// The displacement and rotation of body `body`'s centre under `force` and `moment` there.
inline BodyMotion SolveBodyMotion(const StructureDescription& s, int body,
                                  const Eigen::Vector3d& force,
                                  const Eigen::Vector3d& moment = Eigen::Vector3d::Zero()) {
  FrameLoadCase loads;
  loads.points.push_back({-1, body, force, moment});
  const FrameStaticSolution solution = SolveFrameStatic(FrameModel(s), loads);
  EXPECT_EQ(solution.status, Status::kOk);
  return solution.bodies.at(body);
}

/// The same by the oracle.
inline BodyMotion OracleBodyMotion(const StructureDescription& s, int body,
                                   const Eigen::Vector3d& force,
                                   const Eigen::Vector3d& moment = Eigen::Vector3d::Zero()) {
  const int at = static_cast<int>(s.nodes.size()) + body;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * static_cast<int>(s.nodes.size() + s.bodies.size()));
  f.segment<3>(6 * at) = force;
  f.segment<3>(6 * at + 3) = moment;
  return oracle::SolveStatic(ToOracle(s), f).segment<6>(6 * at);
}

/// The lowest `count` modes at series order 0 against the oracle's on the same mesh: the same
/// matrices, so the eigensolvers' round-off (1e-12 unless `tolerance` says otherwise).
inline void ExpectModesMatchOracle(StructureDescription s, int count, double tolerance = 1e-12) {
  s.series_order = 0;
  ModalOptions options;
  options.count = count;
  const FrameModalResult modes = SolveFrameModal(FrameModel(s), options);
  ASSERT_EQ(modes.modal.status, Status::kOk);
  const Eigen::VectorXd expected = oracle::Frequencies(ToOracle(s), count);
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(modes.modal.modes.at(i).frequency_hz, expected[i], tolerance * expected[i])
        << "mode " << i;
  }
}

/// The mode moving the most mass along direction `k` (0 ... 5: ux ... rz).
inline std::size_t ModeAlong(const FrameModalResult& modes, int k) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < modes.participation.size(); ++i) {
    if (modes.participation[i][k] > modes.participation[best][k]) best = i;
  }
  return best;
}

/// The key a generator's error names, or "built" when it builds.
template <class Design>
std::string ErrorField(StructureDescription (*generator)(const Design&), const Design& design) {
  try {
    generator(design);
  } catch (const FieldError& error) {
    return error.field();
  }
  return "built";
}

}  // namespace cosmems::test
