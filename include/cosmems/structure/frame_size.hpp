#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "cosmems/structure/reverse_cuthill_mckee.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The size of the FrameModel a description makes, counted from the description, so that a
/// model too large for memory is refused before it is built.
struct FrameSize {
  std::int64_t elements = 0;   ///< every member's elements
  std::int64_t unknowns = 0;   ///< free dofs: six per free node and body, less the anchored ones
  std::int64_t bandwidth = 0;  ///< of K and the mass terms: at least FrameModel's
};

/// Every member's elements, summed without overflow: the count the other sizes grow with, cheap
/// to check before FrameSizeOf spends memory in proportion to it.
inline std::int64_t FrameElementCount(const StructureDescription& s) {
  std::int64_t elements = 0;
  for (const StructureMember& m : s.members) elements += m.elements;
  return elements;
}

/// The size of a valid description's (Validate) model. Its carriers of motion (bodies, free nodes,
/// members' interior nodes) are ordered as FrameModel orders them (ReverseCuthillMcKee over the
/// elements' connections); two carriers k places apart in that order hold dofs at most
/// 6 (k + 1) - 1 apart, the bound when one group holds all six directions (a member that
/// stretches); FrameModel's groups of three make it about half that in a planar linear device.
/// It allocates in proportion to the element count: bound FrameElementCount first.
inline FrameSize FrameSizeOf(const StructureDescription& s) {
  FrameSize size;
  size.elements = FrameElementCount(s);
  const std::vector<int> body_of = s.BodyOfNode();
  std::vector<int> carrier(s.nodes.size());
  int carriers = static_cast<int>(s.bodies.size());
  std::int64_t anchored = 0;
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    carrier[n] = body_of[n] >= 0 ? body_of[n] : carriers++;
    anchored += std::count(s.nodes[n].anchor.begin(), s.nodes[n].anchor.end(), true);
  }
  int next = carriers;  // the members' interior nodes, member by member
  for (const StructureMember& m : s.members) carriers += m.elements - 1;
  std::vector<std::vector<int>> adjacency(carriers);
  auto connect = [&](int a, int b) {
    if (a == b) return;
    adjacency[a].push_back(b);
    adjacency[b].push_back(a);
  };
  for (const StructureMember& m : s.members) {
    int previous = carrier[m.from];
    for (int k = 1; k < m.elements; ++k) {
      connect(previous, next);
      previous = next++;
    }
    connect(previous, carrier[m.to]);
  }
  for (std::vector<int>& list : adjacency) {  // as FrameModel lists them: degrees steer the order
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  const std::vector<int> order = ReverseCuthillMcKee(adjacency);
  std::vector<int> place(carriers);
  for (int k = 0; k < carriers; ++k) place[order[k]] = k;
  std::int64_t apart = 0;
  for (int a = 0; a < carriers; ++a) {
    for (int b : adjacency[a]) apart = std::max<std::int64_t>(apart, std::abs(place[a] - place[b]));
  }
  size.unknowns = 6 * std::int64_t{carriers} - anchored;
  size.bandwidth = std::min(6 * (apart + 1) - 1, std::max<std::int64_t>(size.unknowns - 1, 0));
  return size;
}

}  // namespace cosmems
