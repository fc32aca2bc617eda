#include "modal_report.hpp"

#include <chrono>
#include <iomanip>

#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/structure/frame_stretching_force.hpp"
#include "csv_file.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

constexpr std::array<const char*, 6> kDirections = {"ux", "uy", "uz", "rx", "ry", "rz"};

}  // namespace

std::unique_ptr<ModalReport> ModalReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  ModalOptions options;
  options.count = scene.analysis.count;
  const auto start = std::chrono::steady_clock::now();
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  FrameModalResult result;
  if (scene.model.theory == Theory::kStretching) {
    // About the equilibrium under the scene's loads, where stretching has stiffened the members.
    FrameStretchingForce force(model);
    const FrameStaticSolution deflected =
        SolveFrameNonlinearStatic(model, {&force}, MakeFrameLoadCase(scene, structure));
    result.modal.status = deflected.status;
    if (deflected.status == Status::kOk) {
      result = SolveFrameModalAbout(model, force, deflected.displacement, options);
    }
  } else {
    result = SolveFrameModal(model, options);
  }
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.modal.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();

  const Stations stations(model, IsStraightBeam(scene));
  std::vector<ModeResult> modes;
  if (result.modal.status == Status::kOk) {
    for (std::size_t i = 0; i < result.modal.modes.size(); ++i) {
      const Mode& mode = result.modal.modes[i];
      modes.push_back({mode.frequency_hz, mode.kind, result.participation[i],
                       stations.Shape(model, mode.shape)});
    }
    if (static_cast<int>(modes.size()) < scene.analysis.count) {
      header.warnings.push_back("analysis.count = " + std::to_string(scene.analysis.count) +
                                " modes asked for, but the model has only " +
                                std::to_string(modes.size()));
    }
  }
  return std::make_unique<ModalReport>(std::move(header), stations, std::move(modes));
}

void ModalReport::AddResults(nlohmann::ordered_json& json) const {
  nlohmann::ordered_json frequencies = nlohmann::ordered_json::array();
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  for (const ModeResult& mode : modes_) {
    frequencies.push_back(mode.frequency_hz);
    nlohmann::ordered_json participation = nlohmann::ordered_json::object();
    for (int k = 0; k < 6; ++k) participation[kDirections[k]] = mode.participation[k];
    modes.push_back({{"frequency_hz", mode.frequency_hz},
                     {"kind", ToString(mode.kind)},
                     {"participation", participation}});
  }
  json["frequencies_hz"] = frequencies;
  json["modes"] = modes;
}

void ModalReport::PrintResults(std::ostream& out) const {
  out << "mode   frequency        kind        effective mass ux     uy     uz     rx     ry     "
         "rz\n";
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    out << std::setw(4) << i + 1 << "   " << std::setw(10)
        << Significant(modes_[i].frequency_hz / 1e3, 6) << " kHz   " << std::setw(10) << std::left
        << ToString(modes_[i].kind) << std::right << "           ";
    for (double share : modes_[i].participation)
      out << " " << std::setw(6) << Significant(share, 3);
    out << "\n";
  }
}

void ModalReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile summary(directory / "modes.csv", "mode,frequency_hz,kind,ux,uy,uz,rx,ry,rz");
  CsvFile shapes(directory / "mode_shapes.csv", "mode," + stations_.Key() + ",ux,uy,uz,rx,ry,rz");
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    const std::string number = std::to_string(i + 1);
    std::vector<std::string> row = {number, CsvFile::Number(modes_[i].frequency_hz),
                                    ToString(modes_[i].kind)};
    for (double share : modes_[i].participation) row.push_back(CsvFile::Number(share));
    summary.Row(row);
    stations_.WriteRows(shapes, modes_[i].shape, number);
  }
  summary.Close();
  shapes.Close();
}

}  // namespace cosmems::internal
