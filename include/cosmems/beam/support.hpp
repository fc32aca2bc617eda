#pragma once

#include <array>

#include "cosmems/beam/frame_layout.hpp"

namespace cosmems {

/// How a node is held.
enum class Support {
  kFree,     ///< nothing fixed
  kClamped,  ///< every displacement and rotation fixed
  kPinned,   ///< translations fixed, bending rotations free; twist fixed (a fork support), so a
             ///< pinned-pinned beam has no rigid rotation about its axis
  kGuided,   ///< a sliding clamp: rotations and the axial displacement fixed, transverse free
};

/// Whether `support` fixes the nodal degree of freedom `dof`.
constexpr bool Fixes(Support support, NodalDof dof) {
  switch (support) {
    case Support::kFree:
      return false;
    case Support::kClamped:
      return true;
    case Support::kPinned:
      return dof == NodalDof::kUx || dof == NodalDof::kUy || dof == NodalDof::kUz ||
             dof == NodalDof::kRx;
    case Support::kGuided:
      return dof == NodalDof::kUx || dof == NodalDof::kRx || dof == NodalDof::kRy ||
             dof == NodalDof::kRz;
  }
  return false;
}

}  // namespace cosmems
