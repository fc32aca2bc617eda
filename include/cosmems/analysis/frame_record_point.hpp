#pragma once

namespace cosmems {

/// A point whose motion a frame's transient records: a description node, or a body's centre.
struct FrameRecordPoint {
  int node = -1;  ///< a description node, or -1
  int body = -1;  ///< a body, when node is -1
};

}  // namespace cosmems
