#pragma once

#include <istream>
#include <memory>
#include <string>

#include "cosmems/scripted/trajectory.hpp"

namespace cosmems {

/// Reads a trajectory from a CSV file: a header row whose first four columns are
/// `time_s,x_m,y_m,z_m`, then one row per sample with as many fields as the header. Further
/// columns are ignored, so a run recorded by ScriptedDevice::WriteCsv() replays as a trajectory.
/// Times must increase strictly and every value must be finite; blank lines are skipped.
///
/// The position is interpolated linearly between samples, held at the first sample before it
/// and at the last one after it; Duration() is the last sample's time. Throws
/// std::invalid_argument naming the file, the line and the offending field and value; a path that
/// is not a regular file (a FIFO, a device), a file above 1 GiB or one of more than 1e7 rows is
/// refused the same way.
std::unique_ptr<Trajectory> LoadCsvTrajectory(const std::string& path);

/// The same from a stream, whose errors are named after `name`.
std::unique_ptr<Trajectory> ReadCsvTrajectory(std::istream& in, const std::string& name);

}  // namespace cosmems
