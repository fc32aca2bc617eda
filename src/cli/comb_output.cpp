#include "comb_output.hpp"

#include <cmath>

#include "text_format.hpp"

namespace cosmems::internal {

void AddCombStates(const StructureDescription& structure, const std::vector<CombDrive>& combs,
                   const std::vector<CombDriveState>& states, nlohmann::ordered_json& json) {
  if (states.empty()) return;
  nlohmann::ordered_json capacitances = nlohmann::ordered_json::array();
  nlohmann::ordered_json side = nlohmann::ordered_json::array();
  nlohmann::ordered_json entries = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < states.size(); ++c) {
    const CombDriveState& state = states[c];
    capacitances.push_back(state.capacitance_f);
    side.push_back(std::isfinite(state.side_instability_voltage_v)
                       ? nlohmann::ordered_json(state.side_instability_voltage_v)
                       : nlohmann::ordered_json());
    entries.push_back({{"body", structure.bodies[combs[c].body].name},
                       {"force_n", state.force_n},
                       {"engagement_m", state.engagement_m},
                       {"offset_m", state.offset_m}});
  }
  json["capacitance_f"]["combs"] = capacitances;
  json["side_instability_voltage_v"] = side;
  json["combs"] = entries;
}

void PrintCombStates(const StructureDescription& structure, const std::vector<CombDrive>& combs,
                     const std::vector<CombDriveState>& states, std::ostream& out) {
  for (std::size_t c = 0; c < states.size(); ++c) {
    const CombDriveState& state = states[c];
    out << "comb " << c << " on " << structure.bodies[combs[c].body].name << "  force "
        << Scientific(state.force_n) << " N, engaged " << Scientific(state.engagement_m)
        << " m, off centre " << Scientific(state.offset_m) << " m, "
        << Scientific(state.capacitance_f) << " F, side instability at ";
    if (std::isfinite(state.side_instability_voltage_v)) {
      out << Significant(state.side_instability_voltage_v, 4) << " V\n";
    } else {
      out << "no voltage up to 1e6 times the scene's\n";
    }
  }
}

}  // namespace cosmems::internal
