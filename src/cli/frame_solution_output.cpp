#include "frame_solution_output.hpp"

#include "csv_file.hpp"
#include "json_vector.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

nlohmann::ordered_json MotionJson(const FrameModel::Motion& m) {
  return {{"displacement", ToJson(m.head<3>())}, {"rotation", ToJson(m.tail<3>())}};
}

void AddFrameSolution(const StructureDescription& structure, const FrameStaticSolution& solution,
                      nlohmann::ordered_json& json) {
  json["max_deflection"] = solution.max_deflection;
  json["max_stress_pa"] = solution.max_stress_pa;
  json["axial_force_n"] = solution.axial_force_n;
  AddFrameMotions(structure, solution, json);
}

void AddFrameMotions(const StructureDescription& structure, const FrameStaticSolution& solution,
                     nlohmann::ordered_json& json) {
  nlohmann::ordered_json nodes = nlohmann::ordered_json::object();
  for (std::size_t n = 0; n < structure.nodes.size(); ++n) {
    nodes[structure.nodes[n].name] = MotionJson(solution.nodes[n]);
  }
  nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
  for (std::size_t b = 0; b < structure.bodies.size(); ++b) {
    bodies[structure.bodies[b].name] = MotionJson(solution.bodies[b]);
  }
  nlohmann::ordered_json reactions = nlohmann::ordered_json::object();
  for (const FrameReaction& r : solution.reactions) {
    reactions[structure.nodes[r.node].name] = {{"force", ToJson(r.force)},
                                               {"moment", ToJson(r.moment)}};
  }
  json["nodes"] = nodes;
  json["bodies"] = bodies;
  json["reactions"] = reactions;
}

void PrintFrameSolution(const StructureDescription& structure, const FrameStaticSolution& solution,
                        std::ostream& out) {
  out << "max deflection        " << Scientific(solution.max_deflection)
      << " m toward the substrate\n";
  out << "max stress            " << Scientific(solution.max_stress_pa) << " Pa\n";
  out << "axial force           " << Scientific(solution.axial_force_n)
      << " N (the largest in a member)\n";
  PrintFrameMotions(structure, solution, out);
}

void PrintFrameMotions(const StructureDescription& structure, const FrameStaticSolution& solution,
                       std::ostream& out) {
  for (std::size_t n = 0; n < structure.nodes.size(); ++n) {
    out << "node " << structure.nodes[n].name << "  " << Vector(solution.nodes[n].head<3>())
        << " m\n";
  }
  for (std::size_t b = 0; b < structure.bodies.size(); ++b) {
    out << "body " << structure.bodies[b].name << "  " << Vector(solution.bodies[b].head<3>())
        << " m, " << Vector(solution.bodies[b].tail<3>()) << " rad\n";
  }
  for (const FrameReaction& r : solution.reactions) {
    out << "reaction " << structure.nodes[r.node].name << "  " << Vector(r.force) << " N, "
        << Vector(r.moment) << " N m\n";
  }
}

void WriteFrameReactions(const StructureDescription& structure,
                         const std::vector<FrameReaction>& anchors,
                         const std::filesystem::path& directory) {
  CsvFile reactions(directory / "reactions.csv", "node,fx_n,fy_n,fz_n,mx_nm,my_nm,mz_nm");
  for (const FrameReaction& r : anchors) {
    std::vector<std::string> cells = {structure.nodes[r.node].name};
    for (int k = 0; k < 3; ++k) cells.push_back(CsvFile::Number(r.force[k]));
    for (int k = 0; k < 3; ++k) cells.push_back(CsvFile::Number(r.moment[k]));
    reactions.Row(cells);
  }
  reactions.Close();
}

}  // namespace cosmems::internal
