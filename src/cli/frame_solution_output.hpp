#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems::internal {

// A device's static state as every report of one shows it (doc/cli.md, static, frames): the
// motions of its nodes and bodies, the reactions at its anchors and the members' largest
// deflection, stress and axial force.

/// {displacement, rotation} of a node or a body's centre.
nlohmann::ordered_json MotionJson(const FrameModel::Motion& m);

/// max_deflection, max_stress_pa, axial_force_n, nodes, bodies, reactions.
void AddFrameSolution(const StructureDescription& structure, const FrameStaticSolution& solution,
                      nlohmann::ordered_json& json);

/// nodes, bodies, reactions.
void AddFrameMotions(const StructureDescription& structure, const FrameStaticSolution& solution,
                     nlohmann::ordered_json& json);

/// The same as text, one line each.
void PrintFrameSolution(const StructureDescription& structure, const FrameStaticSolution& solution,
                        std::ostream& out);

/// A line for each node, body and reaction.
void PrintFrameMotions(const StructureDescription& structure, const FrameStaticSolution& solution,
                       std::ostream& out);

/// reactions.csv: node, fx_n, fy_n, fz_n, mx_nm, my_nm, mz_nm at every anchored node.
void WriteFrameReactions(const StructureDescription& structure,
                         const std::vector<FrameReaction>& anchors,
                         const std::filesystem::path& directory);

}  // namespace cosmems::internal
