#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "cosmems/surface/contact_state.hpp"

namespace cosmems::internal {

/// The beam against the substrate as every analysis with contact reports it: doc/cli.md's
/// {in_contact, stuck, contact_length_m}, and the extensions shape, state and
/// detached_length_m. Without `lengths` (a device, whose contact has no length along a beam)
/// the two lengths are null.
nlohmann::ordered_json ContactJson(const ContactSummary& contact, bool lengths = true);

/// {proximity_warnings, contacts, stuck_events, releases}.
nlohmann::ordered_json ContactEventsJson(const ContactEvents& events);

/// The summary's lines: state, then (with `lengths`) contact length, detached length.
void PrintContact(std::ostream& out, const ContactSummary& contact, bool lengths = true);

}  // namespace cosmems::internal
