#include "frame_contact_output.hpp"

#include "contact_report.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

FrameContactResults FrameContactResults::Of(const FrameSubstrateContact& contact,
                                            const StructureDescription& structure) {
  FrameContactResults out;
  out.declared = true;
  out.has_lengths = HasContactLengths(structure);
  out.contact = contact.Summary();
  for (std::size_t m = 0; m < structure.members.size(); ++m) {
    out.members.push_back(contact.MemberSummary(static_cast<int>(m)));
  }
  for (std::size_t b = 0; b < structure.bodies.size(); ++b) {
    out.bodies_stuck.push_back(contact.BodyStuck(static_cast<int>(b)));
  }
  return out;
}

void AddFrameContact(const StructureDescription& structure, const FrameContactResults& results,
                     nlohmann::ordered_json& json) {
  json["contact"] = ContactJson(results.contact, results.has_lengths);
  nlohmann::ordered_json members = nlohmann::ordered_json::array();
  for (std::size_t m = 0; m < results.members.size(); ++m) {
    const ContactSummary& member = results.members[m];
    const StructureMember& s = structure.members[m];
    members.push_back({{"nodes", {structure.nodes[s.from].name, structure.nodes[s.to].name}},
                       {"stuck", member.Stuck()},
                       {"shape", ToString(member.shape)},
                       {"detached_length_m", member.detached_length_m},
                       {"contact_length_m", member.contact_length_m}});
  }
  json["members"] = members;
  for (std::size_t b = 0; b < results.bodies_stuck.size(); ++b) {
    json["bodies"][structure.bodies[b].name]["stuck"] = static_cast<bool>(results.bodies_stuck[b]);
  }
}

void PrintFrameContact(const StructureDescription& structure, const FrameContactResults& results,
                       std::ostream& out) {
  PrintContact(out, results.contact, results.has_lengths);
  for (std::size_t m = 0; m < results.members.size(); ++m) {
    const ContactSummary& member = results.members[m];
    if (!member.InContact()) continue;
    const StructureMember& s = structure.members[m];
    out << "member " << structure.nodes[s.from].name << "-" << structure.nodes[s.to].name << "  "
        << Describe(member.shape) << ", detached " << Scientific(member.detached_length_m)
        << " m, on the substrate " << Scientific(member.contact_length_m) << " m\n";
  }
  for (std::size_t b = 0; b < results.bodies_stuck.size(); ++b) {
    out << "body " << structure.bodies[b].name << "  "
        << (results.bodies_stuck[b] ? "stuck" : "free") << "\n";
  }
}

}  // namespace cosmems::internal
