#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems::internal {

/// A device's comb drives at a solved state, as every analysis that solves them reports them:
/// `capacitance_f.combs`, `side_instability_voltage_v` (null where no factor up to 1e6 reaches
/// it) and `combs` [{body, force_n, engagement_m, offset_m}]. Nothing when `states` is empty.
void AddCombStates(const StructureDescription& structure, const std::vector<CombDrive>& combs,
                   const std::vector<CombDriveState>& states, nlohmann::ordered_json& json);
/// The same as text, one line per comb.
void PrintCombStates(const StructureDescription& structure, const std::vector<CombDrive>& combs,
                     const std::vector<CombDriveState>& states, std::ostream& out);

}  // namespace cosmems::internal
