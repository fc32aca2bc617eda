#pragma once

namespace cosmems {

/// A point whose motion a frame's transient records: a description node, a body's centre, or a
/// point along a member (a bridge's midspan).
struct FrameRecordPoint {
  int node = -1;    ///< a description node, or -1
  int body = -1;    ///< a body, when node is -1
  int member = -1;  ///< a member, when node and body are -1
  double at = 0.0;  ///< the point's fraction of the member's length, from its first node
};

}  // namespace cosmems
