#pragma once

#include "cosmems/analysis/fold_search.hpp"
#include "cosmems/surface/frame_faces.hpp"
#include "cosmems/time/newton_options.hpp"

namespace cosmems {

/// A device over parallel-plate electrodes: where they lie, and how the fold is traced.
struct FramePullInOptions {
  FrameGapOptions electrodes;
  bool fringing = false;
  FoldOptions fold;
  NewtonOptions newton;
};

}  // namespace cosmems
