#include "contact_report.hpp"

#include "text_format.hpp"

namespace cosmems::internal {

nlohmann::ordered_json ContactJson(const ContactSummary& contact, bool lengths) {
  nlohmann::ordered_json json = {
      {"in_contact", contact.InContact()}, {"stuck", contact.Stuck()},
      {"shape", ToString(contact.shape)},  {"contact_length_m", nullptr},
      {"state", ToString(contact.state)},  {"detached_length_m", nullptr}};
  if (lengths) {
    json["contact_length_m"] = contact.contact_length_m;
    json["detached_length_m"] = contact.detached_length_m;
  }
  return json;
}

nlohmann::ordered_json ContactEventsJson(const ContactEvents& events) {
  return {{"proximity_warnings", events.proximity_warnings},
          {"contacts", events.contacts},
          {"stuck_events", events.stuck},
          {"releases", events.releases}};
}

void PrintContact(std::ostream& out, const ContactSummary& contact, bool lengths) {
  out << "substrate             " << ToString(contact.state);
  if (contact.Stuck()) out << " (" << Describe(contact.shape) << ")";
  out << "\n";
  if (!lengths) return;
  out << "contact length        " << Scientific(contact.contact_length_m) << " m\n";
  out << "detached length       " << Scientific(contact.detached_length_m)
      << " m (free span from the first support)\n";
}

}  // namespace cosmems::internal
