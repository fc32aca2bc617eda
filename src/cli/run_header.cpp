#include "run_header.hpp"

#include "ignored_settings.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

RunHeader RunHeader::Start(const Scene& scene) {
  RunHeader header;
  header.scene = scene.source;
  header.analysis = scene.analysis.type;
  header.model = scene.model;
  header.warnings = IgnoredSettingWarnings(scene);
  return header;
}

void RunHeader::WarnIfThroughSubstrate(const std::string& subject, double distance,
                                       const std::optional<double>& gap) {
  if (!gap || distance < *gap) return;
  warnings.push_back(subject + " " + Scientific(distance) +
                     " m toward the substrate, at least the gap of " + Significant(*gap) +
                     " m: it passes through the substrate (declare [effects.contact] to stop it "
                     "there)");
}

void RunHeader::AddJson(nlohmann::ordered_json& json) const {
  json["scene"] = scene;
  json["analysis"] = ToString(analysis);
  json["status"] = ToString(status);
  json["model"] = {{"theory", ToString(model.theory)},
                   {"dimension", model.dimension},
                   {"elements", model.elements},
                   {"series_order", model.series_order},
                   {"modes", model.modes},
                   {"dofs", dofs}};
  json["wall_time_s"] = wall_time_s;
}

void RunHeader::Print(std::ostream& out) const {
  out << scene << ": " << ToString(analysis) << " analysis, " << ToString(model.theory)
      << " theory\n";
  out << "model      " << model.dimension << "-D, " << model.elements;
  // The rod's elements interpolate linearly; the series order belongs to the beam's.
  if (model.theory == Theory::kCosserat) {
    out << " two-node rod elements";
  } else {
    out << " elements, series order " << model.series_order;
  }
  out << ", " << dofs << " free dofs\n";
  out << "status     " << ToString(status) << "\n";
  out << "wall time  " << Significant(wall_time_s * 1e3, 3) << " ms\n";
}

}  // namespace cosmems::internal
