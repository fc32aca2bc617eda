#include "analysis_runner.hpp"

#include <stdexcept>
#include <string>

#include "buckling_report.hpp"
#include "haptic_report.hpp"
#include "modal_report.hpp"
#include "pullin_report.hpp"
#include "release_report.hpp"
#include "static_report.hpp"
#include "transient_report.hpp"

namespace cosmems::internal {

std::unique_ptr<AnalysisReport> RunAnalysis(const Scene& scene) {
  switch (scene.analysis.type) {
    case AnalysisType::kStatic:
      return StaticReport::Run(scene);
    case AnalysisType::kModal:
      return ModalReport::Run(scene);
    case AnalysisType::kTransient:
      return TransientReport::Run(scene);
    case AnalysisType::kBuckling:
      return BucklingReport::Run(scene);
    case AnalysisType::kPullin:
      return PullInReport::Run(scene);
    case AnalysisType::kRelease:
      return ReleaseReport::Run(scene);
    case AnalysisType::kHaptic:
      return HapticReport::Run(scene);
  }
  throw std::logic_error(std::string("analysis.type = \"") + ToString(scene.analysis.type) +
                         "\" passed validation but has no runner");
}

}  // namespace cosmems::internal
