#pragma once

#include "cosmems/analysis/fold_search.hpp"
#include "cosmems/surface/gap_integral.hpp"
#include "cosmems/time/newton_options.hpp"

namespace cosmems {

/// A beam's pull-in (SolvePullIn): the electrode, where the travel is held, and how the fold is
/// traced. Apart from the analysis, so that what only describes one (a scene's conversion) does
/// not compile the analysis.
struct PullInOptions {
  GapSpan electrode;  ///< the gap and the electrode's extent [m] along the beam
  bool fringing = false;
  double control_x = 0.0;  ///< m: where the travel is imposed (the tip, or a bridge's midspan)
  FoldOptions fold;
  NewtonOptions newton;
};

}  // namespace cosmems
