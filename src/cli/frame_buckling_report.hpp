#pragma once

#include <memory>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// A device's linear buckling under its loads (doc/cli.md, buckling, devices).
class FrameBucklingReport final : public AnalysisReport {
 public:
  FrameBucklingReport(RunHeader header, double load_factor, double critical_load_n,
                      std::vector<std::string> names, Eigen::MatrixXd shape)
      : AnalysisReport(std::move(header)),
        load_factor_(load_factor),
        critical_load_n_(critical_load_n),
        names_(std::move(names)),
        shape_(std::move(shape)) {}

  static std::unique_ptr<FrameBucklingReport> Run(const Scene& scene);

  /// buckling_mode.csv: name, ux ... rz at every node and body (FrameShape).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  double load_factor_;
  double critical_load_n_;
  std::vector<std::string> names_;  ///< the nodes', then the bodies'
  Eigen::MatrixXd shape_;
};

}  // namespace cosmems::internal
