#pragma once

#include <algorithm>
#include <utility>
#include <vector>

namespace cosmems {

namespace internal {

// Breadth-first levels from `start` over the unvisited vertices; returns the visit order.
inline std::vector<int> BreadthFirst(const std::vector<std::vector<int>>& adjacency, int start,
                                     const std::vector<char>& done, std::vector<int>& level) {
  std::vector<int> order = {start};
  std::fill(level.begin(), level.end(), -1);
  level[start] = 0;
  for (std::size_t head = 0; head < order.size(); ++head) {
    const int v = order[head];
    for (int w : adjacency[v]) {
      if (done[w] || level[w] >= 0) continue;
      level[w] = level[v] + 1;
      order.push_back(w);
    }
  }
  return order;
}

}  // namespace internal

/// An ordering of a graph's vertices (order[k] = the vertex numbered k) that keeps neighbours'
/// numbers close, so a matrix numbered by it has a narrow band: Cuthill-McKee from a
/// pseudo-peripheral vertex of each connected component (George and Liu's search: the
/// farthest vertex of least degree, until the depth stops growing), reversed.
inline std::vector<int> ReverseCuthillMcKee(const std::vector<std::vector<int>>& adjacency) {
  const int n = static_cast<int>(adjacency.size());
  auto degree = [&](int v) { return static_cast<int>(adjacency[v].size()); };
  std::vector<char> done(n, 0);
  std::vector<int> level(n, -1), order;
  order.reserve(n);
  for (int seed = 0; seed < n; ++seed) {
    if (done[seed]) continue;
    int start = seed;
    std::vector<int> reach = internal::BreadthFirst(adjacency, start, done, level);
    int depth = level[reach.back()];
    for (;;) {
      int far = reach.back();
      for (int v : reach) {
        if (level[v] == depth && degree(v) < degree(far)) far = v;
      }
      std::vector<int> next = internal::BreadthFirst(adjacency, far, done, level);
      const int next_depth = level[next.back()];
      if (next_depth <= depth) break;
      start = far;
      reach = std::move(next);
      depth = next_depth;
    }
    // Cuthill-McKee: visit breadth first, each vertex's new neighbours by increasing degree.
    const std::size_t first = order.size();
    order.push_back(start);
    done[start] = 1;
    for (std::size_t head = first; head < order.size(); ++head) {
      std::vector<int> next;
      for (int w : adjacency[order[head]]) {
        if (!done[w]) {
          done[w] = 1;
          next.push_back(w);
        }
      }
      std::sort(next.begin(), next.end(), [&](int a, int b) {
        return degree(a) != degree(b) ? degree(a) < degree(b) : a < b;
      });
      order.insert(order.end(), next.begin(), next.end());
    }
  }
  std::reverse(order.begin(), order.end());
  return order;
}

}  // namespace cosmems
