#pragma once

#include <Eigen/Core>
#include <ostream>
#include <string>
#include <vector>

namespace cosmems {

/// One recorded servo tick of a ScriptedDevice, device frame, SI.
struct ScriptedSample {
  double time_s = 0.0;  ///< tick / rate
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_n = Eigen::Vector3d::Zero();  ///< what the safety layer let through
};

/// Writes samples as CSV with the header `time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n` (velocities left
/// out), with enough digits to read back every double exactly, so a recording replays as a CSV
/// trajectory. Throws std::runtime_error naming the file when it cannot be written.
void WriteSamplesCsv(const std::string& path, const std::vector<ScriptedSample>& samples);
/// The same CSV text on `out`, for a caller that writes the file its own way (whole or not at
/// all).
void WriteSamplesCsv(std::ostream& out, const std::vector<ScriptedSample>& samples);

}  // namespace cosmems
