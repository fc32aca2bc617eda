#pragma once

#include <string>
#include <vector>

#include "cosmems/scene/scene.hpp"

namespace cosmems {

/// One design key of a parametric device (structure.KEY), with its value in the scene: what a
/// front end lists for the user to edit and hands back as a `--set` override.
struct DesignParameter {
  std::string key;  ///< the key under [structure], e.g. "beam_length"
  double value = 0.0;
  bool integer = false;  ///< a count (serpentine's turns); else a length [m]
  std::string meaning;   ///< the key reference's words for it
};

/// The design keys `scene.structure.kind` reads, in the key reference's order, with the values
/// the scene holds; empty for a beam and a netlist.
std::vector<DesignParameter> DesignParameters(const Scene& scene);

}  // namespace cosmems
