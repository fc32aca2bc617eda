#include "run_header.hpp"

#include "text_format.hpp"

namespace cosmems::internal {

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
  out << "model      " << model.dimension << "-D, " << model.elements << " elements, series order "
      << model.series_order << ", " << dofs << " free dofs\n";
  out << "status     " << ToString(status) << "\n";
  out << "wall time  " << Significant(wall_time_s * 1e3, 3) << " ms\n";
}

}  // namespace cosmems::internal
