#pragma once

#include "cosmems/analysis/comb_drive.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "display_space.hpp"
#include "mesh.hpp"

namespace cosmems::viewer {

/// Which half of a comb drive.
enum class CombHalf {
  kMoving,  ///< the body's fingers, moving with it
  kFixed,   ///< the anchored fingers and the spine that holds them
};

/// The fingers of one half of `comb` beside `body`, on its face toward the comb's direction (the
/// way the comb pulls), added to `mesh` in `space`. Drawn to the comb's numbers across (each
/// finger as wide as the gap, `fingers` moving ones between `fingers` + 1 fixed ones, `gap`
/// apart) and engaged over `overlap` at rest; the moving half is moved by `motion` (u [m], theta
/// [rad] about the body's centre), the fixed half stays.
void AddCombFingers(const CombDrive& comb, const StructureBody& body, CombHalf half,
                    const Eigen::Matrix<double, 6, 1>& motion, const DisplaySpace& space,
                    Mesh& mesh);

}  // namespace cosmems::viewer
