#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cosmems/core/status.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// What every result reports whatever the analysis (doc/cli.md, "JSON results"), plus the
/// warnings the run raised.
struct RunHeader {
  std::string scene;  ///< the scene name or path as given
  AnalysisType analysis = AnalysisType::kStatic;
  Status status = Status::kOk;
  SceneModel model;
  int dofs = 0;              ///< free degrees of freedom of the model
  double wall_time_s = 0.0;  ///< model build and solve
  std::vector<std::string> warnings;

  /// The header of a run of `scene`: its name, analysis and model, and the warnings for
  /// settings its analysis does not use (IgnoredSettingWarnings).
  static RunHeader Start(const Scene& scene);

  /// Warns that a linear result reaches the substrate: `subject` ("the tip moves", say) went
  /// `distance` m toward it, at least the `gap`: a scene without contact lets it pass.
  void WarnIfThroughSubstrate(const std::string& subject, double distance,
                              const std::optional<double>& gap);

  /// scene, analysis, status, model {theory, dimension, elements, series_order, modes, dofs},
  /// wall_time_s.
  void AddJson(nlohmann::ordered_json& json) const;
  /// The opening lines of the readable summary.
  void Print(std::ostream& out) const;
};

}  // namespace cosmems::internal
