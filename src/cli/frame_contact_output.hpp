#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "cosmems/structure/structure_description.hpp"
#include "cosmems/surface/contact_state.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"

namespace cosmems::internal {

/// A device against the substrate as its static and release reports show it (doc/cli.md): the
/// device's contact, each member's as a beam's, and whether each body's plate is stuck.
/// Whether a structure's contact has a contact and a detached length: one member (a beam, or a
/// netlist of one member); a device's are null. Every report with contact asks this.
inline bool HasContactLengths(const StructureDescription& structure) {
  return structure.members.size() == 1;
}

struct FrameContactResults {
  bool declared = false;     ///< the scene has contact or stiction
  bool has_lengths = false;  ///< `contact` has lengths (HasContactLengths)
  ContactSummary contact;
  std::vector<ContactSummary> members;
  std::vector<bool> bodies_stuck;

  /// The contact's state at its last committed (converged) step; a structure of one member
  /// has that member's contact and detached lengths, as a beam.
  static FrameContactResults Of(const FrameSubstrateContact& contact,
                                const StructureDescription& structure);
};

/// contact (its lengths null unless has_lengths), members [{nodes, stuck, shape,
/// detached_length_m, contact_length_m}], and `stuck` in each entry of json["bodies"], which must
/// be there.
void AddFrameContact(const StructureDescription& structure, const FrameContactResults& results,
                     nlohmann::ordered_json& json);

/// The device's contact, then a line for each member in contact and each body.
void PrintFrameContact(const StructureDescription& structure, const FrameContactResults& results,
                       std::ostream& out);

}  // namespace cosmems::internal
