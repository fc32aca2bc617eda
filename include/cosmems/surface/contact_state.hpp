#pragma once

namespace cosmems {

/// Where a beam (or one of its nodes) stands with the substrate, in the order it gets there.
enum class ContactState {
  kFree,     ///< farther from the substrate than the proximity distance
  kNear,     ///< within the proximity distance: the warning the user sees before contact
  kContact,  ///< touching, pressed against the substrate
  kStuck,    ///< held by adhesion: stays down until peeled (see SubstrateContact)
};

constexpr const char* ToString(ContactState state) {
  switch (state) {
    case ContactState::kFree:
      return "free";
    case ContactState::kNear:
      return "near";
    case ContactState::kContact:
      return "contact";
    case ContactState::kStuck:
      return "stuck";
  }
  return "unknown";
}

/// Transitions of the whole beam's state, counted at each accepted step: what a caller shows or
/// logs (a warning popup on the first, a "Reset Failure" button on the third).
struct ContactEvents {
  long proximity_warnings = 0;  ///< the beam came within the proximity distance
  long contacts = 0;            ///< the beam touched the substrate
  long stuck = 0;               ///< the beam stuck
  long releases = 0;            ///< a stuck beam came free
};

/// The shape a beam stuck to the substrate holds (Mastrangelo & Hsu; de Boer & Michalske).
enum class StuckShape {
  kFree,  ///< not stuck
  kArc,   ///< stuck by isolated points: a cantilever touching by its tip alone, bent in an arc
  kS,     ///< stuck along a length, lying flat on it: the S shape
};

constexpr const char* ToString(StuckShape shape) {
  switch (shape) {
    case StuckShape::kFree:
      return "free";
    case StuckShape::kArc:
      return "arc";
    case StuckShape::kS:
      return "s";
  }
  return "unknown";
}

/// The shape in words, for people.
constexpr const char* Describe(StuckShape shape) {
  switch (shape) {
    case StuckShape::kFree:
      return "free";
    case StuckShape::kArc:
      return "arc-shaped, touching by its tip";
    case StuckShape::kS:
      return "S-shaped, lying along a length";
  }
  return "unknown";
}

/// The beam against the substrate at the last accepted state, in SI.
struct ContactSummary {
  ContactState state = ContactState::kFree;  ///< the most advanced state of any node
  double contact_length_m = 0.0;   ///< total length lying on the substrate (runs of touching nodes)
  double detached_length_m = 0.0;  ///< free span from the first support to the first touching node
                                   ///< (the whole length when none touches)
  StuckShape shape = StuckShape::kFree;  ///< when stuck: by its tip alone (arc) or along a length
  bool InContact() const { return state >= ContactState::kContact; }
  bool Stuck() const { return state == ContactState::kStuck; }
};

}  // namespace cosmems
